#!/usr/bin/python3
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
"""The turbulent channel over the fixed bed (tests/cases/turbulentBed.sh).

    analyse.py CASE TIME

Reads CASE/TIME/U, k (ASCII, the 6 x 4 x nz cells of the case, blockMesh's
order: x fastest, then y, then z; nz 30 with the air, 26 with a lid) and CASE/grainForce.dat, and prints one
"key value" per line:

    kBed         mean k in the bed one grain below its surface
                 (z = 0.015 ... 0.02 m) [m2/s2]
    kAbove       mean k in the water one grain above it (0.035 ... 0.04 m)
    kRatio       kBed/kAbove
    tauGrains    the fluid force along x on the grains per bed area, mean of
                 the last 5 s of grainForce.dat [Pa]
    tauRatio     tauGrains / (rho g S h) (0.9025 Pa)
    uStar        sqrt(rho g S h / rho) [m/s]
    kappa        von Karman's constant from the log-law fit
    zd           the zero-plane displacement the fit chose [m]
    ks           the roughness, 30 z0 [m]
    ksOverD      ks / d
    fitR2        the fit's coefficient of determination
    uMean        the water's mean velocity above the bed [m/s]

The log law u = (u*/kappa) ln((z - zd)/z0) is fitted to the horizontal
means of u between 1.5 d above the bed surface (z_b = 0.03 m) and 0.5 h
(z = 0.045 ... 0.08 m), u* from the momentum balance; zd is chosen in
[z_b - d, z_b] (the plane where the wall seems to lie: for a bed of
spheres 0.2-0.3 d below the top) as the one that fits best.
"""
import math
import re
import sys

import numpy as np

NX, NY = 6, 4
DZ = 0.005
ZBED = 0.03
D = 0.01
H = 0.1
RHO = 1000.0
TAU = 9.0252*H          # rho g S h [Pa]
AREA = 0.06*0.04


def internal(path, vector):
    """The internalField of an ASCII OpenFOAM field file."""
    text = open(path).read()
    m = re.search(r"internalField\s+nonuniform\s+List<\w+>\s+(\d+)\s*\(", text)
    if not m:
        sys.exit("%s: no nonuniform internalField" % path)
    n = int(m.group(1))
    body = text[m.end():]
    if vector:
        rows = re.findall(r"\(([^()]*)\)", body)[:n]
        return np.array([[float(x) for x in r.split()] for r in rows])
    return np.array([float(x) for x in body.split(")")[0].split()[:n]])


def layers(values):
    """Horizontal means per z layer."""
    nz = len(values)//(NX*NY)
    return values.reshape(nz, NY*NX, *values.shape[1:]).mean(axis=1)


def main(case, time):
    U = internal("%s/%s/U" % (case, time), True)
    k = internal("%s/%s/k" % (case, time), False)
    ux = layers(U[:, 0])
    kz = layers(k)
    zc = (np.arange(len(ux)) + 0.5)*DZ
    out = {}
    out["kBed"] = kz[(zc > 0.015) & (zc < 0.02)].mean()
    out["kAbove"] = kz[(zc > 0.035) & (zc < 0.04)].mean()
    out["kRatio"] = out["kBed"]/out["kAbove"]

    rows = [l.split() for l in open("%s/grainForce.dat" % case)
            if l.strip() and not l.startswith("#")]
    t = np.array([float(r[0]) for r in rows])
    fx = np.array([float(r[1]) for r in rows])
    last = t >= t.max() - 5 + 1e-9
    out["tauGrains"] = fx[last].mean()/AREA
    out["tauRatio"] = out["tauGrains"]/TAU
    uStar = math.sqrt(TAU/RHO)
    out["uStar"] = uStar

    fit = (zc > ZBED + 1.5*D) & (zc < ZBED + 0.5*H)
    best = None
    for zd in np.linspace(ZBED - D, ZBED, 101):
        x = np.log(zc[fit] - zd)
        y = ux[fit]
        slope, icpt = np.polyfit(x, y, 1)
        r2 = 1 - ((y - (slope*x + icpt))**2).sum()/((y - y.mean())**2).sum()
        if best is None or r2 > best[0]:
            best = (r2, zd, slope, icpt)
    r2, zd, slope, icpt = best
    kappa = uStar/slope
    z0 = math.exp(-icpt/slope)
    out["kappa"] = kappa
    out["zd"] = zd
    out["ks"] = 30*z0
    out["ksOverD"] = 30*z0/D
    out["fitR2"] = r2
    water = (zc > ZBED) & (zc < ZBED + H)
    out["uMean"] = ux[water].mean()
    for key, v in out.items():
        print("%-10s %.6g" % (key, v))
    print("# z[m] ux[m/s] k[m2/s2]")
    for z, u, kk in zip(zc, ux, kz):
        print("# %.4f %.5f %.4e" % (z, u, kk))


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
