#!/usr/bin/env python3
"""Fails when a folder includes a header from a layer above it (docs/architecture.md, Layers).

Reads every `#include "..."` in the source folders below and checks it against
ALLOWED_INCLUDES. Known exceptions are listed in KNOWN_EXCEPTIONS, a ratchet: an
exception that no longer occurs fails the check too, so the list can only shrink.

Usage: scripts/check-layers.py [--root DIR]      exit 0 clean, 1 violations, 2 usage
"""
import argparse
import re
import sys
from pathlib import Path

# Folder -> the folders its files may include (besides their own), lowest layer first.
# A folder missing from another's list is above it or beside it: including it is a
# violation. docs/architecture.md's Layers table must list the same folders (the
# self-test checks it); keep its diagram in step too.
ALLOWED_INCLUDES = {
    "include": [],                     # the public API header: standard library only
    "nodes": [],                       # values, ops, shader libraries, images, shader stages
    "compiler": ["nodes"],             # load, IR, passes, interface, reflection
    "backends": ["nodes", "compiler"],  # syntax; from compiler/ only BACKEND_VISIBLE_COMPILER
    "driver": ["backends", "compiler", "nodes", "include"],  # material_compiler, batch_compile, the API
    "import": ["compiler", "nodes"],   # glTF -> graphs; never shaders, never the renderer
    "weather": ["nodes", "include"],  # the weather library: simulation, timelines, precipitation
    "vulkan": ["backends", "compiler", "nodes"],  # Vulkan building blocks: context, images, pipelines
    "snow": ["vulkan", "backends", "compiler", "nodes", "include"],  # the deformable snow library
    "host": ["snow", "vulkan", "weather", "driver", "compiler", "backends", "nodes", "include"],  # the reference host
    "cli": ["host", "snow", "vulkan", "weather", "import", "driver", "compiler", "backends", "nodes"],
    "bench": ["host", "snow", "vulkan", "weather", "import", "driver", "compiler", "backends", "nodes"],
    "tests": ["cli", "host", "snow", "vulkan", "weather", "import", "driver", "compiler", "backends", "nodes", "include"],
    "examples": ["include"],           # engine code: the installed public API only
}

# A backend sees the IR and the material interface, nothing else of the compiler
# backends/ is its own CMake target, weathergen_backends.
BACKEND_VISIBLE_COMPILER = {
    "compiler/ir.hpp",
    "compiler/material_interface.hpp",
    "compiler/pbr_output.hpp",
    "compiler/surface_interface.hpp",
}

# Includes that break the rules today, each (including file, included header).
# Remove an entry when its include goes; the check fails while a stale entry remains.
KNOWN_EXCEPTIONS = set()

SOURCE_SUFFIXES = {".cpp", ".hpp", ".h", ".cc", ".inl"}
INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"')


def layer_of(relative_path):
    """The layer a repository-relative path belongs to, or None."""
    first = relative_path.split("/", 1)[0]
    return first if first in ALLOWED_INCLUDES else None


def resolve(root, including_file, included):
    """The repository-relative path an include names, or None outside the layers."""
    if layer_of(included):
        return included
    sibling = (root / including_file).parent / included
    if sibling.is_file():
        return sibling.resolve().relative_to(root.resolve()).as_posix()
    return None  # a system or third-party header spelled with quotes


def rule_broken(source, target):
    """Why source may not include target, or None when it may."""
    source_layer, target_layer = layer_of(source), layer_of(target)
    if source_layer == target_layer:
        return None
    if target_layer not in ALLOWED_INCLUDES[source_layer]:
        allowed = ", ".join(f"{name}/" for name in ALLOWED_INCLUDES[source_layer]) or "nothing"
        return f"{source_layer}/ may include only its own folder and {allowed}"
    if source_layer == "backends" and target_layer == "compiler" and target not in BACKEND_VISIBLE_COMPILER:
        return "backends/ may include from compiler/ only " + ", ".join(sorted(BACKEND_VISIBLE_COMPILER))
    return None


def source_files(root):
    for layer in ALLOWED_INCLUDES:
        folder = root / layer
        if not folder.is_dir():
            continue
        for path in sorted(folder.rglob("*")):
            if path.suffix in SOURCE_SUFFIXES and path.is_file():
                yield path.relative_to(root).as_posix()


def includes_of(root, relative_path):
    text = (root / relative_path).read_text(encoding="utf-8", errors="replace")
    for number, line in enumerate(text.splitlines(), start=1):
        match = INCLUDE.match(line)
        if match:
            yield number, match.group(1)


def check(root):
    """Returns the list of problems, each one line."""
    problems, seen_exceptions = [], set()
    for source in source_files(root):
        for line, included in includes_of(root, source):
            target = resolve(root, source, included)
            if target is None:
                continue
            why = rule_broken(source, target)
            if why is None:
                continue
            if (source, target) in KNOWN_EXCEPTIONS:
                seen_exceptions.add((source, target))
                continue
            problems.append(f'{source}:{line}: includes "{included}": {why}')
    for source, target in sorted(KNOWN_EXCEPTIONS - seen_exceptions):
        problems.append(f"scripts/check-layers.py: KNOWN_EXCEPTIONS lists {source} -> {target}, "
                        "which no longer occurs: remove the entry")
    return problems


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", type=Path, default=Path(__file__).resolve().parent.parent,
                        help="repository root (default: this script's checkout)")
    args = parser.parse_args()
    if not (args.root / "compiler").is_dir():
        print(f"check-layers: {args.root} has no compiler/ folder; pass the repository root", file=sys.stderr)
        return 2
    problems = check(args.root)
    for problem in problems:
        print(problem, file=sys.stderr)
    if problems:
        print(f"check-layers: {len(problems)} problem(s); the layers are in docs/architecture.md", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
