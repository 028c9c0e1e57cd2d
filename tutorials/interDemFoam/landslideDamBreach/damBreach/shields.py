# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
"""The Shields number on the downstream face during overtopping, measured
from a run (damBreachAnalysis.py shields OUT SCALE CASE...), to place the
flagship on the bedload chart of docs/erosion.md.

At every write time from overtopping on:
  - the granular surface z_b(x) of the resting grains (50 mm bins, from the
    particle dump nearest in time) and its slope; the downstream face is
    the bins downstream of the crest where the surface falls by more than
    10 degrees against the flume bed and holds grains;
  - the water depth above the surface in each face bin, from the cells'
    alpha.water: sum over the cells of the column of alpha times the part
    of the cell above z_b (alpha taken uniform in a cell; cells of 50 mm,
    so a depth of 10-20 mm lies within one cell: a coarse measure);
  - tau_b = rho g h sin(beta), beta the face angle against the horizontal
    (the surface slope plus the flume's 5 degrees): the momentum balance of
    a uniform sheet flow, the same definition as the bedload channel's
    tau_b = rho g S h;
  - theta = tau_b / ((rho_s - rho) g d50), d50 the mass median of the
    grains.
Writes OUT/shields.<scale>.dat (one row per case: the median over the
overtopping of each time's median and 90th percentile over the face,
median depth, face angle) and CASE/shields.dat (one row per time).
"""
import math
import os
import re
import subprocess
import sys

import numpy as np

from .dumps import (BIN, dump_files, profile_edges, read_dump,
                    read_gravity, surface_profile)

RHO, RHOS = 1000.0, 2650.0
MIN_DEPTH = 0.001          # m: a face bin with less water is dry
FACE_ANGLE = 10.0          # degrees: steeper than this against the bed


def read_internal(path, width):
    """internalField of an OpenFOAM volField (ascii): N x width array."""
    text = open(path).read()
    m = re.search(r'internalField\s+uniform\s+([^;]+);', text)
    if m:
        return None if width > 1 else float(m.group(1))
    m = re.search(r'internalField\s+nonuniform\s+List<\w+>\s*(\d+)\s*\(',
                  text)
    if not m:
        sys.exit('damBreachShields: cannot read %s' % path)
    n = int(m.group(1))
    body = text[m.end():]
    nums = re.findall(r'[-+]?\d*\.?\d+(?:[eE][-+]?\d+)?',
                      body[:body.index('\n)')])
    a = np.array(nums[:n*width], dtype=float)
    return a.reshape(n, width) if width > 1 else a


def cell_centres(case):
    c = os.path.join(case, '0', 'C')
    if not os.path.isfile(c):
        subprocess.run(['postProcess', '-case', case, '-func',
                        'writeCellCentres', '-time', '0'],
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                       check=True)
    return read_internal(c, 3)


def summary_value(case, key):
    for line in open(os.path.join(case, 'damBreach.summary')):
        if line.startswith(key):
            return float(line.split()[-1])
    return None


def d50_of(p):
    d = 2*p[:, 1]
    order = np.argsort(d)
    m = np.cumsum(d[order]**3)
    return d[order][np.searchsorted(m, 0.5*m[-1])]


def face_shields(zb, alpha, C, dz, col, flume, d50):
    """theta, water depth and face angle of each wet bin of the downstream
    face of the granular surface zb at one time (alpha: the cells'
    alpha.water, C their centres, col their bin along the flume)."""
    z = C[:, 2]
    crest = int(np.argmax(zb))
    slope = np.gradient(zb, BIN)
    theta, depth, angle = [], [], []
    for i in range(crest + 1, len(zb)):
        if zb[i] <= 0:
            break
        if slope[i] > -math.tan(math.radians(FACE_ANGLE)):
            continue
        cells = col == i
        above = np.clip((z[cells] + dz/2 - zb[i])/dz, 0.0, 1.0)
        n_across = len(np.unique(np.round(C[cells, 1], 6)))
        h = np.sum(alpha[cells]*above)*dz/n_across
        if h < MIN_DEPTH:
            continue
        beta = math.atan(-slope[i]) + flume
        theta.append(RHO*h*math.sin(beta)/((RHOS - RHO)*d50))
        depth.append(h)
        angle.append(math.degrees(beta))
    return theta, depth, angle


def case_shields(case):
    t_over = summary_value(case, 'overtopping from t [s]')
    if t_over is None or t_over < 0:
        return None
    g = read_gravity(case)
    flume = math.atan2(g[0], -g[2])              # bed slope, rad
    C = cell_centres(case)
    x, z = C[:, 0], C[:, 2]
    zs = np.unique(np.round(z, 6))
    dz = np.min(np.diff(zs))
    dumps = dump_files(case, 'particles')
    dump_t = np.array([t for t, _ in dumps])
    edges = profile_edges()
    col = np.digitize(x, edges) - 1
    d50 = d50_of(read_dump(dumps[0][1]))
    rows = []
    times = sorted(float(d) for d in os.listdir(case)
                   if re.fullmatch(r'\d+(\.\d+)?', d) and float(d) >= t_over)
    for t in times:
        name = '%g' % t
        f = os.path.join(case, name, 'alpha.water')
        if not os.path.isfile(f):
            continue
        alpha = read_internal(f, 1)
        p = read_dump(dumps[int(np.argmin(abs(dump_t - t)))][1])
        if p.size == 0:
            continue
        zb = surface_profile(p, edges)
        theta, depth, angle = face_shields(zb, alpha, C, dz, col, flume, d50)
        if theta:
            rows.append([t, len(theta), np.median(theta),
                         np.percentile(theta, 90), np.median(depth),
                         np.median(angle)])
    if not rows:
        return None
    rows = np.array(rows)
    np.savetxt(os.path.join(case, 'shields.dat'), rows, fmt='%.4g',
               header='t[s] faceBins theta_median theta_p90 depth_median[m] '
                      'faceAngle_median[deg] (damBreachShields.py; d50 '
                      '%.4g m)' % d50)
    return [t_over, len(rows), d50, np.median(rows[:, 2]),
            np.median(rows[:, 3]), np.max(rows[:, 3]), np.median(rows[:, 4]),
            np.median(rows[:, 5])]


def main(out, scale, cases):
    lines = ['# Shields number on the downstream face during overtopping '
             '(damBreachAnalysis.py shields; method: damBreachShields.py)',
             '# theta = rho g h sin(beta) / ((rho_s - rho) g d50), h from '
             'alpha.water above the granular surface (50 mm cells), beta '
             'the face angle; medians over the write times from '
             'overtopping on',
             '# case t_overtop_s times d50_m theta_median theta_p90 '
             'theta_p90_max depth_median_m faceAngle_deg']
    for case in cases:
        r = case_shields(case)
        name = os.path.basename(os.path.normpath(case))
        if r is None:
            lines.append('%s -1 0 nan nan nan nan nan nan' % name)
            continue
        lines.append('%s %.1f %d %.4g %.3g %.3g %.3g %.3g %.1f'
                     % ((name,) + tuple(r)))
    with open(os.path.join(out, 'shields.%s.dat' % scale), 'w') as f:
        f.write('\n'.join(lines) + '\n')
    print('\n'.join(lines))
    return 0
