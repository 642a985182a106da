"""Hostile class: identity. No output of any command replaces a file the run reads:
-o, --depfile and --frames are tried against every kind of input (a graph, its
library and image; a model, its buffer and image; a timeline) by its own name, through
a symbolic link and through a hard link planted at the output's name. Each is refused
with exit 2 naming the input, and every file is left as it was. bench-render and
bench-snow write no file, so they have no output to check."""

import os
import shutil
import unittest

import hostile_support as hs
from hostile_support import HostileCase


class Identity(HostileCase):
    def setUp(self):
        super().setUp()
        os.mkdir(self.path("g"))
        os.mkdir(self.path("m"))
        self.write("g/tex.png", hs.png_bytes(2, 2))
        self.write("g/lib.json", hs.library())
        graph = hs.texture_graph("tex.png")
        graph["include"] = {"lib": "lib.json"}
        self.graph = self.write("g/g.json", graph)
        self.model = hs.triangle_model(self.path("m"))
        self.timeline = self.write("t.json", hs.timeline(1))

    def plant(self, at, victim, how):
        """Makes `at` name `victim`: the victim itself, a symbolic link or a hard link."""
        if how == "itself":
            return victim
        os.makedirs(os.path.dirname(at), exist_ok=True)
        (os.symlink if how == "symlink" else os.link)(victim, at)
        return at

    def refused(self, args, victim, vulkan=False):
        self.failsUnchanged(args, 2, os.path.basename(victim), vulkan=vulkan)

    def each(self, victims, hows, case):
        """case(victim, how) for each pair, in a subtest, each from the same files."""
        for victim in victims:
            for how in hows:
                with self.subTest(victim=victim, how=how):
                    self.clear(keep=("g", "m", "t.json"))
                    case(self.path(victim), how)

    def test_compile_outputs_and_depfile(self):
        def output(victim, how):
            self.plant(self.path("out", "g.reflect.json"), victim, how)
            self.refused(["compile", self.graph, "-o", self.path("out")], victim)

        def depfile(victim, how):
            self.refused(["compile", self.graph, "-o", self.path("out"), "--depfile",
                          self.plant(self.path("deps", "g.d"), victim, how)], victim)

        graph_files = ("g/g.json", "g/lib.json", "g/tex.png")
        self.each(graph_files, ("symlink", "hard link"), output)
        self.each(graph_files, ("itself", "symlink", "hard link"), depfile)

    def test_import_outputs(self):
        def output(victim, how):
            self.plant(self.path("out", "box.import.json"), victim, how)
            self.refused(["import", self.model, "-o", self.path("out")], victim)

        self.each(("m/box.gltf", "m/box.bin", "m/tex.png"), ("symlink", "hard link"), output)

    def test_render_material_output(self):
        # The graph is refused before a device opens; its library and image once compiled.
        def output(victim, how):
            self.refused(["render", "--material", self.graph, "--size", "32x32", "-o",
                          self.plant(self.path("x.png"), victim, how)], victim, vulkan=True)

        self.each(("g/g.json", "g/lib.json", "g/tex.png"), ("itself", "hard link"), output)

    def test_render_model_output(self):
        def output(victim, how):
            self.refused(["render", "--model", self.model, "--size", "32x32", "-o",
                          self.plant(self.path("x.png"), victim, how)], victim, vulkan=True)

        self.each(("m/box.gltf", "m/box.bin", "m/tex.png"), ("itself", "symlink"), output)

    def test_render_timeline_output_strip_and_frames(self):
        base = ["render", "--scene", "valley", "--size", "32x32", "--timeline", self.timeline]

        def output(victim, how):
            self.refused(base + ["-o", self.plant(self.path("x.png"), victim, how)], victim, vulkan=True)

        def strip(victim, how):
            self.plant(self.path("x.strip.png"), victim, how)
            self.refused(base + ["-o", self.path("x.png")], victim, vulkan=True)

        def frame(victim, how):
            self.plant(self.path("frames", "valley-01-stage-0.png"), victim, how)
            self.refused(base + ["-o", self.path("x.png"), "--frames", self.path("frames")], victim, vulkan=True)

        self.each(("t.json",), ("itself", "hard link"), output)
        self.each(("t.json",), ("hard link",), strip)
        self.each(("t.json",), ("symlink",), frame)

    def test_render_frames_naming_a_material_image(self):
        self.plant(self.path("frames", "stand-g-01-stage-0.png"), self.path("g/tex.png"), "hard link")
        self.refused(["render", "--material", self.graph, "--size", "32x32", "--timeline", self.timeline,
                      "-o", self.path("x.png"), "--frames", self.path("frames")], "tex.png", vulkan=True)

    # The snowfield reads the bundled graphs (here a copy, through --graphs).
    def test_render_snowfield_output_and_frames(self):
        graphs = self.path("graphs")
        shutil.copytree(self.source("graphs"), graphs)
        base = ["render", "--scene", "snowfield", "--graphs", graphs, "--size", "16x16"]
        self.refused(base + ["-o", os.path.join(graphs, "snowfield.json")], "snowfield.json", vulkan=True)
        os.mkdir(self.path("frames"))
        os.link(os.path.join(graphs, "snow_layer.json"), self.path("frames", "snowfield-02.png"))
        self.refused(base + ["-o", self.path("x.png"), "--frames", self.path("frames")], "snow_layer.json", vulkan=True)


if __name__ == "__main__":
    hs.main()
