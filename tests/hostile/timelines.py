"""Hostile class: timelines (render --timeline). Parsed as strictly as graphs; limits
checked before any stage renders; every error is a usage error naming the timeline
with line and column, and no PNG is written."""

import json
import time
import unittest

import hostile_support as hs
from hostile_support import HostileCase, run_cli

KEY = '"temperature": 5, "precipitation": 0.2, "windIntensity": 0.1, "wind": [1, 0]'


class Timelines(HostileCase):
    def render(self, timeline, code=2, *mentions, size="32x32"):
        t = self.write("t.json", timeline)
        return self.failsUnchanged(["render", "--scene", "valley", "--size", size, "--timeline", t,
                                    "-o", self.path("x.png")], code, *mentions, vulkan=True)

    def test_a_duplicate_key_is_rejected_naming_line_and_column(self):
        r = self.render('{"keyframes": [\n  {"time": 0, %s, "label": "a",\n   "temperature": 3}]}' % KEY, 2,
                        "WG1006", "temperature", "t.json:3:")
        self.assertIn("/keyframes/0/temperature", r.text)
        # One usage error that carries the file's problem, not a second diagnostic inside it.
        self.assertEqual(r.text.count("error WG"), 1, r.text)
        self.assertEqual(r.text.count("hint:"), 1, r.text)
        self.render('{"keyframes": [], "keyframes": []}', 2, "WG1006", "t.json:1:")

    def test_300_stages_are_refused_before_rendering(self):
        start = time.monotonic()
        r = self.render(hs.timeline(300), 2, "300 keyframes", "t.json:", "/keyframes/256", size="64x64")
        # Rendering 300 stages takes tens of seconds; refusing them, a Vulkan start-up.
        self.assertLess(time.monotonic() - start, 10 * hs.time_scale(), "the limit was checked after rendering")

    # Limits named with the file, line and pointer (docs/weather-simulation.md): 256
    # keyframes, 64 stages, labels of 64 bytes. A 10,000-character label used to give a
    # contact sheet 120184 pixels wide, and 300 keyframes a WG9001 without the file.
    def test_timeline_limits_name_the_file_and_pointer(self):
        self.render(hs.timeline(100), 2, "100 stages", "t.json:", "/keyframes/64")
        self.render(hs.timeline(50, keys_per_stage=6), 2, "300 keyframes", "t.json:", "/keyframes/256")
        long_label = {"keyframes": [{"time": 0, "temperature": 5, "precipitation": 0, "label": "x" * 10000}]}
        self.render(long_label, 2, "t.json:", "/keyframes/0/label", "10000 bytes")

    def test_timelines_at_the_limits_are_accepted(self):
        tl = hs.timeline(2, keys_per_stage=128)
        tl["keyframes"][0]["label"] = "y" * 64
        t = self.write("t.json", tl)
        r = run_cli(["render", "--scene", "valley", "--size", "16x16", "--timeline", t, "-o", self.path("x.png")], vulkan=True)
        self.assertSucceeds(r)

    def test_the_timeline_is_a_directory(self):
        self.failsUnchanged(["render", "--scene", "valley", "--size", "32x32", "--timeline", ".", "-o", "x.png"],
                            2, "timeline", vulkan=True, cwd=self.dir)

    def test_malformed_timelines(self):
        one = '{"time": 0, %s, "label": "a"}' % KEY
        cases = {
            "empty file": "", "not JSON": "\x1b[2J garbage", "NUL inside": '{"keyframes": [\u0000%s]}' % one,
            "trailing garbage": '{"keyframes": [%s]} x' % one,
            "no keyframes": '{"keyframes": []}', "not an object": "[]", "keyframes not a list": '{"keyframes": {}}',
            "unknown key": '{"keyframes": [%s], "extra": 1}' % one,
            "unknown keyframe key": '{"keyframes": [{"time": 0, %s, "tempreature": 1}]}' % KEY,
            "infinite": '{"keyframes": [{"time": 1e999, %s}]}' % KEY,
            "times out of order": '{"keyframes": [{"time": 10, %s}, {"time": 0, %s}]}' % (KEY, KEY),
            "hex number": '{"keyframes": [{"time": 0x10, %s}]}' % KEY,
            "string number": '{"keyframes": [{"time": "0", %s}]}' % KEY,
            "out of range": '{"keyframes": [{"time": 0, %s}]}' % KEY.replace('"temperature": 5', '"temperature": 500'),
            "wind of 3": '{"keyframes": [{"time": 0, %s}]}' % KEY.replace("[1, 0]", "[1, 0, 0]"),
            "escape in label": '{"keyframes": [{"time": 0, %s, "label": 7}]}' % KEY,
            "deep": '{"keyframes": %s}' % ("[" * 200 + "]" * 200),
            "big": json.dumps({"keyframes": [], "pad": "x" * (17 << 20)}),
        }
        for what, text in cases.items():
            with self.subTest(what):
                r = self.render(text, 2, "t.json")
                self.assertRegex(r.text, r"t\.json(:\d+:\d+)?", str(r))

    # Fixed ("parse strictly"), kept as a regression: a NUL ends the document and whatever
    # follows it is ignored: `{...}<NUL> garbage {{{` is accepted as a timeline, and
    # graphs share the behaviour (`compile` accepts a graph followed by NUL and garbage).
    def test_bytes_after_a_nul_are_not_ignored(self):
        one = '{"time": 0, %s, "label": "a"}' % KEY
        for what in ("timeline", "graph"):
            with self.subTest(what):
                if what == "timeline":
                    self.render('{"keyframes": [%s]}\u0000 garbage {{{' % one, 2, "t.json")
                else:
                    g = self.write("g.json", json.dumps(hs.flat_graph()) + "\u0000 garbage {{{")
                    self.failsUnchanged(["compile", g, "-o", self.path("out")], 1, "g.json")

    def test_escapes_in_labels_never_reach_stderr_raw(self):
        # An error after the label is read (a later keyframe out of range).
        bad = KEY.replace('"temperature": 5', '"temperature": 500')
        self.render('{"keyframes": [{"time": 0, %s, "label": "\\u001b[2J\\u0007"}, {"time": 10, %s, '
                    '"label": "\\u001b]0;x\\u0007"}]}' % (KEY, bad), 2, "t.json")


class Frames(HostileCase):
    def test_frames_folder_clashes(self):
        t = self.write("t.json", hs.timeline(2))
        self.write("file", b"x")
        for frames in (self.path("file"), t):
            with self.subTest(frames):
                self.failsUnchanged(["render", "--scene", "valley", "--size", "32x32", "--timeline", t, "--frames",
                                     frames, "-o", self.path("x.png")], 2, vulkan=True)

    # Fixed, kept as a regression: `--frames FILE/below` renders every stage, then exits 3
    # ("filesystem error: cannot create directories: Not a directory"): the folder is
    # only checked when the first frame is written, and the exception is not turned
    # into a usage error. `--frames FILE` is checked before rendering.
    def test_frames_folder_below_a_file(self):
        t = self.write("t.json", hs.timeline(2))
        self.write("file", b"x")
        self.failsUnchanged(["render", "--scene", "valley", "--size", "32x32", "--timeline", t, "--frames",
                             self.path("file", "below"), "-o", self.path("x.png")], 2, vulkan=True)


if __name__ == "__main__":
    hs.main()
