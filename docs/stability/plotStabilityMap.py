#!/usr/bin/python3
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
"""Stability map of the void-fraction models (see runStabilityMap.sh).

Reads runs/<model>-<dx/d>/log.interDemFoam; writes
etc/sceneMaps/stabilityMap.dat (the map checkDemScene reads) and
stabilityMap.png here. A run is 'bounded' when it reached the end, nothing went
non-finite, eps stayed in [floor, 1] (by construction; the floor hits are
counted) and the continuity error stayed below 1e-3 (sum local, per step).
"""
import glob
import os
import re
import sys

runs = sys.argv[1] if len(sys.argv) > 1 else "runs"
rows = []
for case in sorted(glob.glob(os.path.join(runs, "*-*"))):
    model, ratio = os.path.basename(case).rsplit("-", 1)
    text = open(os.path.join(case, "log.interDemFoam"), errors="replace").read()
    ended = "\nEnd" in text
    nonfinite = bool(re.search(r"(?i)\bnan\b|Non-finite|inf\b", text))
    eps = [float(x) for x in re.findall(r"min\(voidfraction\) (\S+)", text)]
    floor_steps = len(re.findall(r"voidfraction floor \S+ hit", text))
    cont = [float(x) for x in re.findall(r"continuity errors : sum local = (\S+),", text)]
    m = re.search(r"Timing split: DEM (\S+) s, CFD (\S+) s, coupling (\S+) s", text)
    wall = sum(float(x) for x in m.groups()) if m else float("nan")
    steps = len(re.findall(r"^Time = ", text, re.M))
    bounded = ended and not nonfinite and (max(cont) if cont else 1) < 1e-3
    rows.append(dict(model=model, ratio=float(ratio), ended=ended,
                     nonfinite=nonfinite, minEps=min(eps) if eps else float("nan"),
                     floorSteps=floor_steps, steps=steps,
                     maxCont=max(cont) if cont else float("nan"),
                     wall=wall, bounded=bounded))

out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                   "etc", "sceneMaps", "stabilityMap.dat")
with open(out, "w") as f:
    f.write("# settling cloud, 64 particles of 1 mm, 0.1 s; per model and dx/d\n")
    f.write("# model dx/d bounded ended nonFinite minEps floorHitSteps/steps"
            " maxContinuityErr wall[s]\n")
    for r in rows:
        f.write("%-14s %5.2f %-7s %-5s %-5s %8.4f %6d/%-6d %10.3e %8.1f\n"
                % (r["model"], r["ratio"], "yes" if r["bounded"] else "NO",
                   "yes" if r["ended"] else "no", "yes" if r["nonfinite"] else "no",
                   r["minEps"], r["floorSteps"], r["steps"], r["maxCont"], r["wall"]))
print(open(out).read())

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

models = sorted({r["model"] for r in rows})
ratios = sorted({r["ratio"] for r in rows})
fig, ax = plt.subplots(figsize=(1.3 * len(ratios) + 2, 0.9 * len(models) + 1.5))
for r in rows:
    x, y = ratios.index(r["ratio"]), models.index(r["model"])
    colour = "#8fd18f" if r["bounded"] and not r["floorSteps"] else \
        "#f2d479" if r["bounded"] else "#e88080"
    ax.add_patch(plt.Rectangle((x - 0.5, y - 0.5), 1, 1, color=colour))
    label = ("min $\\epsilon$ %.2f\nfloor %d" % (r["minEps"], r["floorSteps"])
             if r["ended"] else "failed")
    ax.text(x, y, label, ha="center", va="center", fontsize=8)
ax.set_xlim(-0.5, len(ratios) - 0.5)
ax.set_ylim(-0.5, len(models) - 0.5)
ax.set_xticks(range(len(ratios)))
ax.set_xticklabels(["%g" % q for q in ratios])
ax.set_yticks(range(len(models)))
ax.set_yticklabels(models)
ax.set_xlabel("$\\Delta x/d$")
ax.set_title("Settling cloud (64 x 1 mm): green bounded, yellow floor hit, red failed")
fig.tight_layout()
fig.savefig("stabilityMap.png", dpi=120)
