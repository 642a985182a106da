"""Hostile class: kill tests. SIGKILL a batch compile at different moments over an
output folder that holds an older compile's outputs: every file present is whole
(old or new, never cut), JSON parses and SPIR-V is whole modules; the leftovers a
SIGKILL cannot clean up are only staging folders; a re-run succeeds."""

import json
import os
import shutil
import signal
import subprocess
import tempfile
import time
import unittest

import hostile_support as hs
from hostile_support import HostileCase, run_cli

SPIRV_MAGIC = b"\x03\x02\x23\x07"
STAGING = ".weathergen-staging-"


def file_hashes(directory):
    return {f: hs._describe(os.path.join(directory, f)) for f in os.listdir(directory)
            if os.path.isfile(os.path.join(directory, f))}


class KillCase(HostileCase):
    GRAPHS = ["rock", "terrain", "river"]
    ROUNDS = 2  # copies of each graph, under other names

    @classmethod
    def setUpClass(cls):
        # Graphs and reference outputs, shared by the class's cases.
        cls.shared = tempfile.mkdtemp(prefix="wg-hostile-kill-")
        cls.graphs = []
        for round_ in range(cls.ROUNDS):
            for g in cls.GRAPHS:
                text = hs.read(os.path.join(hs.SOURCE_DIR, "graphs", g + ".json"), "r")
                text = text.replace('"name": "%s"' % g, '"name": "%s_%d"' % (g, round_), 1)
                cls.graphs.append(hs.write(os.path.join(cls.shared, "%s_%d.json" % (g, round_)), text))
        cls.args = ["compile"] + cls.graphs + ["-j", "2", "--emit-header"]
        # The old outputs (no weather) and the new ones (each graph's preset) differ.
        cls.ref_old, ref_new = os.path.join(cls.shared, "ref-old"), os.path.join(cls.shared, "ref-new")
        for r in (run_cli(cls.args + ["-o", cls.ref_old, "--weather-preset", "none"]),
                  run_cli(cls.args + ["-o", ref_new])):
            if r.returncode != 0:
                raise RuntimeError(str(r))
        cls.full_run = r.seconds
        cls.old, cls.new = file_hashes(cls.ref_old), file_hashes(ref_new)
        assert set(cls.old) == set(cls.new)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.shared, ignore_errors=True)

    def setUp(self):
        super().setUp()
        self.out = self.path("out")

    def reset(self):
        if os.path.exists(self.out):
            shutil.rmtree(self.out)
        shutil.copytree(self.ref_old, self.out)

    def start(self):
        return subprocess.Popen([hs.CLI] + self.args + ["-o", self.out], stdout=subprocess.DEVNULL,
                                stderr=subprocess.DEVNULL, env=hs.child_env())

    def check_after_kill(self):
        """Every final file is whole; returns (leftovers, mix) where mix = (only-old, only-new) names."""
        leftovers, only_old, only_new = [], [], []
        for f in sorted(os.listdir(self.out)):
            p = os.path.join(self.out, f)
            if f.startswith(STAGING):
                leftovers.append(f)
                continue
            self.assertIn(f, self.old, "an unexpected file after a kill: %s" % f)
            d = hs._describe(p)
            self.assertIn(d, (self.old[f], self.new[f]), "%s is neither the old nor the new file: cut short" % f)
            data = hs.read(p)
            if f.endswith(".json"):
                json.loads(data)
            if f.endswith(".spv"):
                self.assertEqual(len(data) % 4, 0, f)
                self.assertEqual(data[:4], SPIRV_MAGIC, f)
            if self.old[f] != self.new[f]:
                (only_old if d == self.old[f] else only_new).append(f)
        missing = set(self.old) - set(os.listdir(self.out))
        self.assertEqual(missing, set(), "a kill lost outputs that were there before")
        return leftovers, (only_old, only_new)


class Kill(KillCase):
    def test_sigkill_at_several_moments(self):
        notes = []
        fractions = [0.0, 0.1, 0.3, 0.5, 0.7, 0.9, 1.0]
        for fraction in fractions:
            with self.subTest(fraction=fraction):
                self.reset()
                proc = self.start()
                time.sleep(0.02 + fraction * self.full_run)
                proc.send_signal(signal.SIGKILL)
                proc.wait()
                leftovers, (only_old, only_new) = self.check_after_kill()
                notes.append("%.0f%% of %.2fs: exit %s, %d staging leftovers, %d old-only and %d new-only files" % (
                    fraction * 100, self.full_run, proc.returncode, len(leftovers), len(only_old), len(only_new)))
        # A kill while the outputs are staged leaves the staging folder behind; a
        # re-run over it succeeds and publishes every new file.
        for attempt in range(20):
            self.reset()
            proc = self.start()
            while proc.poll() is None and not any(f.startswith(STAGING) for f in os.listdir(self.out)):
                time.sleep(0.002)
            proc.send_signal(signal.SIGKILL)
            proc.wait()
            leftovers, _ = self.check_after_kill()
            if leftovers:
                break
        notes.append("killed while staging: %d staging leftovers (%s)" % (len(leftovers), ", ".join(leftovers)))
        r = run_cli(self.args + ["-o", self.out])
        self.assertSucceeds(r)
        self.assertEqual({f: d for f, d in file_hashes(self.out).items()}, self.new)
        after = [f for f in os.listdir(self.out) if f.startswith(STAGING)]
        notes.append("after a re-run: %d staging leftovers remain (%s)" % (len(after), ", ".join(after)))
        print("\n  " + "\n  ".join(notes))

    def test_sigterm_and_sigint_clean_up(self):
        # Unlike SIGKILL, these can be handled: ideally no staging folder is left.
        for sig in (signal.SIGTERM, signal.SIGINT):
            with self.subTest(sig.name):
                self.reset()
                proc = self.start()
                time.sleep(0.3 * self.full_run)
                proc.send_signal(sig)
                proc.wait(timeout=60)
                leftovers, _ = self.check_after_kill()
                print("\n  %s: exit %s, staging leftovers: %s" % (sig.name, proc.returncode, leftovers or "none"))


class PublishWindow(KillCase):
    ROUNDS = 4  # more files, a longer publish loop to land in
    # Bug: publishing renames the staged files one by one, so a SIGKILL that lands
    # inside the publish loop leaves some materials' files new and others old (and a
    # material's own file set mixed). Each file is whole, but the folder is neither the
    # old state nor the new one. The kill is timed to land inside the loop: when the
    # staging folder starts to empty.
    @unittest.expectedFailure
    def test_a_sigkill_during_publish_leaves_all_old_or_all_new(self):
        for attempt in range(10):
            self.reset()
            proc = self.start()
            staging, most, landed = None, 0, False
            deadline = time.monotonic() + 60 * hs.time_scale()
            while proc.poll() is None and time.monotonic() < deadline:
                if staging is None:
                    names = [f for f in os.listdir(self.out) if f.startswith(STAGING)]
                    staging = os.path.join(self.out, names[0]) if names else None
                    continue
                try:
                    count = len(os.listdir(staging))
                except FileNotFoundError:
                    break
                if count < most:
                    proc.send_signal(signal.SIGKILL)
                    landed = True
                    break
                most = max(most, count)
            proc.wait()
            if landed and proc.returncode == -signal.SIGKILL:
                _, (only_old, only_new) = self.check_after_kill()
                if only_old and only_new:
                    print("\n  landed on attempt %d: %d files old, %d new" % (attempt + 1, len(only_old), len(only_new)))
                    self.fail("a kill during publish left %d files old and %d new, e.g. %s (old) beside %s (new)" % (
                        len(only_old), len(only_new), only_old[0], only_new[0]))
        # Only a mixed folder decides; when publishing is fixed this skips (remove the
        # expectedFailure then).
        self.skipTest("no kill during publish left a mixed folder in 10 attempts")


if __name__ == "__main__":
    hs.main()
