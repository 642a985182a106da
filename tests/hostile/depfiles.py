"""Hostile class: depfiles. File names that Make or Ninja read specially, in every
place a depfile names a file: the run refuses them before writing anything, or it
writes a depfile that real GNU make and Ninja read back as exactly those files."""

import os
import shlex
import shutil
import subprocess
import unittest

import hostile_support as hs
from hostile_support import HostileCase, run_cli

# Names that Make or Ninja treat specially (or that a naive escaper mangles).
SPECIAL = {
    "newline": "a\nb", "tab": "a\tb", "CR": "a\rb", "ESC": "a\x1b[2Jb", "dollar": "a$b", "colon": "a:b",
    "hash": "a#b", "space": "a b", "backslash": "a\\b", "percent": "a%b", "star": "a*b", "pipe": "a|b",
    "equals": "a=b", "semicolon": "a;b", "quote": "a'b\"c", "backquote": "a`b", "non-ASCII": "é雪",
    "injection": "g.json\n\ttouch PWNED", "dollar-paren": "$(shell touch PWNED)", "brackets": "a[b]",
}
# A shorter list for the other places a name can come from.
FEW = ["space", "dollar", "hash", "colon", "newline", "tab", "injection"]

# Names that make or Ninja misread ("escape or reject every character
# that Make or Ninja treat specially"). These were bugs, now refused before anything is
# written; the cases stay as regressions:
# * a backslash is written doubled (`a\b.png` as `a\\b.png`): GNU make stops with "No
#   rule to make target 'a\\b.png'" and Ninja reads `a\\b.png`, a file that does not
#   exist, so the output is never clean. Both read a backslash literally unless it
#   precedes a space or '#'.
# * ';' and '|' are written raw: in a Make rule line ';' starts the recipe (command
#   injection, see test_make_recipe_injection_through_a_semicolon) and '|' starts the
#   order-only prerequisites.
# * Ninja's depfile parser (1.11) ends a file name at any character outside
#   [A-Za-z0-9+,/_:.~(){}%=@[]!-] and bytes >= 0x80, with no escape for them: `a*b.png`
#   is read as `a` and `b.png`. Such names cannot be expressed and must be refused.
KNOWN_BAD = {"backslash": "make and Ninja", "semicolon": "make", "pipe": "make",
             "star": "Ninja", "quote": "Ninja", "backquote": "Ninja"}


def ninja_escape(path):
    return path.replace("$", "$$").replace(" ", "$ ").replace(":", "$:")


class DepfileCase(HostileCase):
    def setUp(self):
        super().setUp()
        self.make = shutil.which("make")
        self.ninja = shutil.which("ninja")

    def check(self, graph, out="out", depfile="out.d"):
        """Compiles `graph` (relative to self.dir) with --depfile: refused with nothing
        written, or a depfile that make and ninja read back as the real files."""
        args = ["compile", graph, "-o", out, "--target", "glsl", "--depfile", depfile]
        before = hs.snapshot(self.dir)
        r = run_cli(args, cwd=self.dir)
        self.assertClean(r)
        if r.returncode != 0:
            self.assertEqual(r.returncode, 2, str(r))
            self.assertIn("depfile", r.text)
            self.assertUnchanged(before, self.dir)
            return "refused"
        text = open(self.path(depfile), "rb").read()
        bad = sorted({b for b in text if b in hs.RAW_CONTROL or b == 0x0D})
        self.assertEqual(bad, [], "raw control bytes in the depfile: %r" % text)
        self.assertFalse(os.path.exists(self.path("PWNED")))
        outputs = sorted(os.path.join(out, f) for f in os.listdir(self.path(out)))
        if self.make:
            with open(self.path("check.mk"), "w") as f:
                f.write("include %s\n" % depfile)
            m = subprocess.run([self.make, "-f", "check.mk", "-n"], cwd=self.dir, capture_output=True, timeout=60)
            self.assertEqual(m.returncode, 0, "GNU make misreads the depfile %r:\n%s" % (text, m.stderr.decode()))
            self.assertFalse(os.path.exists(self.path("PWNED")), "make ran a command from the depfile")
        if self.ninja:
            shutil.rmtree(self.path(out))
            os.remove(self.path(depfile))
            cmd = " ".join(shlex.quote(a) for a in [hs.CLI] + args).replace("$", "$$")
            with open(self.path("build.ninja"), "w") as f:
                f.write("rule wg\n  command = %s\n  depfile = %s\n  deps = gcc\n" % (cmd, ninja_escape(depfile)))
                f.write("build %s: wg %s\n" % (" ".join(ninja_escape(o) for o in outputs), ninja_escape(graph)))
            env = hs.child_env()
            n = subprocess.run([self.ninja], cwd=self.dir, capture_output=True, timeout=120, env=env)
            self.assertEqual(n.returncode, 0, n.stdout.decode())
            n = subprocess.run([self.ninja, "-n"], cwd=self.dir, capture_output=True, timeout=60, env=env)
            self.assertIn(b"no work to do", n.stdout, "Ninja misreads the depfile %r: it rebuilds every time\n%s" %
                          (text, subprocess.run([self.ninja, "-t", "deps"], cwd=self.dir, capture_output=True).stdout))
            self.assertFalse(os.path.exists(self.path("PWNED")), "ninja ran a command from the depfile")
        return "written"


class SpecialNames(DepfileCase):
    def texture_case(self, key):
        name = SPECIAL[key] + ".png"
        self.write(name, hs.png_bytes(2, 2))
        self.write("g.json", hs.texture_graph(name))
        return self.check("g.json")

    def test_texture_names(self):
        for key in SPECIAL:
            if key in KNOWN_BAD:
                continue
            with self.subTest(key):
                self.texture_case(key)
                self.clear()

    def test_names_that_make_or_ninja_misread(self):
        for key in KNOWN_BAD:
            with self.subTest(key):
                self.texture_case(key)
                self.clear()

    # Fixed, kept as a regression: the red team's newline injection is refused, but a ';' is
    # written raw. With the texture `g.json;touch${IFS}PWNED;.png`, the depfile's rule
    # line reads `OUTPUTS: g.json g.json;touch$${IFS}PWNED;.png`, and the next `make`
    # that finds the outputs out of date runs `touch ${IFS}PWNED` as their recipe.
    def test_make_recipe_injection_through_a_semicolon(self):
        if not self.make:
            self.skipTest("no GNU make")
        name = "g.json;touch${IFS}PWNED;.png"
        self.write(name, hs.png_bytes(2, 2))
        self.write("g.json", hs.texture_graph(name))
        r = run_cli(["compile", "g.json", "-o", "out", "--target", "glsl", "--depfile", "out.d"], cwd=self.dir)
        self.assertClean(r)
        if r.returncode == 0:
            with open(self.path("check.mk"), "w") as f:
                f.write("include out.d\n")
            os.utime(self.path("g.json"), (2e9, 2e9))  # the outputs are out of date
            subprocess.run([self.make, "-f", "check.mk"], cwd=self.dir, capture_output=True, timeout=60)
        self.assertFalse(os.path.exists(self.path("PWNED")), "make ran a command injected through the depfile")
        self.assertEqual(r.returncode, 2, str(r))

    def test_library_names(self):
        for key in FEW:
            with self.subTest(key):
                lib = SPECIAL[key] + ".json"
                self.write(lib, hs.library())
                self.write("g.json", hs.flat_graph(include={"lib": lib}))
                self.check("g.json")
                self.clear()

    def test_graph_file_names(self):
        for key in FEW:
            with self.subTest(key):
                graph = self.write(SPECIAL[key] + ".json", hs.flat_graph())
                self.check(os.path.basename(graph))
                self.clear()

    def test_output_folder_names(self):
        self.write("g.json", hs.flat_graph())
        for key in FEW:
            with self.subTest(key):
                self.check("g.json", out=SPECIAL[key])
                self.clear(keep=("g.json",))


class DepfilePlaces(HostileCase):
    """A depfile that cannot be written: nothing is written, older outputs survive."""

    def setUp(self):
        super().setUp()
        self.graph = self.write("g.json", hs.flat_graph())
        self.assertSucceeds(run_cli(["compile", self.graph, "-o", self.path("out"), "--target", "glsl"]))
        self.write("g.json", hs.flat_graph(colour=(0.1, 0.2, 0.3)))  # the next run's outputs differ
        os.mkdir(self.path("adir"))

    def test_unwritable_depfiles(self):
        places = {"a missing folder": self.path("missing", "out.d"), "a directory": self.path("adir"),
                  "below a file": self.path("g.json", "out.d"), "the output folder": self.path("out"),
}
        for what, depfile in places.items():
            with self.subTest(what):
                self.failsUnchanged(["compile", self.graph, "-o", self.path("out"), "--target", "glsl",
                                     "--depfile", depfile], 2)

    # Fixed, kept as a regression: `--depfile OUT/g.frag.glsl`, one of the run's own outputs,
    # exits 0 and the depfile replaces the shader. The depfile must not be an output.
    def test_a_depfile_naming_one_of_the_outputs(self):
        self.failsUnchanged(["compile", self.graph, "-o", self.path("out"), "--target", "glsl",
                             "--depfile", self.path("out", "g.frag.glsl")], 2)

    # Fixed, kept as a regression: `--depfile ''` (an unset build variable) is accepted and silently writes no
    # depfile; `-o ''` is a usage error, and so should this be.
    def test_an_empty_depfile_name(self):
        self.failsUnchanged(["compile", self.graph, "-o", self.path("out"), "--target", "glsl", "--depfile", ""], 2)

    def test_a_read_only_depfile_folder(self):
        if os.geteuid() == 0:
            self.skipTest("root writes into read-only folders")
        os.chmod(self.path("adir"), 0o500)
        self.failsUnchanged(["compile", self.graph, "-o", self.path("out"), "--depfile", self.path("adir", "o.d")], 2)


if __name__ == "__main__":
    hs.main()
