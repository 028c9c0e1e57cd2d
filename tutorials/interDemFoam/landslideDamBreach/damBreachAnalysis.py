#!/usr/bin/python3
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
"""Landslide dam breach: the seed's analysis (Figs. 6-11) from one run.

    damBreachAnalysis.py CASE                 one run: tables and plots in CASE
    damBreachAnalysis.py compare OUT CASE...  several runs side by side
    damBreachAnalysis.py grading BUILD [--out FILE] [--grains FILE]
                                              the grading of a poured dam
    damBreachAnalysis.py ended CASE [--window 20] [--tolerance 0.005]
                               [--energyTolerance 0.02] [--maxTime 200]
                                              exit 0 when the run should stop:
                                              the breach has ended (H and [E]
                                              level over the window) or the
                                              run has reached maxTime
    damBreachAnalysis.py matrix DIR SCALE CASE...
                                              all eight scenarios: the matrix,
                                              the findings, Figs. 8-11
    damBreachAnalysis.py coarseness DIR SCALE CASE...
                                              the variants' chart
    damBreachAnalysis.py shields DIR SCALE CASE...
                                              the Shields number on the
                                              downstream face during
                                              overtopping (damBreachShields.py)
    damBreachAnalysis.py deposit CASE... [--every 20]
                                              where the grains are: in the
                                              flume, on the bed downstream
                                              of the poured dam's toe (the
                                              deposit) and how many of those
                                              move, every 20 s

Reads the DEM dumps CASE/post/particles.<step>.txt and contacts.<step>.txt
(DEM/in.dam writes them; step x demDt is the time, demDt the DEM step of
CASE/DEM/in.case, which Allrun writes: 1e-4 s for C, 5e-5 s for F, 2.5e-5 s
for F at full scale) and the water function objects in CASE/postProcessing.
Writes, in CASE:

  damBreach.dat      per dump: t, dam height H (eq. 21's H), its rate
                     (H(t+1) - H(t))/dt (eq. 21), dimensionless total energy
                     [E] (eq. 20) and its parts, grains left, mean normal and
                     tangential contact force, mean particle-fluid force, and
                     the water discharges in and out
  profiles.dat       longitudinal profiles (surface of the resting grains)
                     at chosen times: x, then one column per time
  damBreach.summary  initial and residual height, peak rate, final [E],
                     grains carried out, water balance closure
  damBreach.png, profiles.png

Definitions (the seed leaves them open; these are ours):
  surface h(x)  the top (z + r) of the highest grain at rest (|v| < 0.05 m/s)
                in each 50 mm bin along the flume, z normal to the bed;
                grains in transport are not the dam
  dam height H  max over x of h(x)
  [E]           (sum m g.h + 1/2 sum m v^2 + 1/2 sum I w^2)/E(t=0), heights
                measured upwards (against g) from the bed at the outlet, so
                every term is positive; I = 2/5 m r^2; grains carried out of
                the flume take their energy with them
  contact force mean |F_n| and |F_t| over the grain-grain contacts
  fluid force   mean |F_f| over the grains (drag + pressure gradient)
  water balance V(t_end) - V(t_1) against the integral of (Q_in - Q_out -
                Q_top) dt, relative to the water that came in

grading: the dam a build poured (BUILD/dam.grains, the dump DEM/in.buildDam
writes, or --grains) against its grading (BUILD/DEM/in.material.<material>:
the diameters of the particle templates and the mass-based weights of fix
pdd; material, demDt and width from BUILD/DEM/in.case). Prints and writes
(--out; the rows of the other materials in FILE are kept) per size class:
material, d [m], target and measured mass fraction, count; then the solid
fraction (grain volume over the trapezoid's volume, and in the core of the
dam) and the DEM step against the Rayleigh time of the smallest grain.
Exits 1 when a class misses its target mass fraction by more than
GRADING_TOLERANCE (3 points), a grain matches no class, or the DEM step
exceeds 20 % of the Rayleigh time.
"""
import glob
import os
import re
import sys

import numpy as np

GRADING_TOLERANCE = 0.03   # largest |measured - target| mass fraction
RAYLEIGH_LIMIT = 0.2       # largest DEM step / Rayleigh time of the smallest
REST_SPEED = 0.05      # m/s: a grain slower than this is part of the bed
BIN = 0.05             # m: profile bins (the CFD cell size)
FLUME_LENGTH = 7.0
LEVEL_ENERGY = 0.02    # [E] changed by less than this over 20 s: levelled off
                       # (P9; the run-length rule of ended)
ENDED_WINDOW = 20.0    # s: the run-length rule's window (Allrun, the matrix)
ENDED_HEIGHT = 0.005   # m: the dam height changed by less than this over it


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


def analyse(case):
    g = read_gravity(case)
    dumps = dump_files(case, 'particles')
    if len(dumps) < 2:
        sys.exit('damBreachAnalysis: fewer than two dumps in %s/post '
                 '(particles.<step>.txt): did the run start?' % case)
    contacts = dict(dump_files(case, 'contacts'))
    edges = np.arange(0.0, FLUME_LENGTH + BIN/2, BIN)
    centres = 0.5*(edges[1:] + edges[:-1])

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
    rows = np.array(rows)
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

    table = np.column_stack([t, height, rate, rows[:, 2]/e0, rows[:, 3],
                             rows[:, 4], rows[:, 5], rows[:, 6], rows[:, 7],
                             rows[:, 8], rows[:, 9], rows[:, 10], rows[:, 11],
                             qin, qout, depth, freeboard])
    np.savetxt(os.path.join(case, 'damBreach.dat'), table, fmt='%.6g',
               header='t[s] H[m] eq21_rate[m/s] E/E0 Ek[J] Erot[J] Ep[J] '
                      'grains mass[kg] Fn_mean[N] Ft_mean[N] Ff_mean[N] '
                      'contacts Qin[m3/s] Qout[m3/s] lake_depth[m] '
                      'freeboard[m]')

    # Profiles at six times spread over the run
    pick = np.unique(np.linspace(0, len(profiles) - 1, 6).round().astype(int))
    ptab = np.column_stack([centres] + [profiles[i][1] for i in pick])
    np.savetxt(os.path.join(case, 'profiles.dat'), ptab, fmt='%.5g',
               header='x[m] ' + ' '.join('h(t=%gs)[m]' % profiles[i][0]
                                         for i in pick))

    tail = t >= t[0] + 0.9*(t[-1] - t[0])
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
            'mean outflow, last 10 % [m3/s]': np.mean(
                wb['qout'][wb['t'] >= wb['t'][0] + 0.9*(wb['t'][-1] - wb['t'][0])]),
        })
    with open(os.path.join(case, 'damBreach.summary'), 'w') as f:
        for k, v in summary.items():
            f.write('%-52s %.6g\n' % (k, v))
    for k, v in summary.items():
        print('%-52s %.6g' % (k, v))

    plot_case(case, table, centres, [profiles[i] for i in pick], wb)


def height_at(case, times, span=2.0):
    """The dam height H averaged over the dumps in [t - span, t] for each
    t of times (one grain more or less on the crest moves H by its
    diameter; the mean over a few dumps is the dam's height)."""
    dumps = dump_files(case, 'particles')
    edges = np.arange(0.0, FLUME_LENGTH + BIN/2, BIN)
    out = []
    def height(path):
        p = read_dump(path)
        return surface_profile(p, edges).max() if p.size else 0.0   # no grain
    for t in times:
        hs = [height(f) for td, f in dumps if t - span - 1e-9 <= td <= t + 1e-9]
        out.append(np.mean(hs) if hs else np.nan)
    return out


def height_change(case, window):
    """The dam height (height_at) at the last dump's time t_end and at
    t_end - window: (h_before, h_end, t_end); None when the run is shorter
    than the window (plus 2 s)."""
    dumps = dump_files(case, 'particles')
    if not dumps:
        sys.exit('damBreachAnalysis: no dumps in %s/post' % case)
    t_end = dumps[-1][0]
    if t_end < window + 2.0:
        return None
    h_before, h_end = height_at(case, [t_end - window, t_end])
    return h_before, h_end, t_end


def energy_change(case, window):
    """[E] (E/E(0), the dumps' total energy as in analyse) at the dump
    nearest t_end - window and at the last dump t_end: (E_before, E_end);
    None when the run is shorter than the window (plus 2 s)."""
    dumps = dump_files(case, 'particles')
    t_end = dumps[-1][0]
    if t_end < window + 2.0:
        return None
    g = read_gravity(case)
    times = np.array([t for t, f in dumps])
    before = dumps[int(np.argmin(np.abs(times - (t_end - window))))][1]
    e = []
    for path in (dumps[0][1], before, dumps[-1][1]):
        p = read_dump(path)
        e.append(sum(energy(p, g)) if p.size else 0.0)
    if not e[0] > 0:
        sys.exit('damBreachAnalysis: no energy in the first dump of %s/post'
                 % case)
    return e[1]/e[0], e[2]/e[0]


def emptied(case):
    """The first <time>/liggghts.restart.emptied of the case (serial or
    processor0), or None: when every grain has gone the solver writes it
    instead of a DEM state, and nothing is left to erode."""
    def time_of(path):
        try:
            return float(os.path.basename(os.path.dirname(path)))
        except ValueError:
            return float('inf')
    found = sorted(glob.glob(os.path.join(case, '[0-9]*',
                                          'liggghts.restart.emptied'))
                   + glob.glob(os.path.join(case, 'processor0', '[0-9]*',
                                            'liggghts.restart.emptied')),
                   key=time_of)
    return found[0] if found else None


def breach_state(case, window=ENDED_WINDOW, tolerance=ENDED_HEIGHT,
                 energy_tolerance=LEVEL_ENERGY):
    """The run-length rule, one place for Allrun (ended) and the matrix:
    a dict with 'gone' (emptied's file or None), 'short' (the run is shorter
    than the window), the heights 'h' and [E]s 'e' (before, end; nan when
    the run is short), the last dump's time 't_end', and 'done': every
    grain has left, or over the last window seconds the dam height changed
    by less than tolerance and [E] by less than energy_tolerance (the
    breach has ended: the dam neither lowers nor loses grains)."""
    dumps = dump_files(case, 'particles')
    if not dumps:
        sys.exit('damBreachAnalysis: no dumps in %s/post' % case)
    nan = float('nan')
    state = {'gone': emptied(case), 'short': False, 'h': (nan, nan),
             'e': (nan, nan), 't_end': dumps[-1][0], 'done': False}
    change_of = height_change(case, window)
    if change_of is None:
        state['short'] = True
    else:
        state['h'] = change_of[:2]
        state['e'] = energy_change(case, window)
    state['height_change'] = abs(state['h'][1] - state['h'][0])
    state['energy_change'] = abs(state['e'][1] - state['e'][0])
    level = state['height_change'] < tolerance and state['energy_change'] < energy_tolerance
    state['done'] = state['gone'] is not None or (not state['short'] and level)
    return state


def ended(case, window, tolerance, max_time, energy_tolerance):
    """True when the run should stop: breach_state's rule (every grain
    has left, or over the last window seconds the dam height changed by
    less than tolerance and [E] by less than energy_tolerance), or the run
    has reached max_time (the longest run of its scale; said so)."""
    state = breach_state(case, window, tolerance, energy_tolerance)
    if state['gone']:
        print('%s: every grain has left the flume (%s): the breach has ended'
              % (case, os.path.relpath(state['gone'], case)))
        return True
    done = state['done']
    if state['short']:
        print('%s: %.1f s run, shorter than the %g s window: not ended'
              % (case, state['t_end'], window))
    else:
        (h_before, h_end), (e_before, e_end) = state['h'], state['e']
        change, e_change = state['height_change'], state['energy_change']
        print('%s: dam height %.4f m at %.1f s, %.4f m at %.1f s: change '
              '%.1f mm %s %.1f mm; [E] %.3f -> %.3f: change %.3f %s %.3f: %s'
              % (case, h_before, state['t_end'] - window, h_end,
                 state['t_end'], 1000*change,
                 '<' if change < tolerance else '>=', 1000*tolerance,
                 e_before, e_end, e_change,
                 '<' if e_change < energy_tolerance else '>=',
                 energy_tolerance,
                 'the breach has ended' if done else 'still changing'))
    if not done and state['t_end'] >= max_time - 1e-6:
        print('%s: NOT ENDED: the run has reached %g s, the longest run of '
              'its scale (Allrun -maxTime); stopped and analysed as it is'
              % (case, max_time))
        return True
    return done


def max_displacement(dumps):
    first, last = read_dump(dumps[0][1]), read_dump(dumps[-1][1])
    pos0 = {int(row[0]): row[3:6] for row in first}
    d = [np.linalg.norm(row[3:6] - pos0[int(row[0])]) for row in last
         if int(row[0]) in pos0]
    return max(d) if d else 0.0


def plot_case(case, table, centres, profiles, wb):
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt

    name = os.path.basename(os.path.abspath(case))
    t = table[:, 0]
    fig, ax = plt.subplots(2, 3, figsize=(15, 8))
    ax[0, 0].plot(t, table[:, 1]*1000, 'k-', label='dam height H')
    if not np.all(np.isnan(table[:, 16])):
        ax[0, 0].plot(t, (table[:, 1] - table[:, 16])*1000, 'b--',
                      label='lake level at the crest')
        ax[0, 0].legend(fontsize=8)
    ax[0, 0].set(xlabel='t [s]', ylabel='dam height H [mm]',
                 title='Dam height (seed Fig. 10)')
    ax[0, 1].plot(t, table[:, 2]*1000, 'b-')
    ax[0, 1].axhline(0, color='grey', lw=0.5)
    ax[0, 1].set(xlabel='t [s]', ylabel='(H(t+1) - H(t))/dt [mm/s]',
                 title='Height change rate, eq. 21 (Fig. 11)')
    ax[0, 2].plot(t, table[:, 3], 'r-')
    ax[0, 2].set(xlabel='t [s]', ylabel='[E] = E/E(0)',
                 title='Dimensionless total energy, eq. 20 (Fig. 8)')
    ax[1, 0].plot(t, table[:, 9], label='normal contact |F_n|')
    ax[1, 0].plot(t, table[:, 10], label='tangential contact |F_t|')
    ax[1, 0].plot(t, table[:, 11], label='particle-fluid |F_f|')
    ax[1, 0].set(xlabel='t [s]', ylabel='mean force [N]',
                 title='Forces (seed Fig. 7)')
    ax[1, 0].legend(fontsize=8)
    for tp, h in profiles:
        ax[1, 1].plot(centres, h*1000, label='t = %g s' % tp)
    ax[1, 1].set(xlim=(2.5, 7), xlabel='x along the bed [m]',
                 ylabel='surface of resting grains [mm]',
                 title='Longitudinal profiles (seed Fig. 9)')
    ax[1, 1].legend(fontsize=8)
    if wb:
        ax[1, 2].plot(wb['t'], smooth(wb['t'], wb['qin'], 0.5)*1000,
                      label='inflow')
        ax[1, 2].plot(wb['t'], smooth(wb['t'], wb['qout'], 0.5)*1000,
                      label='outflow (outlet)')
        ax[1, 2].legend(fontsize=8)
    ax[1, 2].set(xlabel='t [s]', ylabel='discharge [l/s] (0.5 s mean)',
                 title='Water discharge')
    fig.suptitle('Landslide dam breach, %s' % name)
    fig.tight_layout()
    fig.savefig(os.path.join(case, 'damBreach.png'), dpi=110)

    fig, axp = plt.subplots(figsize=(9, 4))
    for tp, h in profiles:
        axp.plot(centres, h*1000, label='t = %g s' % tp)
    axp.set(xlim=(2.5, 7), xlabel='x along the bed [m]',
            ylabel='surface of resting grains, normal to the bed [mm]',
            title='Breach morphology, %s (seed Fig. 9)' % name)
    axp.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(case, 'profiles.png'), dpi=110)


# The dam (DEM/in.buildDam): upstream toe at x = 3 m, height and crest width
# 0.3 m, slopes 35 and 25 degrees to the bed
DAM_TOE, DAM_HEIGHT, DAM_CREST = 3.0, 0.3, 0.3
DAM_SLOPES = (35.0, 25.0)
# the core of the dam, where the solid fraction is sampled: 0.3 m along the
# bed under the crest, 0.04-0.24 m above the bed (away from every surface)
CORE_X, CORE_Z = (3.45, 3.75), (0.04, 0.24)


def dam_area():
    """The dam's cross-section, m2."""
    up, down = (DAM_HEIGHT/np.tan(np.radians(a)) for a in DAM_SLOPES)
    return DAM_HEIGHT*(DAM_CREST + 0.5*(up + down))


def dam_downstream_toe():
    """x of the poured dam's downstream toe, m."""
    up, down = (DAM_HEIGHT/np.tan(np.radians(a)) for a in DAM_SLOPES)
    return DAM_TOE + up + DAM_CREST + down


def deposit(cases, every):
    """Per case, every `every` seconds of its dumps (and its last): grains
    in the flume, grains downstream of the poured dam's toe, and of those
    the ones moving (faster than REST_SPEED): is the deposit at rest or
    being carried out of the flume?"""
    toe = dam_downstream_toe()
    print('# x > %.3f m: downstream of the poured dam; moving: faster than '
          '%g m/s' % (toe, REST_SPEED))
    print('%-22s %7s %8s %11s %8s %10s' % ('case', 't [s]', 'flume',
          'downstream', 'moving', 'dam moving'))
    for case in cases:
        dumps = dump_files(case, 'particles')
        for i, (t, f) in enumerate(dumps):
            last = i == len(dumps) - 1
            if not last and abs(t/every - round(t/every)) > 1e-6:
                continue
            p = read_dump(f)
            if p.size == 0:
                print('%-22s %7.1f %8d %11d %8d %10d' % (case, t, 0, 0, 0, 0))
                continue
            down = p[:, 3] > toe
            moving = np.linalg.norm(p[:, 6:9], axis=1) > REST_SPEED
            print('%-22s %7.1f %8d %11d %8d %10d'
                  % (case, t, len(p), down.sum(), (down & moving).sum(),
                     (~down & moving).sum()))


def liggghts_lines(path):
    """The commands of a LIGGGHTS input file, comments and continuations
    (&) joined, as lists of words."""
    text = open(path).read().replace('&\n', ' ')
    return [l.split('#')[0].split() for l in text.splitlines()
            if l.split('#')[0].strip()]


def read_grading(path):
    """Diameters (m), target mass fractions and densities of the size classes
    of an in.material file: the particle templates and the weights of its
    fix particledistribution/discrete (mass-based unless /numberbased)."""
    templates, dist = {}, None
    for w in liggghts_lines(path):
        if len(w) > 3 and w[0] == 'fix' and w[3] == 'particletemplate/sphere':
            d = dict(zip(w[4:], w[5:]))
            i = w.index('radius')
            if w[i + 1] != 'constant' or w[w.index('density') + 1] != 'constant':
                sys.exit('damBreachAnalysis: %s: template %s: only constant '
                         'radius and density are checked' % (path, w[1]))
            templates[w[1]] = (2*float(w[i + 2]),
                               float(w[w.index('density') + 2]))
        elif len(w) > 3 and w[0] == 'fix' \
                and w[3].startswith('particledistribution/discrete'):
            n = int(w[5])
            dist = (w[3], [(w[6 + 2*k], float(w[7 + 2*k])) for k in range(n)])
    if dist is None or not templates:
        sys.exit('damBreachAnalysis: no particle templates or fix '
                 'particledistribution/discrete in %s' % path)
    style, pairs = dist
    d = np.array([templates[t][0] for t, _ in pairs])
    rho = np.array([templates[t][1] for t, _ in pairs])
    weight = np.array([wt for _, wt in pairs])
    if style.endswith('/numberbased'):
        weight = weight*rho*d**3
    return d, weight/weight.sum(), rho


def read_grains(path):
    """The grains of a LIGGGHTS custom dump: dict of columns."""
    lines = open(path).read().splitlines()
    i = next((k for k, l in enumerate(lines) if l.startswith('ITEM: ATOMS')),
             None)
    if i is None:
        sys.exit('damBreachAnalysis: %s is not a LIGGGHTS dump' % path)
    names = lines[i].split()[2:]
    rows = [l.split() for l in lines[i + 1:] if l.strip()]
    a = np.array(rows, dtype=float).reshape(-1, len(names))
    return {n: a[:, k] for k, n in enumerate(names)}


def core_solid_fraction(g, width, periodic, h=0.002):
    """Fraction of the core box (CORE_X x width x CORE_Z) inside grains,
    sampled on a grid of spacing h (periodic images across y)."""
    xs = np.arange(CORE_X[0] + h/2, CORE_X[1], h)
    ys = np.arange(h/2, width, h)
    zs = np.arange(CORE_Z[0] + h/2, CORE_Z[1], h)
    occ = np.zeros((len(xs), len(ys), len(zs)), bool)
    shifts = (-width, 0.0, width) if periodic else (0.0,)
    for r, x, y, z in zip(g['radius'], g['x'], g['y'], g['z']):
        if x + r < CORE_X[0] or x - r > CORE_X[1] \
                or z + r < CORE_Z[0] or z - r > CORE_Z[1]:
            continue
        i0, i1 = np.searchsorted(xs, [x - r, x + r])
        k0, k1 = np.searchsorted(zs, [z - r, z + r])
        for s in shifts:
            j0, j1 = np.searchsorted(ys, [y + s - r, y + s + r])
            if j1 <= j0:
                continue
            d2 = (xs[i0:i1, None, None] - x)**2 \
                + (ys[None, j0:j1, None] - y - s)**2 \
                + (zs[None, None, k0:k1] - z)**2
            occ[i0:i1, j0:j1, k0:k1] |= d2 < r*r
    return occ.mean()


def rayleigh_time(build, r, rho):
    """T_R = pi r sqrt(rho/G)/(0.1631 nu + 0.8766) with the particles' E and
    nu of DEM/in.common (as interDemFoam checks it), s."""
    E = nu = None
    for w in liggghts_lines(os.path.join(build, 'DEM', 'in.common')):
        if len(w) > 5 and w[0] == 'fix' and w[3] == 'property/global':
            if w[4] == 'youngsModulus':
                E = float(w[6])
            elif w[4] == 'poissonsRatio':
                nu = float(w[6])
    if E is None or nu is None:
        sys.exit('damBreachAnalysis: no youngsModulus/poissonsRatio in '
                 '%s/DEM/in.common' % build)
    G = E/(2*(1 + nu))
    return np.pi*r*np.sqrt(rho/G)/(0.1631*nu + 0.8766)


def grading(build, out=None, grains=None, scale=None):
    """Check the grading of the dam poured in BUILD; True when it passes."""
    v = case_variables(build)
    material = v.get('material')
    if not material:
        sys.exit('damBreachAnalysis: no material in %s/DEM/in.case' % build)
    dt = dem_step(build)
    width = float(v['width'])
    periodic = v.get('yBoundary', 'p') == 'p'
    d, target, rho = read_grading(
        os.path.join(build, 'DEM', 'in.material.' + material))
    g = read_grains(grains or os.path.join(build, 'dam.grains'))
    n = len(g['radius'])
    if n == 0:
        sys.exit('damBreachAnalysis: no grains in the dam of %s' % build)
    # each grain to its class: the template diameter it has (to 1e-6)
    dg = 2*g['radius']
    k = np.argmin(np.abs(dg[:, None] - d[None, :]), axis=1)
    stray = np.abs(dg - d[k]) > 1e-6*d[k]
    mass = g['mass']
    count = np.bincount(k[~stray], minlength=len(d))
    measured = np.bincount(k[~stray], weights=mass[~stray],
                           minlength=len(d))/mass.sum()
    volume = np.sum(4/3*np.pi*g['radius']**3)
    bulk = volume/(dam_area()*width)
    core = core_solid_fraction(g, width, periodic)
    i = np.argmin(d)
    tR = rayleigh_time(build, d[i]/2, rho[i])
    times = {}
    for w in liggghts_lines(os.path.join(build, 'DEM', 'in.buildDam')):
        if len(w) >= 4 and w[0] == 'variable' and w[1].endswith('Time'):
            times[w[1]] = w[3]

    rows = ['%-6s %.4f %.4f %.4f %d' % (material, d[c], target[c],
                                        measured[c], count[c])
            for c in range(len(d))]
    summary = ('# %s: %d grains, %.2f kg; solid fraction %.3f (grain volume '
               '/ trapezoid %.4f m3), %.3f (core); DEM step %g s = %.1f %% of '
               'the Rayleigh time %.3g s of the %g mm grains; pour %s s, '
               'settle %s + %s s'
               % (material, n, mass.sum(), bulk, dam_area()*width, core, dt,
                  100*dt/tR, tR, 1000*d[i], times.get('pourTime', '?'),
                  times.get('settleTime', '?'), times.get('restTime', '?')))
    print('Grading of the dam, material %s (%s):' % (material, build))
    print('  %-6s %-7s %-7s %-8s %s' % ('', 'd [mm]', 'target', 'measured',
                                        'count'))
    for c in range(len(d)):
        print('  %-6s %-7g %-7.3f %-8.3f %d' % (material, 1000*d[c],
                                                target[c], measured[c],
                                                count[c]))
    print(summary[2:])

    problems = []
    for c in range(len(d)):
        if abs(measured[c] - target[c]) > GRADING_TOLERANCE + 1e-12:
            problems.append('d = %g mm: %.3f of the mass, target %.3f '
                            '(+-%g allowed), %d grains'
                            % (1000*d[c], measured[c], target[c],
                               GRADING_TOLERANCE, count[c]))
    if stray.any():
        problems.append('%d grains of diameters %s mm match no class'
                        % (stray.sum(), ', '.join('%g' % (1000*x) for x in
                                                   sorted(set(dg[stray])))))
    if dt > RAYLEIGH_LIMIT*tR:
        problems.append('DEM step %g s is %.1f %% of the Rayleigh time %.3g s '
                        'of the %g mm grains (at most %g %%)'
                        % (dt, 100*dt/tR, tR, 1000*d[i], 100*RAYLEIGH_LIMIT))

    if out:
        # the other materials' summaries ('# X: ...') and rows ('X d ...')
        other = {}
        if os.path.isfile(out):
            for line in open(out).read().splitlines():
                w = line.split()
                if len(w) > 1 and w[0] == '#' and w[1].endswith(':'):
                    m = w[1][:-1]
                elif w and w[0] != '#' and not w[0].startswith('#'):
                    m = w[0]
                else:
                    continue
                if m != material:
                    other.setdefault(m, []).append(line)
        other[material] = [summary] + rows
        with open(out, 'w') as f:
            f.write('# The grading of the poured dams%s (written by '
                    'damBreachAnalysis.py grading after each build)\n'
                    % (', %s scale' % scale if scale else ''))
            f.write('# targets from DEM/in.material.<material>; a class passes '
                    'within +-%g of its mass fraction\n' % GRADING_TOLERANCE)
            f.write('# material d_m target_mass_fraction '
                    'measured_mass_fraction count\n')
            for m in sorted(other):
                f.write('\n'.join(other[m]) + '\n')
        print('Grading written to %s' % out)
    if problems:
        print('GRADING CHECK FAILED: the dam of material %s is not its '
              'grading:\n  %s' % (material, '\n  '.join(problems)))
        return False
    print('Grading check passed: every class within %g of its target mass '
          'fraction' % GRADING_TOLERANCE)
    return True


def compare(out, cases):
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(1, 3, figsize=(15, 4.5))
    lines = []
    for case in cases:
        d = np.loadtxt(os.path.join(case, 'damBreach.dat'))
        name = os.path.basename(os.path.abspath(case))
        ax[0].plot(d[:, 0], d[:, 1]*1000, label=name)
        ax[1].plot(d[:, 0], d[:, 3], label=name)
        ax[2].plot(d[:, 0], d[:, 14]*1000, label=name)
        s = {k.strip(): float(v) for k, v in
             (l.rstrip().rsplit(None, 1) for l in
              open(os.path.join(case, 'damBreach.summary')))}
        lines.append('%-12s residual H %.4f m (H0 %.4f m, -%.1f %%), final '
                     '[E] %.3f, grains out %d, water balance %.3f %%'
                     % (name, s['residual dam height (last 10 % of the run) [m]'],
                        s['initial dam height H0 [m]'],
                        s['height reduction [%]'], s['final [E]'],
                        s['grains carried out of the flume'],
                        s.get('water balance error (in - out - storage)/in [%]',
                              float('nan'))))
    ax[0].set(xlabel='t [s]', ylabel='dam height H [mm]',
              title='Dam height (seed Fig. 10)')
    ax[1].set(xlabel='t [s]', ylabel='[E]', title='Total energy, eq. 20 (Fig. 8)')
    ax[2].set(xlabel='t [s]', ylabel='outflow [l/s]', title='Outflow discharge')
    for a in ax:
        a.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out + '.png', dpi=110)
    with open(out + '.txt', 'w') as f:
        f.write('\n'.join(lines) + '\n')
    print('\n'.join(lines))


if __name__ == '__main__':
    if len(sys.argv) >= 3 and sys.argv[1] == 'grading':
        import argparse
        ap = argparse.ArgumentParser(prog='damBreachAnalysis.py grading')
        ap.add_argument('build')
        ap.add_argument('--out')
        ap.add_argument('--grains')
        ap.add_argument('--scale')
        a = ap.parse_args(sys.argv[2:])
        sys.exit(0 if grading(a.build, a.out, a.grains, a.scale) else 1)
    elif len(sys.argv) >= 3 and sys.argv[1] == 'ended':
        import argparse
        ap = argparse.ArgumentParser(prog='damBreachAnalysis.py ended')
        ap.add_argument('case')
        ap.add_argument('--window', type=float, default=ENDED_WINDOW)
        ap.add_argument('--tolerance', type=float, default=ENDED_HEIGHT)
        ap.add_argument('--energyTolerance', type=float,
                        default=LEVEL_ENERGY)
        ap.add_argument('--maxTime', type=float, default=200.0)
        a = ap.parse_args(sys.argv[2:])
        sys.exit(0 if ended(a.case, a.window, a.tolerance, a.maxTime,
                            a.energyTolerance) else 1)
    elif len(sys.argv) >= 5 and sys.argv[1] == 'matrix':
        import damBreachMatrix
        sys.exit(damBreachMatrix.main(sys.argv[2], sys.argv[3], sys.argv[4:]))
    elif len(sys.argv) >= 5 and sys.argv[1] == 'coarseness':
        import damBreachMatrix
        sys.exit(damBreachMatrix.coarseness(sys.argv[2], sys.argv[3],
                                            sys.argv[4:]))
    elif len(sys.argv) >= 5 and sys.argv[1] == 'shields':
        import damBreachShields
        sys.exit(damBreachShields.main(sys.argv[2], sys.argv[3],
                                       sys.argv[4:]))
    elif len(sys.argv) >= 3 and sys.argv[1] == 'deposit':
        import argparse
        ap = argparse.ArgumentParser(prog='damBreachAnalysis.py deposit')
        ap.add_argument('cases', nargs='+')
        ap.add_argument('--every', type=float, default=20.0)
        a = ap.parse_args(sys.argv[2:])
        deposit(a.cases, a.every)
    elif len(sys.argv) >= 4 and sys.argv[1] == 'compare':
        compare(sys.argv[2], sys.argv[3:])
    elif len(sys.argv) == 2:
        analyse(sys.argv[1])
    else:
        sys.exit(__doc__)
