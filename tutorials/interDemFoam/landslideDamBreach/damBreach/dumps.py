# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
"""A case's DEM data: its DEM step (DEM/in.case, written by Allrun), its
LIGGGHTS dumps (post/particles.<step>.txt, contacts.<step>.txt), gravity;
the surface profile and the energy of one dump."""
import glob
import os
import re
import sys

import numpy as np

REST_SPEED = 0.05      # m/s: a grain slower than this is part of the bed
BIN = 0.05             # m: profile bins (the CFD cell size)
FLUME_LENGTH = 7.0


def read_gravity(case):
    text = open(os.path.join(case, 'constant', 'g')).read()
    m = re.search(r'value\s*\(\s*([-\d.eE+]+)\s+([-\d.eE+]+)\s+([-\d.eE+]+)', text)
    return np.array([float(v) for v in m.groups()])


def case_variables(case):
    """The index variables of CASE/DEM/in.case (written by Allrun)."""
    path = os.path.join(case, 'DEM', 'in.case')
    if not os.path.isfile(path):
        sys.exit('damBreachAnalysis: no %s (Allrun writes it): cannot tell '
                 'the DEM step' % path)
    v = {}
    for line in open(path):
        w = line.split('#')[0].split()
        if len(w) >= 4 and w[0] == 'variable' and w[2] == 'index':
            v[w[1]] = w[3]
    return v


def dem_step(case):
    """The DEM step of the case (demDt in DEM/in.case), s."""
    v = case_variables(case)
    try:
        dt = float(v['demDt'])
    except (KeyError, ValueError):
        sys.exit('damBreachAnalysis: no numeric demDt in %s/DEM/in.case'
                 % case)
    if not dt > 0:
        sys.exit('damBreachAnalysis: demDt %g in %s/DEM/in.case is not '
                 'positive' % (dt, case))
    return dt


def dump_files(case, kind):
    dt = dem_step(case)
    files = glob.glob(os.path.join(case, 'post', kind + '.*.txt'))
    steps = [int(re.search(r'\.(\d+)\.txt$', f).group(1)) for f in files]
    order = np.argsort(steps)
    return [(steps[i]*dt, files[i]) for i in order]


def read_dump(path):
    """The rows of a LIGGGHTS text dump (per-atom or local)."""
    with open(path) as f:
        lines = f.readlines()
    start = next(i for i, l in enumerate(lines) if l.startswith('ITEM: ATOMS')
                 or l.startswith('ITEM: ENTRIES')) + 1
    rows = [l.split() for l in lines[start:] if l.strip()]
    if not rows:
        return np.zeros((0, 0))
    return np.array(rows, dtype=float)


def profile_edges():
    """The edges of the profile bins along the flume, m."""
    return np.arange(0.0, FLUME_LENGTH + BIN/2, BIN)


def surface_profile(p, edges):
    """Top of the resting grains in each bin (0 where none)."""
    x, z, r = p[:, 3], p[:, 5], p[:, 1]
    speed = np.linalg.norm(p[:, 6:9], axis=1)
    rest = speed < REST_SPEED
    h = np.zeros(len(edges) - 1)
    idx = np.digitize(x[rest], edges) - 1
    top = z[rest] + r[rest]
    ok = (idx >= 0) & (idx < len(h))
    np.maximum.at(h, idx[ok], top[ok])
    return h


def energy(p, g):
    m, r = p[:, 2], p[:, 1]
    pos = p[:, 3:6].copy()
    pos[:, 0] -= FLUME_LENGTH                      # datum: bed at the outlet
    ep = -np.sum(m*(pos @ g))
    ek = 0.5*np.sum(m*np.sum(p[:, 6:9]**2, axis=1))
    er = 0.5*np.sum(0.4*m*r**2*np.sum(p[:, 9:12]**2, axis=1))
    return ep, ek, er
