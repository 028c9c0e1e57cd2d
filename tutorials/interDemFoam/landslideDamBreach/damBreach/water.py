# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
"""The water function objects of a case (CASE/postProcessing): time
series joined over the pieces of a run, probes, the water balance and
the lake's level."""
import glob
import os

import numpy as np


def read_series(case, name, column):
    """A function object's time series, joined over restarts."""
    rows = {}
    for d in sorted(glob.glob(os.path.join(case, 'postProcessing', name, '*')),
                    key=lambda s: float(os.path.basename(s))):
        for f in glob.glob(os.path.join(d, '*.dat')):
            for line in open(f):
                if line.startswith('#') or not line.strip():
                    continue
                w = line.split()
                rows[float(w[0])] = float(w[column])
    t = np.array(sorted(rows))
    return t, np.array([rows[k] for k in t])


def water_balance(case):
    t, vol = read_series(case, 'waterVolume', 1)
    if len(t) < 3:
        return None
    series = {}
    for name in ('inletFlux', 'outletFlux', 'atmosphereFlux'):
        tt, q = read_series(case, name, 1)
        series[name] = np.interp(t, tt, q)
    qin = -series['inletFlux']               # patch fluxes point outwards
    qout = series['outletFlux']
    qtop = series['atmosphereFlux']
    dt = np.diff(t)
    vin = np.sum(qin[1:]*dt)
    vout = np.sum(qout[1:]*dt)
    vtop = np.sum(qtop[1:]*dt)
    dstore = vol[-1] - vol[0]
    return dict(t=t, vol=vol, qin=qin, qout=qout, qtop=qtop, vin=vin,
                vout=vout, vtop=vtop, dstore=dstore,
                error=(vin - vout - vtop - dstore)/max(vin, 1e-30))


def read_probes(case, name, field='alpha.water'):
    """A probes function object's values: {time: [value per probe]},
    joined over restarts (empty without the probes)."""
    rows = {}
    for d in glob.glob(os.path.join(case, 'postProcessing', name, '*')):
        f = os.path.join(d, field)
        if not os.path.isfile(f):
            continue
        for line in open(f):
            if line.startswith('#') or not line.strip():
                continue
            w = line.split()
            rows[float(w[0])] = [float(a) for a in w[1:]]
    return rows


def lake_level(case):
    """Bed-normal lake depth at x = 2.975 m: sum of alpha dz over the probe
    column (probes lakeLevel, 50 mm cells), or None without the probes."""
    rows = {t: sum(v)*0.05 for t, v in read_probes(case, 'lakeLevel').items()}
    if len(rows) < 2:
        return None
    t = np.array(sorted(rows))
    return t, np.array([rows[k] for k in t])


def smooth(t, q, window):
    """Moving average over a time window (the per-step fluxes jitter)."""
    if len(t) < 2:
        return q
    n = max(1, int(round(window/np.median(np.diff(t)))))
    kernel = np.ones(n)
    # divided by the number of samples in the window: no dip at the ends
    return np.convolve(q, kernel, mode='same') \
        / np.convolve(np.ones_like(q), kernel, mode='same')
