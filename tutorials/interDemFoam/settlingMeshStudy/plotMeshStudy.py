#!/usr/bin/python3
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
"""Seed Fig. 3 study: terminal settling velocity of a 1 mm particle against
the cell size, per void-fraction model, and its cost.

Reads  <runs>/<model>-<dx/d>/particleHistory.dat and log.interDemFoam
Writes meshStudy.dat, meshStudyError.png (error vs dx/d),
       meshStudySpeed.png (|error| vs wall time: the speed-accuracy chart)

Reference: the terminal velocity of the seed's eq. 19 in water (Di Felice
single-sphere Cd with the square), 0.1341 m/s. A run that did not reach the
end, or went non-finite, is reported as failed (no point in the charts).
"""
import glob
import math
import os
import re
import sys

import numpy as np

RHO_W, MU_W, G = 1000.0, 1e-3, 9.81
D, RHO_P = 1e-3, 2500.0


def terminal_velocity():
    lo, hi = 1e-6, 5.0
    for _ in range(200):
        v = 0.5 * (lo + hi)
        re_p = RHO_W * v * D / MU_W
        cd = (0.63 + 4.8 / math.sqrt(re_p)) ** 2
        net = (RHO_P - RHO_W) * math.pi / 6 * D ** 3 * G \
            - 0.5 * cd * RHO_W * math.pi / 4 * D ** 2 * v * v
        lo, hi = (v, hi) if net > 0 else (lo, v)
    return 0.5 * (lo + hi)


def main():
    runs = sys.argv[1] if len(sys.argv) > 1 else "runs"
    vt_ref = terminal_velocity()
    rows = []
    for case in sorted(glob.glob(os.path.join(runs, "*-*"))):
        model, ratio = os.path.basename(case).rsplit("-", 1)
        ratio = float(ratio)
        log = os.path.join(case, "log.interDemFoam")
        text = open(log).read() if os.path.exists(log) else ""
        m = re.search(r"Timing split: DEM (\S+) s, CFD (\S+) s, coupling (\S+) s", text)
        ok = m is not None and "\nEnd" in text
        wall = sum(float(x) for x in m.groups()) if m else float("nan")
        floor_hits = len(re.findall(r"voidfraction floor .* hit", text))
        vt, spread = float("nan"), float("nan")
        hist = os.path.join(case, "particleHistory.dat")
        if ok and os.path.exists(hist):
            data = np.loadtxt(hist, comments="#", ndmin=2)
            tail = data[:, 0] >= data[-1, 0] - 0.03
            v = -data[tail, 2]
            if np.all(np.isfinite(v)):
                vt = float(v.mean())
                spread = float(v.max() - v.min())
            else:
                ok = False
        err = (vt - vt_ref) / vt_ref
        rows.append((model, ratio, vt, err, spread, wall, floor_hits, ok))

    with open("meshStudy.dat", "w") as f:
        f.write("# terminal velocity of a 1 mm particle vs cell size; eq. 19: %.4f m/s\n"
                % vt_ref)
        f.write("# model dx/d v_terminal[m/s] error[%] v_range_last_0.03s[m/s]"
                " wall[s] floorHitSteps ran\n")
        for r in rows:
            f.write("%-14s %5.2f %9.5f %+8.2f %9.5f %8.1f %6d %s\n"
                    % (r[0], r[1], r[2], 100 * r[3], r[4], r[5], r[6],
                       "yes" if r[7] else "FAILED"))
    print(open("meshStudy.dat").read())

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    models = sorted({r[0] for r in rows})
    markers = {"centre": "o", "divided": "s", "virtualSphere": "^", "diffusion": "D"}

    fig, ax = plt.subplots(figsize=(7, 4.5))
    for mname in models:
        pts = sorted((r[1], 100 * r[3]) for r in rows if r[0] == mname and r[7])
        if pts:
            ax.plot(*zip(*pts), marker=markers.get(mname, "x"), label=mname)
    ax.axhspan(-3, 3, color="0.9", label="$\\pm$3 %")
    ax.axhline(0, color="k", lw=0.8)
    ax.set_xlabel("cell size / particle diameter  $\\Delta x/d$")
    ax.set_ylabel("terminal velocity error vs eq. 19 [%]")
    ax.set_title("1 mm particle settling in water (seed Fig. 3)")
    ax.legend()
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig("meshStudyError.png", dpi=120)

    fig, ax = plt.subplots(figsize=(7, 4.5))
    for mname in models:
        pts = [(r[5], abs(100 * r[3]), r[1]) for r in rows if r[0] == mname and r[7]]
        if pts:
            ax.scatter([p[0] for p in pts], [max(p[1], 1e-2) for p in pts],
                       marker=markers.get(mname, "x"), label=mname)
            for p in pts:
                ax.annotate("%g" % p[2], (p[0], max(p[1], 1e-2)), fontsize=7,
                            xytext=(3, 3), textcoords="offset points")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("wall time of the run [s] (labels: $\\Delta x/d$)")
    ax.set_ylabel("|terminal velocity error| [%]")
    ax.set_title("Speed against accuracy")
    ax.legend()
    ax.grid(alpha=0.3, which="both")
    fig.tight_layout()
    fig.savefig("meshStudySpeed.png", dpi=120)
    return 0


if __name__ == "__main__":
    sys.exit(main())
