#!/usr/bin/env python3
"""scripts/check-layers.py catches planted violations and stale exceptions.

Each case copies the checkout's source files into a temporary tree, changes one
thing, and runs the script on it with --root.
Usage: check_layers_test.py REPOSITORY_ROOT
"""
import importlib.util
import re
import shutil
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

ROOT = Path(sys.argv.pop(1) if len(sys.argv) > 1 else Path(__file__).resolve().parents[2])
SCRIPT = ROOT / "scripts" / "check-layers.py"
FOLDERS = ["include", "nodes", "compiler", "backends", "import", "weather", "vulkan", "snow", "host", "cli", "bench", "tests", "examples"]
SUFFIXES = {".cpp", ".hpp", ".h", ".cc", ".inl"}


def copy_sources(destination):
    for folder in FOLDERS:
        for path in (ROOT / folder).rglob("*"):
            if path.suffix in SUFFIXES and path.is_file():
                target = destination / path.relative_to(ROOT)
                target.parent.mkdir(parents=True, exist_ok=True)
                shutil.copyfile(path, target)


class CheckLayersTest(unittest.TestCase):
    def setUp(self):
        self.tree = Path(tempfile.mkdtemp(prefix="wg-layers-"))
        copy_sources(self.tree)

    def tearDown(self):
        shutil.rmtree(self.tree)

    def run_check(self, exceptions=None):
        """Runs the script, or a copy of it whose KNOWN_EXCEPTIONS are `exceptions`."""
        script = SCRIPT
        if exceptions is not None:
            script = self.tree / "check-layers.py"
            text = re.sub(r"^KNOWN_EXCEPTIONS = .*$", "KNOWN_EXCEPTIONS = " + repr(set(exceptions)),
                          SCRIPT.read_text(), count=1, flags=re.M)
            script.write_text(text)
        result = subprocess.run([sys.executable, str(script), "--root", str(self.tree)],
                                capture_output=True, text=True)
        return result.returncode, result.stderr

    def append_line(self, relative_path, line):
        path = self.tree / relative_path
        text = path.read_text()
        path.write_text(text + line + "\n")
        return text.count("\n") + 1  # the planted line's number

    def test_the_checkout_is_clean(self):
        code, output = self.run_check()
        self.assertEqual(code, 0, output)

    def test_a_lower_layer_including_a_higher_one_fails_naming_file_line_and_rule(self):
        line = self.append_line("nodes/op_registry.cpp", '#include "cli/commands.hpp"')
        code, output = self.run_check()
        self.assertEqual(code, 1)
        self.assertIn(f'nodes/op_registry.cpp:{line}: includes "cli/commands.hpp"', output)
        self.assertIn("nodes/ may include only", output)

    def test_a_sibling_layer_is_not_allowed_either(self):
        line = self.append_line("import/preset_map.cpp", '#include "host/scene_renderer.hpp"')
        code, output = self.run_check()
        self.assertEqual(code, 1)
        self.assertIn(f'import/preset_map.cpp:{line}: includes "host/scene_renderer.hpp"', output)

    def test_a_backend_sees_only_the_ir_and_interface_headers(self):
        line = self.append_line("backends/glsl_syntax.cpp", '#include "compiler/graph_loader.hpp"')
        code, output = self.run_check()
        self.assertEqual(code, 1)
        self.assertIn(f'backends/glsl_syntax.cpp:{line}: includes "compiler/graph_loader.hpp"', output)
        self.assertIn("backends/ may include from compiler/ only", output)

    def test_a_listed_exception_allows_its_include(self):
        self.append_line("backends/glsl_syntax.cpp", '#include "compiler/graph_loader.hpp"')
        code, output = self.run_check(exceptions={("backends/glsl_syntax.cpp", "compiler/graph_loader.hpp")})
        self.assertEqual(code, 0, output)

    def test_an_exception_that_no_longer_occurs_fails(self):
        code, output = self.run_check(exceptions={("backends/glsl_syntax.cpp", "compiler/graph_loader.hpp")})
        self.assertEqual(code, 1)
        self.assertIn("backends/glsl_syntax.cpp -> compiler/graph_loader.hpp, which no longer occurs", output)


def load_script():
    spec = importlib.util.spec_from_file_location("check_layers", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


class LayersDocumentationTest(unittest.TestCase):
    def test_the_layers_table_lists_what_the_script_allows(self):
        allowed = load_script().ALLOWED_INCLUDES
        text = (ROOT / "docs" / "architecture.md").read_text()
        section = text[text.index("## Layers"):]
        rows = re.findall(r"^\| `([a-z]+)/` \| ([^|]*) \|", section, re.MULTILINE)
        self.assertGreaterEqual(len(rows), 7)
        for folder, depends_on in rows:
            documented = set(re.findall(r"`([a-z]+)/`", depends_on))
            self.assertEqual(documented, set(allowed[folder]), f"docs/architecture.md's row for {folder}/")


if __name__ == "__main__":
    unittest.main(verbosity=1)
