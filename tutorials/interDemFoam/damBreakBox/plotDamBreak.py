#!/usr/bin/python3
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
"""Dam break in a closed box: water volume and surge front against time.

Reads the case's postProcessing tables and written alpha.water fields and
writes damBreak.png and damBreakFront.dat beside them. The front is the
water length of the bottom cell row; the reference is Martin & Moyce (1952),
column width a = 0.1 m, n^2 = 2, Z = x/a against T = t sqrt(2 g/a).
"""
import os
import re
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

case = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
a, g, nx, dx = 0.1, 9.81, 40, 0.01

# Martin & Moyce (1952), n^2 = 2: (T, Z)
martinMoyce = [(0.41, 1.11), (0.84, 1.22), (1.19, 1.44), (1.43, 1.67),
               (1.63, 1.89), (1.83, 2.11), (1.98, 2.33), (2.20, 2.56),
               (2.32, 2.78), (2.51, 3.00), (2.65, 3.22), (2.83, 3.44),
               (2.98, 3.67), (3.11, 3.89)]


def readVolume(path):
    t, v = [], []
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            cols = line.split()
            t.append(float(cols[0]))
            v.append(float(cols[1]))
    return t, v


def readInternalField(path):
    with open(path) as f:
        text = f.read()
    m = re.search(r"internalField\s+nonuniform\s+List<scalar>\s*\d+\s*\(([^)]*)\)", text)
    if m:
        return [float(x) for x in m.group(1).split()]
    m = re.search(r"internalField\s+uniform\s+([-\d.eE+]+)", text)
    return [float(m.group(1))]*(nx*nx) if m else None


times = sorted((d for d in os.listdir(case) if re.fullmatch(r"[0-9.eE+-]+", d)), key=float)
front = []
for d in times:
    alpha = readInternalField(os.path.join(case, d, "alpha.water"))
    if alpha:
        front.append((float(d), sum(alpha[:nx])*dx))

with open(os.path.join(case, "damBreakFront.dat"), "w") as f:
    f.write("# t [s]  front x [m] (water length of the bottom cell row)\n")
    for t, x in front:
        f.write(f"{t:.6g} {x:.6g}\n")

t, v = readVolume(os.path.join(case, "postProcessing/waterVolume/0/volFieldValue.dat"))
drift = [(vi - v[0])/v[0] for vi in v]

fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.2))
ax1.plot(t, drift, "b-")
ax1.set_xlabel("t [s]")
ax1.set_ylabel(r"relative change of $\sum \varepsilon \alpha V$")
ax1.set_title(f"water volume (max |drift| {max(abs(d) for d in drift):.1e})")
ax1.ticklabel_format(axis="y", style="sci", scilimits=(0, 0))

scale = (2*g/a)**0.5
ax2.plot([T for T, Z in martinMoyce], [Z for T, Z in martinMoyce], "ko",
         mfc="none", label="Martin & Moyce (1952)")
ax2.plot([tt*scale for tt, x in front], [x/a for tt, x in front], "r.-",
         label="interDemFoam")
ax2.axhline(0.4/a, color="grey", ls=":", lw=1)
ax2.set_xlabel(r"$T = t\,\sqrt{2g/a}$")
ax2.set_ylabel(r"$Z = x/a$")
ax2.set_title("surge front (grey: far wall)")
ax2.legend()
fig.tight_layout()
out = os.path.join(case, "damBreak.png")
fig.savefig(out, dpi=110)
print("wrote", out, "and", os.path.join(case, "damBreakFront.dat"))
