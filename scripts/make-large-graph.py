#!/usr/bin/env python3
"""Writes a large material graph for the compile-time curve in docs/BENCHMARKS.md.

  make-large-graph.py NODES CONSTANTS OUT.json

NODES distinct nodes (a random DAG of adds over the leaves, then a balanced reduction so
that none is dead) and CONSTANTS distinct vec2 leaves, each adding its own constant
(2 scalars and 1 vector each, as glslang counts them). Deterministic (seeded).
"""
import json
import random
import sys


def main():
    nodes_wanted, constants, out = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
    random.seed(1)
    leaves = max(2, min(constants, nodes_wanted // 4))
    nodes = [{"id": "uv", "op": "texcoord"}]
    pool = []
    for i in range(leaves):
        nodes.append({"id": f"l{i}", "op": "add",
                      "inputs": {"a": "uv.out", "b": [0.5 + i * 1e-4, 0.25 + i * 1e-4]}})
        pool.append(f"l{i}.out")
    for k in range(nodes_wanted // 2 - leaves):
        a, b = random.sample(range(len(pool)), 2)
        nodes.append({"id": f"r{k}", "op": "add", "inputs": {"a": pool[a], "b": pool[b]}})
        pool.append(f"r{k}.out")
    level, k = pool, 0
    while len(level) > 1:
        following = []
        for j in range(0, len(level) - 1, 2):
            nodes.append({"id": f"s{k}", "op": "add", "inputs": {"a": level[j], "b": level[j + 1]}})
            following.append(f"s{k}.out")
            k += 1
        if len(level) % 2:
            following.append(level[-1])
        level = following
    nodes.append({"id": "c", "op": "swizzle", "inputs": {"in": level[0], "channels": "xyx"}})
    with open(out, "w") as f:
        json.dump({"name": "large", "nodes": nodes, "output": {"baseColor": "c.out"}}, f)


if __name__ == "__main__":
    main()
