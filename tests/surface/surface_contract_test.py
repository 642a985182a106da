#!/usr/bin/python3
"""The surface contract as a foreign host meets it (docs/engine-api.md).

Compiles every bundled graph with --target surface, checks each reflection's "surface"
object against docs/surface-contract.schema.json, then writes host glue from the
reflection alone (examples/surface-glue) and compiles it with glslang, validating the
SPIR-V: each material alone in GLSL, GLSL ES and HLSL; two materials in one shader
with one material's set moved by its macro; every weather map absent (its fallback);
and a host that declares every resource itself.

Usage: surface_contract_test.py --cli WEATHERGEN --source-dir DIR
Prints 'N passed, M failed' and exits non-zero on any failure.
"""
import argparse
import json
import re
import subprocess
import sys
import tempfile
from pathlib import Path

import jsonschema

RESULTS = {"passed": 0, "failed": 0}


def check(name, ok, detail=""):
    RESULTS["passed" if ok else "failed"] += 1
    print(("ok     " if ok else "FAILED ") + name + ("" if ok else "\n" + detail))


def run(args):
    return subprocess.run(args, capture_output=True, text=True, timeout=300)


def compile_glue(language, vertex, fragment, out):
    """Compiles both glue stages; returns (ok, log, [spv paths])."""
    spvs, logs = [], []
    for path, stage in ((vertex, "vert"), (fragment, "frag")):
        if language == "glsles":  # OpenGL ES semantics: no SPIR-V, a compile check
            r = run(["glslangValidator", "-S", stage, str(path)])
        else:
            spv = out / (path.name + ".spv")
            extra = ["-D", "-e", "main"] if language == "hlsl" else []
            r = run(["glslangValidator", "-V", *extra, "-S", stage, str(path), "-o", str(spv)])
            if r.returncode == 0:
                v = run(["spirv-val", str(spv)])
                r = v if v.returncode else r
                spvs.append(spv)
        logs.append(r.stdout + r.stderr)
        if r.returncode:
            return False, "\n".join(logs), spvs
    return True, "", spvs


def disassembly(spvs):
    return "\n".join(run(["spirv-dis", str(s)]).stdout for s in spvs)


def decorations(text, name):
    """The DescriptorSet and Binding decorations of the variable named name."""
    lines = [line.strip() for line in text.splitlines()]
    ids = [line.split()[1] for line in lines if line.startswith("OpName") and f'"{name}"' in line]
    found = {}
    for line in lines:
        parts = line.split()
        if len(parts) == 4 and parts[0] == "OpDecorate" and parts[1] in ids and parts[2] in ("DescriptorSet", "Binding"):
            found[parts[2]] = int(parts[3])
    return found


def main(argv):
    parser = argparse.ArgumentParser()
    parser.add_argument("--cli", required=True)
    parser.add_argument("--source-dir", required=True)
    args = parser.parse_args(argv)
    source = Path(args.source_dir)
    sys.path.insert(0, str(source / "examples" / "surface-glue"))
    import surface_glue

    schema = json.loads((source / "docs" / "surface-contract.schema.json").read_text())
    graphs = sorted((source / "graphs").glob("*.json"))
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        out = tmp / "compiled"
        r = run([args.cli, "compile", *map(str, graphs), "-o", str(out), "--target", "surface", "-q"])
        check("compile --target surface writes every bundled graph's surface", r.returncode == 0, r.stderr)
        if r.returncode:
            return 1
        # The glue declares the lowest GLSL version the contract promises: the full stages'.
        lowest = re.search(r"kGlslVersion = (\d+);", (source / "backends" / "shader_syntax.hpp").read_text()).group(1)
        probe = surface_glue.write_glue("glsl", tmp / "probe", sorted(out.glob("*.reflect.json"))[:1])[0]
        declared = probe.read_text().splitlines()[0]
        check(f"the glsl glue declares #version {lowest}", declared == f"#version {lowest}", declared)
        reflections = sorted(out.glob("*.reflect.json"))
        for reflection in reflections:
            surface = json.loads(reflection.read_text())["surface"]
            errors = [e.message for e in jsonschema.Draft202012Validator(schema).iter_errors(surface)]
            check(f"{reflection.name}: surface object matches the schema", not errors, "\n".join(errors[:5]))
            for language in ("glsl", "glsles", "hlsl"):
                glue = tmp / "glue" / reflection.stem / language
                vertex, fragment = surface_glue.write_glue(language, glue, [reflection])
                ok, log, _ = compile_glue(language, vertex, fragment, glue)
                check(f"{reflection.stem}: {language} glue from the reflection compiles", ok, log[-3000:])

        # Two materials in one shader; road's set moved by its macro.
        pair = [out / "rock.reflect.json", out / "road.reflect.json"]
        road = json.loads(pair[1].read_text())["surface"]
        road_set = road["resources"][-1]["setMacro"]
        road_texture = next(r for r in road["resources"] if r["kind"] == "texture" and not r["shared"])
        for language in ("glsl", "glsles", "hlsl"):
            glue = tmp / "pair" / language
            vertex, fragment = surface_glue.write_glue(language, glue, pair, [(road_set, "5")])
            ok, log, spvs = compile_glue(language, vertex, fragment, glue)
            check(f"rock and road share one {language} shader", ok, log[-3000:])
            if ok and spvs:
                moved = decorations(disassembly(spvs), road_texture["identifier"])
                check(f"{language}: {road_set}=5 moves {road_texture['identifier']} to set 5",
                      moved.get("DescriptorSet") == 5 and moved.get("Binding") == road_texture["binding"], str(moved))

        # Materials whose names read alike as identifiers ("a-b", "a_b") still share a shader.
        alike = []
        for name in ("wet-rock", "wet_rock"):
            graph = json.loads((source / "graphs" / "rock.json").read_text())
            graph["name"] = name
            alike.append(tmp / "alike" / (name + ".json"))
            alike[-1].parent.mkdir(parents=True, exist_ok=True)
            alike[-1].write_text(json.dumps(graph))
        r = run([args.cli, "compile", *map(str, alike), "-o", str(tmp / "alike" / "out"), "--target", "surface", "-q"])
        check("wet-rock and wet_rock compile into one folder", r.returncode == 0, r.stderr)
        alike_reflections = sorted((tmp / "alike" / "out").glob("*.reflect.json"))
        for language in ("glsl", "glsles", "hlsl"):
            glue = tmp / "alike" / language
            vertex, fragment = surface_glue.write_glue(language, glue, alike_reflections)
            ok, log, _ = compile_glue(language, vertex, fragment, glue)
            check(f"wet-rock and wet_rock share one {language} shader", ok, log[-3000:])

        # Every weather map absent: the surfaces compile and declare none of them.
        absent = sorted({r["absentMacro"] for p in pair for r in json.loads(p.read_text())["surface"]["resources"]
                         if "absentMacro" in r})
        maps = {r["identifier"] for p in pair for r in json.loads(p.read_text())["surface"]["resources"] if "absentMacro" in r}
        for language in ("glsl", "hlsl"):
            glue = tmp / "absent" / language
            vertex, fragment = surface_glue.write_glue(language, glue, pair, [(m, "") for m in absent])
            ok, log, spvs = compile_glue(language, vertex, fragment, glue)
            check(f"{language}: with {', '.join(absent)} the surfaces compile", ok, log[-3000:])
            if ok:
                text = disassembly(spvs)
                left = sorted(m for m in maps if f'"{m}"' in text)
                check(f"{language}: no absent map is declared", not left, str(left))

        # A host with its own resources declares every identifier the reflection lists.
        for language in ("glsl", "hlsl"):
            glue = tmp / "host" / language
            vertex, fragment = surface_glue.write_glue(language, glue, pair, host_resources=True)
            ok, log, _ = compile_glue(language, vertex, fragment, glue)
            check(f"{language}: a host that declares the resources itself compiles", ok, log[-3000:])

    print(f"{RESULTS['passed']} passed, {RESULTS['failed']} failed")
    return 1 if RESULTS["failed"] else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
