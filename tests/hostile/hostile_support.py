"""Shared helpers for the hostile catalog (tests/hostile/*.py).

Every case runs the real CLI binary in a child process with a hard timeout, so a hang
fails the case instead of blocking CI, and checks the outcome from the outside:

* the exit code is the documented one (1 bad input, 2 bad usage), never 3 (a bug),
  never a signal, never the timeout;
* stderr holds no raw control bytes (ESC, CR, BEL...) and names the file or JSON
  pointer at fault;
* the output directory and the input files are exactly as before (names, sizes,
  SHA-256 of contents, link targets), via tree snapshots.

The CLI path and the source dir come from the command line (ctest passes
$<TARGET_FILE:weathergen> and the source dir) or from WG_CLI / WG_SOURCE_DIR:

    python3 tests/hostile/files.py --cli build/weathergen --source-dir .
"""

import hashlib
import json
import os
import shutil
import signal
import stat
import struct
import subprocess
import sys
import tempfile
import time
import unittest
import zlib

CLI = os.environ.get("WG_CLI", "")
SOURCE_DIR = os.environ.get("WG_SOURCE_DIR", os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))

# Seconds a case may take before it counts as a hang. Generous: the sanitizer build is
# several times slower, and CI has 2 cores shared by parallel tests.
DEFAULT_TIMEOUT = 60


def main():
    """unittest.main() after taking --cli and --source-dir off the command line."""
    global CLI, SOURCE_DIR
    argv = [sys.argv[0]]
    args = sys.argv[1:]
    while args:
        a = args.pop(0)
        if a == "--cli":
            CLI = args.pop(0)
        elif a == "--source-dir":
            SOURCE_DIR = args.pop(0)
        else:
            argv.append(a)
    if not CLI:
        CLI = os.path.join(SOURCE_DIR, "build", "weathergen")
    CLI = os.path.abspath(CLI)
    SOURCE_DIR = os.path.abspath(SOURCE_DIR)
    if not os.access(CLI, os.X_OK):
        sys.exit("hostile: no CLI at %s (pass --cli PATH)" % CLI)
    unittest.main(argv=argv, verbosity=2)


def sanitized_build():
    """True when the CLI was built with AddressSanitizer (WEATHERGEN_SANITIZE)."""
    with open(CLI, "rb") as f:
        return b"__asan_init" in f.read()


_SLOW = None


def time_scale():
    """How many times slower than a normal build the CLI is expected to run."""
    global _SLOW
    if _SLOW is None:
        _SLOW = 6.0 if sanitized_build() else 1.0
    return _SLOW


# --- running the CLI ---------------------------------------------------------------

class Result:
    def __init__(self, args, returncode, stdout, stderr, seconds, timed_out):
        self.args, self.returncode = args, returncode
        self.stdout, self.stderr = stdout, stderr
        self.seconds, self.timed_out = seconds, timed_out

    @property
    def text(self):
        return self.stderr.decode("utf-8", "replace")

    def __str__(self):
        return "weathergen %s\n  exit %s after %.2fs%s\n  stderr: %r\n  stdout: %r" % (
            " ".join(repr(a) for a in self.args), self.returncode, self.seconds,
            " (TIMED OUT: a hang)" if self.timed_out else "", self.stderr[:2000], self.stdout[:500])


def child_env(vulkan=False, extra=None):
    env = dict(os.environ)
    # A non-TTY stderr already silences the progress line; -q is not needed.
    if vulkan:
        # Under the sanitizer build the child unloads lavapipe before LeakSanitizer runs
        # (tests/integration/process_support.hpp kVulkanChildEnvironment).
        env["ASAN_OPTIONS"] = "detect_leaks=0:abort_on_error=1"
    if extra:
        env.update(extra)
    return env


def run_cli(args, cwd=None, timeout=DEFAULT_TIMEOUT, vulkan=False, env=None, preexec_fn=None, stdin=subprocess.DEVNULL):
    """Runs the CLI; a hang is killed at `timeout` and reported as timed_out."""
    start = time.monotonic()
    proc = subprocess.Popen([CLI] + [str(a) for a in args], cwd=cwd, stdin=stdin, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, env=child_env(vulkan, env), preexec_fn=preexec_fn,
                            start_new_session=True)
    timed_out = False
    try:
        out, err = proc.communicate(timeout=timeout * time_scale())
    except subprocess.TimeoutExpired:
        timed_out = True
        os.killpg(proc.pid, signal.SIGKILL)
        out, err = proc.communicate()
    return Result(args, proc.returncode, out, err, time.monotonic() - start, timed_out)


# --- tree snapshots ----------------------------------------------------------------

def snapshot(*roots):
    """{path: description} of every entry under each root (not following links):
    kind, size and SHA-256 for files, target for links. A missing root is recorded."""
    snap = {}
    for root in roots:
        root = str(root)
        if not os.path.lexists(root):
            snap[root] = ("missing",)
            continue
        snap[root] = _describe(root)
        if os.path.isdir(root) and not os.path.islink(root):
            for dirpath, dirnames, filenames in os.walk(root):
                for name in dirnames + filenames:
                    p = os.path.join(dirpath, name)
                    snap[p] = _describe(p)
    return snap


def _describe(path):
    st = os.lstat(path)
    if stat.S_ISLNK(st.st_mode):
        return ("link", os.readlink(path))
    if stat.S_ISDIR(st.st_mode):
        return ("dir",)
    if stat.S_ISREG(st.st_mode):
        h = hashlib.sha256()
        with open(path, "rb") as f:
            for block in iter(lambda: f.read(1 << 20), b""):
                h.update(block)
        return ("file", st.st_size, h.hexdigest())
    return ("special", stat.S_IFMT(st.st_mode))


def diff_snapshots(before, after):
    lines = []
    for p in sorted(set(before) | set(after)):
        if before.get(p) != after.get(p):
            lines.append("  %s: %s -> %s" % (p, before.get(p, "absent"), after.get(p, "absent")))
    return "\n".join(lines)


# --- PNGs and graphs ---------------------------------------------------------------

def png_bytes(width, height, pixels=None, claimed=None):
    """An RGBA PNG. `claimed` = (w, h) writes those in IHDR while the data stays small."""
    w, h = claimed or (width, height)
    raw = b"".join(b"\0" + (pixels or b"\x80\x40\x20\xff") * width for _ in range(height))

    def chunk(tag, data):
        return struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF)

    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 6, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


def flat_graph(name="g", colour=(0.5, 0.4, 0.3), **extra):
    g = {"name": name, "nodes": [], "output": {"baseColor": list(colour)}}
    g.update(extra)
    return g


def texture_graph(file_name, name="g"):
    """A graph whose one image texture is `file_name` (any string, JSON-escaped here)."""
    return {"name": name, "textures": {"t": {"file": file_name}},
            "nodes": [{"id": "uv", "op": "texcoord"},
                      {"id": "s", "op": "sample", "inputs": {"texture": "t", "uv": "uv.out"}}],
            "output": {"baseColor": "s.rgb"}}


def library(params=1, padding=0):
    """A graph library with `params` float parameters and `padding` bytes of description."""
    lib = {"description": "x" * padding,
           "parameters": {"p%d" % i: {"type": "float", "default": 0.5} for i in range(params)},
           "nodes": [{"id": "p0", "op": "parameter", "param": "p0"}]}
    return lib


def timeline(stages, keys_per_stage=1):
    """A valid timeline with `stages` distinctly labelled stages."""
    keys = []
    t = 0
    for s in range(stages):
        for _ in range(keys_per_stage):
            keys.append({"time": t, "temperature": 5, "precipitation": 0.2, "windIntensity": 0.1,
                         "wind": [1, 0], "label": "stage %d" % s})
            t += 600
    return {"keyframes": keys}


def triangle_model(folder, name="box", material=None, image=None, version="2.0", buffer_uri=None, image_uri="tex.png"):
    """Writes a one-triangle glTF model, NAME.gltf with its buffer NAME.bin and image
    tex.png beside it, into `folder`; returns the .gltf path. `material` replaces the
    material, `image` the PNG's bytes."""
    positions = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)
    texcoords = struct.pack("<6f", 0, 0, 1, 0, 0, 1)
    buffer_uri = buffer_uri or name + ".bin"
    write(os.path.join(folder, buffer_uri.replace("%2B", "+")), positions + texcoords)
    write(os.path.join(folder, image_uri.replace("%2B", "+")), image if image is not None else png_bytes(2, 2))
    model = {
        "asset": {"version": version}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "material": 0}]}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
                      {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC2"}],
        "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 24}],
        "buffers": [{"uri": buffer_uri, "byteLength": 60}],
        "materials": [material or {"name": "Mat", "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
        "textures": [{"source": 0}], "images": [{"uri": image_uri}],
    }
    return write(os.path.join(folder, name + ".gltf"), model)


def read(path, mode="rb"):
    with open(str(path), mode) as f:
        return f.read()


def write(path, content):
    path = str(path)
    if isinstance(content, (dict, list)):
        content = json.dumps(content, indent=1)
    if isinstance(content, str):
        content = content.encode("utf-8")
    with open(path, "wb") as f:
        f.write(content)
    return path


# Control bytes that must never reach a terminal raw: C0 except TAB and LF, DEL, and
# the C1 range's single-byte CSI when it is not part of a UTF-8 sequence.
RAW_CONTROL = set(range(0x00, 0x09)) | set(range(0x0B, 0x20)) | {0x7F}


class HostileCase(unittest.TestCase):
    """A case in a fresh temp dir (self.dir), removed afterwards."""

    def setUp(self):
        self.dir = tempfile.mkdtemp(prefix="wg-hostile-")
        self.addCleanup(self._cleanup)

    def _cleanup(self):
        # A test may leave read-only dirs or FIFOs; make everything removable.
        for dirpath, dirnames, _ in os.walk(self.dir):
            for d in dirnames:
                p = os.path.join(dirpath, d)
                if not os.path.islink(p):
                    os.chmod(p, 0o700)
        shutil.rmtree(self.dir, ignore_errors=True)

    def clear(self, keep=()):
        """Empties the temp dir between subtests, but for the names in `keep`."""
        for f in os.listdir(self.dir):
            if f not in keep:
                p = self.path(f)
                if os.path.isdir(p) and not os.path.islink(p):
                    shutil.rmtree(p)
                else:
                    os.remove(p)

    def path(self, *parts):
        return os.path.join(self.dir, *parts)

    def write(self, name, content):
        return write(self.path(name), content)

    def source(self, *parts):
        return os.path.join(SOURCE_DIR, *parts)

    def png(self, name="ok.png", size=4):
        return self.write(name, png_bytes(size, size))

    # --- assertions ----------------------------------------------------------------

    def assertNoSignal(self, r):
        self.assertFalse(r.timed_out, "the CLI hung:\n%s" % r)
        self.assertGreaterEqual(r.returncode, 0, "the CLI died by signal %d:\n%s" % (-r.returncode, r))
        self.assertNotIn(r.returncode, (3, 134, 139), "internal error (exit 3) or abort:\n%s" % r)
        self.assertNotIn(b"AddressSanitizer", r.stderr, str(r))
        self.assertNotIn(b"runtime error:", r.stderr, str(r))

    def assertClean(self, r):
        """No hang, no signal, no internal error, no raw control bytes on stderr."""
        self.assertNoSignal(r)
        bad = sorted({b for b in r.stderr if b in RAW_CONTROL})
        self.assertEqual(bad, [], "raw control bytes %s reached stderr:\n%s" % ([hex(b) for b in bad], r))
        self.assertNotIn(b"\xc2\x9b", r.stderr, "a raw C1 CSI reached stderr:\n%s" % r)

    def assertFails(self, r, code, *mentions):
        """Exit `code` (1 or 2, or a tuple of them), clean stderr that mentions each string."""
        self.assertClean(r)
        codes = code if isinstance(code, tuple) else (code,)
        self.assertIn(r.returncode, codes, str(r))
        for m in mentions:
            self.assertIn(m, r.text, "stderr should mention %r:\n%s" % (m, r))

    def assertSucceeds(self, r):
        self.assertClean(r)
        self.assertEqual(r.returncode, 0, str(r))

    def assertUnchanged(self, before, *roots):
        after = snapshot(*roots)
        self.assertEqual(before, after, "files changed:\n" + diff_snapshots(before, after))

    def failsUnchanged(self, args, code, *mentions, watch=None, **kw):
        """Runs args; asserts the failure and that `watch` (default: the temp dir) is unchanged."""
        roots = watch or [self.dir]
        before = snapshot(*roots)
        r = run_cli(args, **kw)
        self.assertFails(r, code, *mentions)
        after = snapshot(*roots)
        self.assertEqual(before, after, "the failed run changed files:\n%s\n%s" % (diff_snapshots(before, after), r))
        return r

