#!/usr/bin/env python3
"""Checks the WeathergenCompile spawns of a Bazel --execution_log_json_file.

Usage: cache_hits.py LOG SPAWNS HITS RUNNER
Fails unless the log has exactly SPAWNS weathergen spawns, exactly HITS of them cache
hits, every other one run by RUNNER ("worker": the persistent worker; "local": a
process of its own), and no absolute path or environment variable in any of their keys.
"""
import json
import sys


def spawns(path):
    # Bazel writes one JSON object after another, not a JSON array.
    text = open(path, encoding="utf-8").read()
    decoder = json.JSONDecoder()
    pos = 0
    while True:
        while pos < len(text) and text[pos].isspace():
            pos += 1
        if pos == len(text):
            return
        spawn, pos = decoder.raw_decode(text, pos)
        yield spawn


def main():
    log, want_spawns, want_hits, want_runner = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4]
    compiles = [s for s in spawns(log) if s.get("mnemonic") == "WeathergenCompile"]
    hits = [s for s in compiles if s.get("remoteCacheHit")]
    problems = []
    for s in compiles:
        # Absolute paths or host variables in a key would make it differ per machine.
        absolute = [a for a in s["commandArgs"] if a.startswith("/")]
        absolute += [i["path"] for i in s.get("inputs", []) if i["path"].startswith("/")]
        if absolute:
            problems.append("%s: absolute paths %s" % (s["progressMessage"], absolute))
        if s.get("environmentVariables"):
            problems.append("%s: environment %s" % (s["progressMessage"], s["environmentVariables"]))
    print("%d weathergen spawns, %d cache hits" % (len(compiles), len(hits)))
    for s in compiles:
        if not s.get("remoteCacheHit"):
            print("  ran (%s): %s" % (s.get("runner"), s["progressMessage"]))
            if s.get("runner") != want_runner:
                problems.append("%s: ran by %s, not %s" % (s["progressMessage"], s.get("runner"), want_runner))
    if len(compiles) != want_spawns:
        problems.append("expected %d spawns" % want_spawns)
    if len(hits) != want_hits:
        problems.append("expected %d cache hits" % want_hits)
    for p in problems:
        print("FAIL: " + p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
