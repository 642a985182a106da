#!/usr/bin/env python3
"""Prints the sun tables of docs/weather-model.md (eq. 3.5): mean snow and moss coverage
of rock.json for normals around the hemisphere at several sun elevations, from
`weathergen eval`. Each cell averages a 5 x 5 grid of points 0.37 m apart (y = 0), so the
noisy edges of eq. 3.14 average out. The sun shines from +x; "towards" faces tilt to +x.

usage: scripts/weather-sun-table.py [WEATHERGEN] [EXTRA_WEATHER]
  EXTRA_WEATHER is appended to every --weather list (e.g. sunMelt=1).
"""
import json
import math
import subprocess
import sys

weathergen = sys.argv[1] if len(sys.argv) > 1 else "build/weathergen"
extra = sys.argv[2] if len(sys.argv) > 2 else ""
ELEVATIONS = [15, 25, 45, 60, 90]
POINTS = [(0.37 * i + 0.11, 0.37 * j + 0.23) for i in range(5) for j in range(5)]


def mean_coverage(term, weather, normal):
    total = 0.0
    for x, z in POINTS:
        at = "worldPosition=%g:0:%g,normal=%s,texcoord=%g:%g" % (x, z, normal, x / 4, z / 4)
        w = weather + ("," + extra if extra else "")
        out = subprocess.run([weathergen, "eval", "graphs/rock.json", "--weather", w, "--at", at],
                             check=True, capture_output=True, text=True).stdout
        total += json.loads(out)["coverage"][term]
    return total / len(POINTS)


def tilted(degrees, towards):
    t = math.radians(degrees)
    return "%.6f:%.6f:0" % (math.sin(t) * (1 if towards else -1), math.cos(t))


def sun(e):
    r = math.radians(e)
    return "%.6f:%.6f:0" % (math.cos(r), math.sin(r))


snow_columns = [("flat", "0:1:0"), ("30° towards", tilted(30, True)), ("30° away", tilted(30, False)),
                ("45° towards", tilted(45, True)), ("45° away", tilted(45, False))]
print("Snow, snowLevel 1, -4 °C, sunIntensity 1:")
print("| sun elevation | " + " | ".join(c for c, _ in snow_columns) + " |")
print("|---" * (len(snow_columns) + 1) + "|")
for e in ELEVATIONS:
    weather = "snowLevel=1,temperature=-4,sunDirection=" + sun(e)
    row = [mean_coverage("snow", weather, n) for _, n in snow_columns]
    print("| %d° | " % e + " | ".join("%.2f" % v for v in row) + " |")

moss_columns = [("shaded flank", "-1:0:0"), ("top", "0:1:0"), ("sunlit flank", "1:0:0")]
for level in (0.3, 0.6):
    print()
    print("Moss, mossLevel %g, 13 °C, sunIntensity 1:" % level)
    print("| sun elevation | " + " | ".join(c for c, _ in moss_columns) + " |")
    print("|---" * (len(moss_columns) + 1) + "|")
    for e in ELEVATIONS:
        weather = "mossLevel=%g,temperature=13,sunDirection=%s" % (level, sun(e))
        row = [mean_coverage("moss", weather, n) for _, n in moss_columns]
        print("| %d° | " % e + " | ".join("%.2f" % v for v in row) + " |")
