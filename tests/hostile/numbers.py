"""Hostile class: numbers on the command line. Every number is parsed strictly, with
the same rules as graphs (JSON numbers, finite, in range): anything else is a usage
error (exit 2) before anything is read, rendered or written. (A NUL cannot be passed
in argv; NULs inside files are in files.py and timelines.py.)"""

import hostile_support as hs
from hostile_support import HostileCase

BAD_REALS = ["+-1", "--1", "+1", "0x10", "inf", "-inf", "nan", "1e999", "-1e999", "1,", " 1", "1 ", "", "1e", ".5",
             "5.", "1_0", "\uff11", "01", "1..2", "1e+", "0b1", "1/2", "١"]
BAD_SIZES = ["4294967297x1", "1x4294967297", "16x16junk", "16x", "x16", "16", "0x16", "16x0", "-16x16", "16x-16",
             " 16x16", "16x16 ", "16X16", "16x16x16", "+16x16", "0x10x16", "1e2x16", "16.0x16", "8193x1",
             "18446744073709551632x16", ""]
BAD_COUNTS = ["0", "-1", "99999999999", "4294967297", "18446744073709551617", "1.5", "1e2", "+2", "0x2", "2x", " 2",
              "", "nan", "inf"]


class CommandLineNumbers(HostileCase):
    def setUp(self):
        super().setUp()
        self.graph = self.write("g.json", hs.flat_graph(parameters={"p": {"type": "float", "default": 0.5}}))

    def test_render_size(self):
        for size in BAD_SIZES:
            with self.subTest(size):
                self.failsUnchanged(["render", "--scene", "valley", "--size", size, "-o", self.path("x.png")], 2,
                                    "--size", vulkan=True)
                self.failsUnchanged(["render", "--scene", "valley", "--size=" + size, "-o", self.path("x.png")], 2,
                                    vulkan=True)

    def test_bench_render_size_and_frames(self):
        self.failsUnchanged(["bench-render", "--size", "16x16junk"], 2, vulkan=True)
        for frames in BAD_COUNTS:
            with self.subTest(frames):
                self.failsUnchanged(["bench-render", "--size", "16x16", "--frames", frames], 2, vulkan=True)

    def test_sample_counts(self):
        for samples in BAD_COUNTS + ["3", "16", "5"]:
            with self.subTest(samples):
                self.failsUnchanged(["render", "--scene", "valley", "--samples", samples, "-o", self.path("x.png")], 2,
                                    "--samples", vulkan=True)
                self.failsUnchanged(["bench-render", "--size", "16x16", "--samples", samples], 2, vulkan=True)

    def test_eval_weather_surface_and_parameters(self):
        for value in BAD_REALS:
            with self.subTest(value):
                for args in (["--weather", "temperature=" + value], ["--param", "p=" + value],
                             ["--at", "texcoord=0.5:" + value], ["--weather", "windDirection=%s:0" % value]):
                    self.failsUnchanged(["eval", self.graph] + args, 2)

    def test_eval_out_of_range_and_repeated(self):
        for args in (["--weather", "temperature=61"], ["--weather", "precipitation=1.5"],
                     ["--weather", "temperature=1,temperature=2"], ["--weather", "windDirection=1:0:0:0"],
                     ["--at", "texcoord=1:2:3"], ["--weather", "=1"],
                     ["--weather", "temperature"], ["--weather", ","], ["--param", "nope=1"]):
            with self.subTest(" ".join(args)):
                self.failsUnchanged(["eval", self.graph] + args, 2)

    def test_compile_job_counts(self):
        for jobs in BAD_COUNTS:
            with self.subTest(jobs):
                self.failsUnchanged(["compile", self.graph, "-o", self.path("out"), "-j", jobs], 2, "-j")
                self.failsUnchanged(["compile", self.graph, "-o", self.path("out"), "-j" + jobs], 2)

    def test_render_camera_scale_and_watch_counts(self):
        for args in (["--camera", "orbit:1,2,3,4"], ["--camera", "orbit:nan,1"], ["--camera", "orbit:1e999,1"],
                     ["--camera", "orbit:0x1,1"], ["--camera", "orbit:1,"], ["--model-scale", "0"],
                     ["--model-scale", "nan"], ["--model-scale", "1e999"], ["--model-scale", "1e-7"],
                     ["--watch", "--watch-renders", "0"], ["--watch", "--watch-renders", "99999999999"]):
            with self.subTest(" ".join(args)):
                self.failsUnchanged(["render", "--scene", "valley", "--size", "16x16", "-o", self.path("x.png")] + args,
                                    2, vulkan=True)

    def test_bench_snow_counts(self):
        for args in (["--frames", "0"], ["--frames", "1e999"], ["--walk-minutes", "nan"], ["--walk-minutes", "-1"],
                     ["--walk-minutes", "1e999"], ["--profile-seconds", "0"], ["--profile-seconds", "1e999"],
                     ["--store-budget", "-1"], ["--store-budget", "nan"], ["--refill-tiles", "0"],
                     ["--refill-tiles", "1.5"], ["--refill-tiles", "99999"]):
            with self.subTest(" ".join(args)):
                self.failsUnchanged(["bench-snow"] + args, 2, vulkan=True)


if __name__ == "__main__":
    hs.main()
