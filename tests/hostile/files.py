"""Hostile class: files. Every kind of file that is not a readable graph, image,
library or timeline, given in each of those roles; inputs that are also outputs."""

import os
import unittest

import hostile_support as hs
from hostile_support import HostileCase, run_cli

# Bytes that are neither JSON nor an image, with a terminal escape and a NUL in them:
# a parser error that quotes what it read must not echo them raw.
GARBAGE = b"\x1b[2J\x1b]0;pwned\x07\x00\xff\xfe garbage \x9b31m\r\n"


class Kinds(HostileCase):
    """Builds the same set of hostile files in every case's temp dir."""

    def setUp(self):
        super().setUp()
        os.mkdir(self.path("adir"))
        self.write("empty.json", b"")
        self.write("garbage.json", GARBAGE)
        os.symlink("loop2", self.path("loop1"))
        os.symlink("loop1", self.path("loop2"))
        self.kinds = {
            "directory": self.path("adir"),
            "/dev/zero": "/dev/zero",
            "/dev/null": "/dev/null",
            "empty": self.path("empty.json"),
            "garbage": self.path("garbage.json"),
            "symlink loop": self.path("loop1"),
        }


class GraphKinds(Kinds):
    def test_compile_refuses_each_kind_as_the_graph(self):
        for kind, path in self.kinds.items():
            with self.subTest(kind):
                r = self.failsUnchanged(["compile", path, "-o", self.path("out")], 1)
                self.assertIn(os.path.basename(path), r.text)
                if kind in ("directory", "/dev/zero", "/dev/null"):
                    self.assertRegex(r.text, "not a regular file|is a directory", str(r))

    def test_eval_refuses_each_kind_as_the_graph(self):
        for kind, path in self.kinds.items():
            with self.subTest(kind):
                self.failsUnchanged(["eval", path], 1, os.path.basename(path))

    def test_compile_variants_refuses_each_kind_as_the_graph(self):
        for kind, path in self.kinds.items():
            with self.subTest(kind):
                self.failsUnchanged(["compile", path, "--variants", "all", "-o", self.path("out")], 1,
                                    os.path.basename(path))

    def test_import_refuses_each_kind_as_the_model(self):
        for kind, path in self.kinds.items():
            if kind == "symlink loop":
                continue  # below
            with self.subTest(kind):
                self.failsUnchanged(["import", path, "-o", self.path("out")], (1, 2), os.path.basename(path))

    # Fixed, kept as a regression: `import LOOP` exits 3 (WG9900 "internal error: filesystem error: status: Too
    # many levels of symbolic links"): std::filesystem::status throws on ELOOP and the
    # exception reaches the command boundary. It is a user error (exit 1).
    def test_import_refuses_a_symlink_loop_as_the_model(self):
        self.failsUnchanged(["import", self.path("loop1"), "-o", self.path("out")], (1, 2), "loop1")

    # Fixed, kept as a regression: a symlink loop is reported as "no such file" (ENOENT) instead of ELOOP
    # ("too many levels of symbolic links"): the user looks for a missing file.
    def test_a_symlink_loop_is_not_reported_as_missing(self):
        r = self.failsUnchanged(["compile", self.path("loop1"), "-o", self.path("out")], 1)
        self.assertNotIn("no such file", r.text.lower(), str(r))


class TextureKinds(Kinds):
    def compile_texture(self, file_name):
        graph = self.write("g.json", hs.texture_graph(file_name))
        return self.failsUnchanged(["compile", graph, "-o", self.path("out")], 1, "/textures/t/file", "g.json:")

    def test_each_kind_as_a_texture_is_an_input_error_naming_the_file(self):
        for kind, path in self.kinds.items():
            with self.subTest(kind):
                r = self.compile_texture(path)
                self.assertRegex(r.text, "WG300[23]|WG1007", str(r))

    # Fixed, kept as a regression: a directory or a device given as an image is reported as
    # "file ... not found" (WG3002), not as "not a regular file".
    def test_a_directory_or_device_texture_is_reported_as_not_a_regular_file(self):
        for kind in ("directory", "/dev/zero", "/dev/null"):
            with self.subTest(kind):
                r = self.compile_texture(self.kinds[kind])
                self.assertNotIn("not found", r.text, str(r))
                self.assertRegex(r.text, "not a regular file|is a directory", str(r))

    def test_a_nul_inside_a_texture_path_is_refused(self):
        self.png("ok.png")
        r = self.compile_texture("ok.png\u0000.txt")
        self.assertIn("NUL", r.text)
        self.assertNotIn(b"\x00", r.stderr)


class LibraryKinds(Kinds):
    def test_each_kind_as_an_include_is_an_input_error_at_the_include(self):
        for kind, path in self.kinds.items():
            with self.subTest(kind):
                graph = self.write("g.json", hs.flat_graph(include={"lib": path}))
                r = self.failsUnchanged(["compile", graph, "-o", self.path("out")], 1)
                # An error inside a library names the library; any other, the include.
                self.assertRegex(r.text, r"/include/lib\]|^[^:]*%s:[0-9]+:[0-9]+:" % os.path.basename(path), str(r))

    # Fixed, kept as a regression: a directory or device given as a library is reported as
    # "no such library file", not as "not a regular file".
    def test_a_directory_or_device_library_is_reported_as_not_a_regular_file(self):
        for kind in ("directory", "/dev/zero", "/dev/null"):
            with self.subTest(kind):
                graph = self.write("g.json", hs.flat_graph(include={"lib": self.kinds[kind]}))
                r = self.failsUnchanged(["compile", graph, "-o", self.path("out")], 1)
                self.assertRegex(r.text, "not a regular file|is a directory", str(r))


class TimelineKinds(Kinds):
    def test_each_kind_as_a_timeline_is_a_usage_error_before_rendering(self):
        for kind, path in list(self.kinds.items()) + [(".", ".")]:
            with self.subTest(kind):
                r = self.failsUnchanged(["render", "--scene", "valley", "--size", "32x32", "--timeline", path,
                                         "-o", self.path("x.png")], 2, "timeline", vulkan=True, cwd=self.dir)
                if kind in ("directory", "/dev/zero", "/dev/null", "."):
                    self.assertRegex(r.text, "not a regular file|is a directory", str(r))


class InputsAreNeverOutputs(HostileCase):
    def setUp(self):
        super().setUp()
        self.png("ok.png")
        self.write("lib.json", hs.library())
        g = hs.texture_graph("ok.png")
        g["include"] = {"lib": "lib.json"}
        self.graph = self.write("g.json", g)

    def test_a_graph_named_like_its_reflection_compiled_into_its_own_folder_survives(self):
        graph = self.write("x.reflect.json", hs.flat_graph("x"))
        self.failsUnchanged(["compile", graph, "-o", self.dir], 2, "x.reflect.json")

    def test_a_graph_named_like_its_shader_compiled_into_its_own_folder_survives(self):
        graph = self.write("x.vert.glsl", hs.flat_graph("x"))
        self.failsUnchanged(["compile", graph, "-o", self.dir, "--target", "glsl"], 2)

    def test_a_depfile_naming_any_input_is_refused(self):
        for victim in ("g.json", "lib.json", "ok.png"):
            with self.subTest(victim):
                self.failsUnchanged(["compile", self.graph, "-o", self.path("out"), "--depfile", self.path(victim)],
                                    2, victim)

    def test_a_depfile_naming_an_input_through_another_spelling_is_refused(self):
        os.symlink(".", self.path("here"))
        for spelling in ("./g.json", "here/g.json", "out/../g.json"):
            with self.subTest(spelling):
                self.failsUnchanged(["compile", "g.json", "-o", "out", "--depfile", spelling], 2, cwd=self.dir)

    def test_an_image_named_like_an_output_in_the_output_folder_survives(self):
        # The texture file is itself called g.reflect.json... in the output folder.
        os.rename(self.path("ok.png"), self.path("g.frag.glsl"))
        graph = self.write("g.json", hs.texture_graph("g.frag.glsl"))
        self.failsUnchanged(["compile", graph, "-o", self.dir], (1, 2))

    def test_output_dir_naming_an_existing_regular_file(self):
        self.failsUnchanged(["compile", self.graph, "-o", self.graph], 2, "g.json")
        self.failsUnchanged(["compile", self.graph, "-o", self.path("ok.png")], 2, "ok.png")

    def test_output_dir_below_a_regular_file(self):
        self.failsUnchanged(["compile", self.graph, "-o", self.path("ok.png", "out")], 2)

    # A rebuild keeps an output that already holds its bytes and only touches it; one the
    # compiling user may not touch (another user's file in the user's own output folder)
    # is replaced as it was before outputs were kept, not a "Permission denied".
    @unittest.skipUnless(os.geteuid() == 0, "needs root to own a file the compiling user does not")
    def test_an_unchanged_output_owned_by_another_user_is_replaced(self):
        nobody = 65534
        os.chmod(self.dir, 0o755)
        out = self.path("out")
        os.mkdir(out)
        os.chown(out, nobody, nobody)
        graph = self.write("f.json", hs.flat_graph("f"))

        def as_nobody():
            os.setgroups([])
            os.setgid(nobody)
            os.setuid(nobody)

        args = ["compile", graph, "-o", out, "--target", "glsl", "-q"]
        first = run_cli(args, preexec_fn=as_nobody)
        self.assertSucceeds(first)
        shader = os.path.join(out, "f.frag.glsl")
        before = hs.read(shader)
        os.chown(shader, 0, 0)
        again = run_cli(args, preexec_fn=as_nobody)
        self.assertSucceeds(again)
        self.assertEqual(hs.read(shader), before)

    # Fixed ("inputs are never outputs"), kept as a regression: `render --material G.json -o G.json`
    # and `render --timeline T.json -o T.json` exit 0 and replace the graph or the
    # timeline with the PNG; only compile checks its outputs against its inputs.
    def test_render_output_naming_its_own_graph_or_timeline(self):
        graph = self.write("m.json", hs.flat_graph("m"))
        tl = self.write("t.json", hs.timeline(1))
        for args in (["--material", graph, "-o", graph], ["--scene", "valley", "--timeline", tl, "-o", tl]):
            with self.subTest(args[0]):
                self.failsUnchanged(["render", "--size", "32x32"] + args, (1, 2), vulkan=True)


if __name__ == "__main__":
    hs.main()
