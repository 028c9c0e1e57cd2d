# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
"""One run's analysis (damBreachAnalysis.py CASE): per dump the dam height
H, its rate (eq. 21), [E] (eq. 20) and its parts, grains left, forces, the
water discharges, lake depth and freeboard (CASE/damBreach.dat); the
longitudinal profiles (profiles.dat); the summary (damBreach.summary)
and the plots."""
import os
import sys

import numpy as np

from .dumps import (dump_files, energy, profile_edges, read_dump,
                    read_gravity, surface_profile)
from .figures import plot_case
from .water import lake_level, smooth, water_balance


def read_summary(case):
    """CASE/damBreach.summary: {quantity: value}."""
    s = {}
    for line in open(os.path.join(case, 'damBreach.summary')):
        k, v = line.rstrip().rsplit(None, 1)
        s[k.strip()] = float(v)
    return s


def max_displacement(dumps):
    first, last = read_dump(dumps[0][1]), read_dump(dumps[-1][1])
    pos0 = {int(row[0]): row[3:6] for row in first}
    d = [np.linalg.norm(row[3:6] - pos0[int(row[0])]) for row in last
         if int(row[0]) in pos0]
    return max(d) if d else 0.0


def dump_series(case, dumps, g, edges, centres):
    """Per dump with grains: the row [t, H, E, Ek, Erot, Ep, grains, mass,
    mean |F_n|, mean |F_t|, mean |F_f|, contacts] (an array), the profile
    (t, h(x)) and the x of the crest."""
    contacts = dict(dump_files(case, 'contacts'))
    rows, profiles, crest_x = [], [], []
    for t, path in dumps:
        p = read_dump(path)
        if p.size == 0:
            continue
        h = surface_profile(p, edges)
        ep, ek, er = energy(p, g)
        ff = np.mean(np.linalg.norm(p[:, 12:15], axis=1))
        fn = ft = 0.0
        nc = 0
        if t in contacts:
            c = read_dump(contacts[t])
            if c.size:
                fn = np.mean(np.linalg.norm(c[:, 0:3], axis=1))
                ft = np.mean(np.linalg.norm(c[:, 3:6], axis=1))
                nc = len(c)
        rows.append([t, h.max(), ep + ek + er, ek, er, ep, len(p),
                     np.sum(p[:, 2]), fn, ft, ff, nc])
        profiles.append((t, h))
        crest_x.append(centres[np.argmax(h)])
    return np.array(rows), profiles, crest_x


def freeboard_series(case, g, t, height, crest_x):
    """The lake depth at x = 2.975 m and the freeboard at the dump times
    (nan without the lakeLevel probes)."""
    # Freeboard: real-world elevation of the crest minus that of the lake
    # surface at x = 2.975 m (elevation = z cos(b) - x sin(b), b the slope
    # of the bed from the gravity vector); overtopping when it turns negative
    slope = np.arctan2(g[0], -g[2])
    lake = lake_level(case)
    if lake:
        depth = np.interp(t, lake[0], lake[1])
        freeboard = (height*np.cos(slope) - np.array(crest_x)*np.sin(slope)) \
            - (depth*np.cos(slope) - 2.975*np.sin(slope))
        freeboard[height <= 0] = np.nan          # no dam left: no crest
    else:
        depth = freeboard = np.full_like(t, np.nan)
    return depth, freeboard


def write_profiles(case, centres, profiles):
    """profiles.dat: the profiles at six times spread over the run; returns
    those six (t, h)."""
    pick = np.unique(np.linspace(0, len(profiles) - 1, 6).round().astype(int))
    ptab = np.column_stack([centres] + [profiles[i][1] for i in pick])
    np.savetxt(os.path.join(case, 'profiles.dat'), ptab, fmt='%.5g',
               header='x[m] ' + ' '.join('h(t=%gs)[m]' % profiles[i][0]
                                         for i in pick))
    return [profiles[i] for i in pick]


def last_tenth(t, end=None):
    """The rows of times t in the last 10 % of [t[0], end] (end: t's last
    time unless given): the window of the residual height and of the
    mean outflow, and of compare.equal_time's common time."""
    end = t[-1] if end is None else end
    return (t >= t[0] + 0.9*(end - t[0])) & (t <= end)


def summary_values(rows, rate, freeboard, wb, dumps):
    """The quantities of damBreach.summary, in its order."""
    t, height = rows[:, 0], rows[:, 1]
    e0 = rows[0, 2]
    tail = last_tenth(t)
    summary = {
        'end time [s]': t[-1],
        'initial dam height H0 [m]': height[0],
        'residual dam height (last 10 % of the run) [m]': height[tail].mean(),
        'height reduction [%]': 100*(1 - height[tail].mean()/height[0]),
        'peak lowering rate -dH/dt [m/s]': -np.nanmin(rate),
        'final [E]': rows[-1, 2]/e0,
        'grains at start': int(rows[0, 6]),
        'grains carried out of the flume': int(rows[0, 6] - rows[-1, 6]),
        'largest grain displacement [m]': max_displacement(dumps),
    }
    over = np.nonzero(freeboard < 0)[0]
    summary['overtopping from t [s] (-1: none)'] = t[over[0]] if len(over) else -1
    if len(over):
        summary['dam height at overtopping [m]'] = height[over[0]]
        summary['height lost after overtopping [m]'] = \
            height[over[0]] - height[tail].mean()
    if wb:
        summary.update({
            'water in [m3]': wb['vin'],
            'water out, outlet [m3]': wb['vout'],
            'water out, top [m3]': wb['vtop'],
            'storage change [m3]': wb['dstore'],
            'water balance error (in - out - storage)/in [%]': 100*wb['error'],
            'mean outflow, last 10 % [m3/s]':
                np.mean(wb['qout'][last_tenth(wb['t'])]),
        })
    return summary


def analyse(case):
    """One run: damBreach.dat, profiles.dat, damBreach.summary (printed
    too), damBreach.png and profiles.png in CASE."""
    g = read_gravity(case)
    dumps = dump_files(case, 'particles')
    if len(dumps) < 2:
        sys.exit('damBreachAnalysis: fewer than two dumps in %s/post '
                 '(particles.<step>.txt): did the run start?' % case)
    edges = profile_edges()
    centres = 0.5*(edges[1:] + edges[:-1])
    rows, profiles, crest_x = dump_series(case, dumps, g, edges, centres)
    t, height = rows[:, 0], rows[:, 1]
    e0 = rows[0, 2]
    rate = np.zeros_like(height)
    rate[:-1] = np.diff(height)/np.diff(t)          # eq. 21, forward
    rate[-1] = np.nan

    wb = water_balance(case)
    if wb:
        qin = np.interp(t, wb['t'], smooth(wb['t'], wb['qin'], 0.5))
        qout = np.interp(t, wb['t'], smooth(wb['t'], wb['qout'], 0.5))
    else:
        qin = qout = np.full_like(t, np.nan)
    depth, freeboard = freeboard_series(case, g, t, height, crest_x)

    table = np.column_stack([t, height, rate, rows[:, 2]/e0, rows[:, 3],
                             rows[:, 4], rows[:, 5], rows[:, 6], rows[:, 7],
                             rows[:, 8], rows[:, 9], rows[:, 10], rows[:, 11],
                             qin, qout, depth, freeboard])
    np.savetxt(os.path.join(case, 'damBreach.dat'), table, fmt='%.6g',
               header='t[s] H[m] eq21_rate[m/s] E/E0 Ek[J] Erot[J] Ep[J] '
                      'grains mass[kg] Fn_mean[N] Ft_mean[N] Ff_mean[N] '
                      'contacts Qin[m3/s] Qout[m3/s] lake_depth[m] '
                      'freeboard[m]')
    picked = write_profiles(case, centres, profiles)

    summary = summary_values(rows, rate, freeboard, wb, dumps)
    with open(os.path.join(case, 'damBreach.summary'), 'w') as f:
        for k, v in summary.items():
            f.write('%-52s %.6g\n' % (k, v))
    for k, v in summary.items():
        print('%-52s %.6g' % (k, v))

    plot_case(case, table, centres, picked, wb)
