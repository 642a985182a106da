"""Hostile class: full disks, simulated with RLIMIT_FSIZE. The child ignores SIGXFSZ,
so a write past the limit fails with EFBIG instead of killing it. Each run must fail
with the system's reason and leave the output folder exactly as the previous run left
it: no partial file, no staging folder, no temporary."""

import os
import resource
import signal

import hostile_support as hs
from hostile_support import HostileCase, run_cli

# Limits that fail at different points: the first byte, inside a shader, inside the
# SPIR-V, after the small files.
LIMITS = [0, 1, 4096, 20000, 60000]


def limited(nbytes):
    def preexec():
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
        resource.setrlimit(resource.RLIMIT_FSIZE, (nbytes, nbytes))
    return preexec


class FullDisk(HostileCase):
    def setUp(self):
        super().setUp()
        self.graphs = [self.write("g%d.json" % i, hs.flat_graph("g%d" % i)) for i in range(3)]
        self.graphs.append(self.source("graphs", "rock.json"))
        self.out = self.path("out")
        # The previous run's outputs, which a failed run must leave intact.
        self.assertSucceeds(run_cli(["compile"] + self.graphs + ["-o", self.out, "--emit-header",
                                                                   "--depfile", self.path("out.d")]))
        for i in range(3):  # the next run's outputs differ from these
            self.write("g%d.json" % i, hs.flat_graph("g%d" % i, colour=(0.9, 0.1, 0.1)))

    def sweep(self, args, *mentions, vulkan=False, limits=LIMITS):
        """Runs args under each limit: a failure changes nothing; a success is complete."""
        for nbytes in limits:
            with self.subTest(limit=nbytes):
                before = hs.snapshot(self.dir)
                r = run_cli(args, preexec_fn=limited(nbytes), vulkan=vulkan)
                self.assertClean(r)
                if r.returncode == 0:
                    continue  # everything fitted under this limit
                self.assertIn(r.returncode, (1, 2), str(r))
                self.assertIn("File too large", r.text, "the error should give the system's reason:\n%s" % r)
                for m in mentions:
                    self.assertIn(m, r.text)
                self.assertUnchanged(before, self.dir)

    def test_compile_all_targets_with_header_and_depfile(self):
        self.sweep(["compile"] + self.graphs + ["-o", self.out, "--emit-header", "--depfile", self.path("out.d")])

    def test_compile_with_every_target(self):
        self.sweep(["compile"] + self.graphs + ["-o", self.out, "--target", "all,msl,glsles"], limits=[1, 20000])

    def test_compile_variants(self):
        self.sweep(["compile", self.source("graphs", "rock.json"), "--variants", "all", "-o", self.out], limits=[4096])

    def test_compile_into_a_new_folder_leaves_no_folder(self):
        self.sweep(["compile"] + self.graphs + ["-o", self.path("new", "deeper")])
        self.assertFalse(os.path.exists(self.path("new")))

    def test_render_keeps_the_previous_png(self):
        self.write("x.png", hs.png_bytes(2, 2))
        self.sweep(["render", "--scene", "valley", "--size", "32x32", "-o", self.path("x.png")], "x.png", vulkan=True,
                   limits=[100])

    def test_import_keeps_the_previous_graphs(self):
        model = "/usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb"
        if not os.path.exists(model):
            self.skipTest("assimp-testmodels is not installed")
        self.assertSucceeds(run_cli(["import", model, "-o", self.path("imported")]))
        self.sweep(["import", model, "-o", self.path("imported"), "--weather-preset", "terrain"])


if __name__ == "__main__":
    hs.main()
