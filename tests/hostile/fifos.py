"""Hostile class: FIFOs. A FIFO in every input role, for every command: a clean error
within seconds. Nothing writes to the FIFO, so a reader that opens it blocks forever;
the hard timeout turns that into a failure."""

import os

import hostile_support as hs
from hostile_support import HostileCase

LIMIT = 20  # seconds before a case counts as a hang (times the sanitizer factor)


class Fifos(HostileCase):
    def setUp(self):
        super().setUp()
        os.mkfifo(self.path("fifo.json"))
        os.mkfifo(self.path("fifo.png"))
        os.mkfifo(self.path("fifo.gltf"))
        self.fifo = self.path("fifo.json")
        self.graph = self.write("g.json", hs.flat_graph())

    def prompt(self, args, code, *mentions, vulkan=False):
        r = self.failsUnchanged(args, code, *mentions, timeout=LIMIT, vulkan=vulkan)
        self.assertLess(r.seconds, 5 * hs.time_scale() + (5 if vulkan else 0), "slow to refuse a FIFO:\n%s" % r)
        return r

    def test_as_the_graph(self):
        out = self.path("out")
        for args in (["compile", self.fifo, "-o", out], ["compile", self.graph, self.fifo, "-o", out],
                     ["compile", self.fifo, "--variants", "all", "-o", out], ["eval", self.fifo],
                     ["eval", self.fifo, "--help"]):
            with self.subTest(" ".join(a for a in args[:3] if a != self.fifo)):
                self.prompt(args, 1, "not a regular file")

    def test_as_a_texture(self):
        graph = self.write("t.json", hs.texture_graph("fifo.png"))
        for args in (["compile", graph, "-o", self.path("out")], ["eval", graph]):
            with self.subTest(args[0]):
                self.prompt(args, 1, "fifo.png", "/textures/t/file")

    def test_as_an_include(self):
        graph = self.write("i.json", hs.flat_graph(include={"lib": "fifo.json"}))
        self.prompt(["compile", graph, "-o", self.path("out")], 1, "/include/lib")
        self.prompt(["eval", graph], 1, "/include/lib")

    def test_as_a_timeline(self):
        self.prompt(["render", "--scene", "valley", "--size", "32x32", "--timeline", self.fifo,
                     "-o", self.path("x.png")], 2, "not a regular file", vulkan=True)

    def test_as_a_material_or_model_to_render_or_import(self):
        self.prompt(["render", "--material", self.fifo, "--size", "32x32", "-o", self.path("x.png")], (1, 2),
                    "not a regular file", vulkan=True)
        self.prompt(["render", "--model", self.path("fifo.gltf"), "--size", "32x32", "-o", self.path("x.png")], (1, 2),
                    vulkan=True)
        self.prompt(["import", self.path("fifo.gltf"), "-o", self.path("out")], (1, 2), "not a regular file")

    def test_as_the_output_folder(self):
        self.prompt(["compile", self.graph, "-o", self.fifo], 2)

    def test_as_the_depfile_or_the_png(self):
        # Writing into a FIFO with no reader would block: the run either refuses it or
        # replaces it atomically (a temporary renamed over it), promptly either way.
        for args, vulkan in ((["compile", self.graph, "-o", self.path("out"), "--depfile", self.fifo], False),
                             (["render", "--scene", "valley", "--size", "32x32", "-o", self.fifo], True)):
            with self.subTest(args[0]):
                r = hs.run_cli(args, timeout=LIMIT, vulkan=vulkan)
                self.assertClean(r)
                self.assertIn(r.returncode, (0, 2), str(r))
                if r.returncode == 0:
                    self.assertTrue(os.path.isfile(self.fifo), "wrote into the FIFO instead of replacing it")
                os.remove(self.fifo)
                os.mkfifo(self.fifo)

    def test_in_place_of_an_output_or_a_cache_entry(self):
        # A rebuild reads the file already at each output's name (to leave an unchanged
        # one in place) and the cache's entries: a FIFO in either place is replaced, not
        # waited on.
        out, cache = self.path("out"), self.path("cache")
        args = ["compile", self.graph, "-o", out, "--cache", cache, "-q"]
        r = hs.run_cli(args, timeout=LIMIT)
        self.assertEqual(r.returncode, 0, str(r))
        entries = [name for name in os.listdir(cache) if name.endswith(".entry")]
        self.assertEqual(len(entries), 1, entries)
        for path in (os.path.join(out, "g.reflect.json"), os.path.join(cache, entries[0])):
            with self.subTest(os.path.basename(path)):
                os.remove(path)
                os.mkfifo(path)
                r = hs.run_cli(args, timeout=LIMIT)
                self.assertClean(r)
                self.assertFalse(r.timed_out, str(r))
                self.assertEqual(r.returncode, 0, str(r))
                self.assertTrue(os.path.isfile(path), "the FIFO was not replaced")


if __name__ == "__main__":
    hs.main()
