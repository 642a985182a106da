#!/usr/bin/env python3
"""What the weather adds to a stage, by kind of SPIR-V instruction.

`weathergen stats` counts every instruction after spirv-opt's performance passes,
declarations included. This splits the same difference (a graph's weather against
preset none, one tier, GLSL) into the module's declarations (debug names, decorations,
types, constants, variables) and the instructions in function bodies, which are what a
GPU runs. Used for docs/BENCHMARKS.md ("Quality tiers: declarations and code").

    scripts/weather-cost-by-kind.py graphs/rock.json low [build/weathergen]
"""
import collections
import pathlib
import re
import subprocess
import sys
import tempfile

KINDS = {"OpName": "names", "OpMemberName": "names", "OpDecorate": "decorations",
         "OpMemberDecorate": "decorations", "OpVariable": "variables"}


def kinds(spv):
    text = subprocess.run(["spirv-dis", spv], capture_output=True, text=True, check=True).stdout
    counts, in_function = collections.Counter(), False
    for line in text.splitlines():
        match = re.search(r"\b(Op\w+)", line)
        if not match or line.lstrip().startswith(";"):
            continue
        op = match.group(1)
        in_function = in_function or op == "OpFunction"
        if in_function:
            counts["code"] += 1
        elif op.startswith("OpConstant"):
            counts["constants"] += 1
        elif op.startswith("OpType"):
            counts["types"] += 1
        else:
            counts[KINDS.get(op, "other")] += 1
    return counts


def stage_kinds(cli, graph, tier, preset, out):
    args = [cli, "compile", graph, "--target", "spirv", "--quality", tier, "-o", out, "-q", "--no-cache"]
    subprocess.run(args + (["--weather-preset", preset] if preset else []), check=True)
    result = {}
    for stage in ("vert", "frag"):
        spv = next(pathlib.Path(out).glob(f"*.glsl.{stage}.spv"))
        optimized = str(spv) + ".opt"
        subprocess.run(["spirv-opt", "-O", "--target-env=vulkan1.1", str(spv), "-o", optimized], check=True)
        result[stage] = kinds(optimized)
    return result


def main():
    graph, tier = sys.argv[1], sys.argv[2]
    cli = sys.argv[3] if len(sys.argv) > 3 else "build/weathergen"
    with tempfile.TemporaryDirectory() as tmp:
        weathered = stage_kinds(cli, graph, tier, None, tmp + "/weathered")
        bare = stage_kinds(cli, graph, tier, "none", tmp + "/none")
    order = ["code", "constants", "names", "decorations", "types", "variables", "other"]
    print("stage  total  " + "  ".join(order))
    for stage in ("vert", "frag"):
        diff = {k: weathered[stage][k] - bare[stage][k] for k in order}
        print(f"{stage:5} {sum(diff.values()):+6d}  " + "  ".join(f"{diff[k]:+d}" for k in order))


if __name__ == "__main__":
    main()
