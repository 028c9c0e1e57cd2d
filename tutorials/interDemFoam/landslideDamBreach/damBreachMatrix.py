#!/usr/bin/python3
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
"""Landslide dam breach: the eight scenarios together (seed Table 2).

    damBreachAnalysis.py matrix DIR SCALE CASE...

run by `Allrun -scenario all` after every case has its damBreach.dat and
damBreach.summary (damBreachAnalysis.py CASE). Writes, in DIR:

  matrix.<scale>.dat    one row per scenario: scenario, inflow (Table 2,
                        full 0.5 m flume; the small slice carries 1/5 of it),
                        material, H0, residual H, overtopping time (-1:
                        none), final [E], grains carried out of the flume,
                        wall time of the run
  phases.<scale>.dat    per scenario the start of each phase (P4)
  findings.<scale>.txt  the seed's findings P1-P12, each with the measured
                        evidence and "holds" / "does not hold" (with
                        runs missing: "holds on the runs present", and the
                        count says 0 of 12)
  fig8.<scale>.png      [E](t), all eight (seed Fig. 8)
  fig9.<scale>.png      longitudinal profiles, a grid A-H (seed Fig. 9)
  fig10.<scale>.png     dam height H(t), all eight (seed Fig. 10)
  fig11.<scale>.png     height-change rate, eq. 21 (seed Fig. 11)

The measures (ours where the seed gives only words):
  H(t)         damBreach.dat's H, smoothed over 2 s (one grain more or less
               on the crest moves H by its diameter)
  residual H   damBreach.summary's mean over the last 10 % of the run
  overtopping  damBreach.summary's (freeboard at x = 2.975 m below zero)
  seepage at the toe  first time alpha.water > 0.5 in the bed cell just
               downstream of the dam's toe (probes toeWater)
  phases       toe erosion: the surface over the last 0.25 m above the
               initial toe half a median grain diameter lower than at t = 0
               (seepage or overflow); backward erosion: the downstream slope
               (between 25 % and 75 % of H) 3 degrees flatter than at t = 0;
               head-cut: after overtopping, H 10 % of H0 below its height at
               overtopping; rebalance: H stays within 5 mm of the residual
               height from then on; complete failure: residual height under
               10 % of H0. The first two phases last from toe erosion to
               head-cut (P6)
  surface layer  grains whose top lies within one largest diameter below the
               local surface h(x), on the downstream half of the dam (from
               the crest to the toe of the resting grains)
"""
import glob
import os
import sys

import numpy as np

import damBreachAnalysis as dba

SCENARIOS = ['C1', 'C2', 'C3', 'C4', 'F1', 'F2', 'F3', 'F4']
INFLOW = {'1': 0.005, '2': 0.01, '3': 0.015, '4': 0.02}   # Table 2, m3/s
CREST = (3.428, 3.729)     # the initial crest, x along the bed [m]
TOE = 4.372                # the initial downstream toe [m]
SMOOTH = 2.0               # s: H averaged over this window
BACKWARD_DEG = 3.0         # downstream slope flatter by this: backward erosion
HEADCUT = 0.10             # H below its overtopping value by this x H0
REBALANCE = 0.005          # m: H within this of the residual height
FAILED = 0.10              # residual height under this x H0: complete failure


def summary(case):
    s = {}
    for line in open(os.path.join(case, 'damBreach.summary')):
        k, v = line.rstrip().rsplit(None, 1)
        s[k.strip()] = float(v)
    return s


def cpu_time(case):
    """CPU time of the run: the last ExecutionTime of each solver log
    (log.interDemFoam and its continuations), summed; LIGGGHTS runs in the
    solver's process, so this is the whole coupled run on one core."""
    total, found = 0.0, False
    for log in glob.glob(os.path.join(case, 'log.interDemFoam*')):
        last = None
        for line in open(log, errors='replace'):
            if line.startswith('ExecutionTime'):
                last = line
        if last:
            total += float(last.split()[2])
            found = True
    return total if found else np.nan


def smooth_series(t, y, window=SMOOTH):
    out = np.empty_like(y)
    for i, ti in enumerate(t):
        sel = (t >= ti - window/2) & (t <= ti + window/2)
        out[i] = np.nanmean(y[sel])
    return out


def toe_seepage(case):
    """First time the toe cell holds water (alpha > 0.5), or None."""
    rows = {t: v[0] for t, v in dba.read_probes(case, 'toeWater').items()}
    if not rows:
        return None, False
    t = np.array(sorted(rows))
    a = np.array([rows[k] for k in t])
    wet = np.nonzero(a > 0.5)[0]
    return (t[wet[0]] if len(wet) else None), True


def slope_angle(centres, h, height):
    """Downstream slope [deg] of a profile between 75 % and 25 % of its
    height, going downstream from the crest; nan when not found."""
    if height <= 0:
        return np.nan
    i0 = int(np.argmax(h))
    x75 = x25 = None
    for i in range(i0, len(h)):
        if x75 is None and h[i] < 0.75*height:
            x75 = centres[i]
        if h[i] < 0.25*height:
            x25 = centres[i]
            break
    if x75 is None or x25 is None or x25 <= x75:
        return np.nan
    return np.degrees(np.arctan(0.5*height/(x25 - x75)))


def shape_factor(h):
    """Area of a profile over half its height times its base (where it
    stands higher than 5 % of its height): 1 for a triangle, 1.22 for the
    initial trapezoid (0.3 m high, 0.3 m crest, 1.37 m base), more for a
    plateau."""
    height = h.max()
    if height <= 0:
        return np.nan
    base = np.sum(h > 0.05*height)*dba.BIN
    return np.sum(h)*dba.BIN/(0.5*height*base)


class Run:
    """One scenario's run: series from damBreach.dat, profiles and grains
    from the DEM dumps."""

    def __init__(self, name, case):
        self.name, self.case = name, case
        self.material, self.level = name[0], name[1]
        self.inflow = INFLOW[self.level]
        d = np.loadtxt(os.path.join(case, 'damBreach.dat'))
        self.t, self.H = d[:, 0], d[:, 1]
        self.E, self.Fn, self.Ff = d[:, 3], d[:, 9], d[:, 11]
        self.rate = d[:, 2]
        # the lake's closest approach to the crest (freeboard, m; negative
        # once it overtops)
        fb = d[:, 16]
        k = int(np.nanargmin(fb)) if np.any(np.isfinite(fb)) else -1
        self.fb_min = fb[k] if k >= 0 else np.nan
        self.t_fb_min = self.t[k] if k >= 0 else np.nan
        self.closest_text = 'closest: freeboard %.1f mm at %.1f s' \
            % (1000*self.fb_min, self.t_fb_min)
        self.Hs = smooth_series(self.t, self.H)
        self.s = summary(case)
        self.H0 = self.s['initial dam height H0 [m]']
        self.Hres = self.s['residual dam height (last 10 % of the run) [m]']
        self.t_over = self.s['overtopping from t [s] (-1: none)']
        self.E_end = self.s['final [E]']
        self.grains_out = int(self.s['grains carried out of the flume'])
        self.grains0 = int(self.s['grains at start'])
        wall = os.path.join(case, 'wallTime')
        self.wall = float(open(wall).read()) if os.path.isfile(wall) \
            else np.nan
        self.t_seep, self.has_toe_probe = toe_seepage(case)
        self._grains()
        self._phases()

    def _grains(self):
        """Profiles, slopes, surface-layer grain sizes and the first grains
        to move, from the dumps."""
        dumps = dba.dump_files(self.case, 'particles')
        edges = np.arange(0.0, dba.FLUME_LENGTH + dba.BIN/2, dba.BIN)
        self.centres = 0.5*(edges[1:] + edges[:-1])
        first = dba.read_dump(dumps[0][1])
        self.d_all = 2*first[:, 1]
        pos0 = {int(r[0]): r[3:6] for r in first}
        d0 = {int(r[0]): 2*r[1] for r in first}
        self.dmax = self.d_all.max()
        self.tp, self.profiles, self.slope = [], [], []
        self.d_moved_first = None       # mean d of the first grains to move
        self.t_moved_first = None
        self.surface_d50 = []
        for t, f in dumps:
            p = dba.read_dump(f)
            if p.size == 0:
                continue
            h = dba.surface_profile(p, edges)
            self.tp.append(t)
            self.profiles.append(h)
            self.slope.append(slope_angle(self.centres, h, h.max()))
            self.surface_d50.append(self.surface_median(p, h))
            if self.d_moved_first is None:
                moved = [d0[int(r[0])] for r in p if int(r[0]) in pos0 and
                         np.linalg.norm(r[3:6] - pos0[int(r[0])]) > 0.05]
                gone = [k for k in pos0 if k not in set(p[:, 0].astype(int))]
                moved += [d0[k] for k in gone]
                if len(moved) >= 0.02*len(pos0):
                    self.d_moved_first = np.mean(moved)
                    self.t_moved_first = t
        self.tp = np.array(self.tp)
        self.slope = np.array(self.slope)

    def surface_median(self, p, h):
        """Median diameter of the surface layer of the downstream half."""
        top = h.max()
        if top <= 0:
            return np.nan
        ic = int(np.argmax(h))
        it = ic
        while it < len(h) - 1 and h[it + 1] > 0.1*top:
            it += 1
        x0, x1 = self.centres[ic], self.centres[it] + dba.BIN/2
        x, ztop, d = p[:, 3], p[:, 5] + p[:, 1], 2*p[:, 1]
        idx = np.clip(np.digitize(x, np.arange(0.0, dba.FLUME_LENGTH +
                                                dba.BIN/2, dba.BIN)) - 1,
                      0, len(h) - 1)
        speed = np.linalg.norm(p[:, 6:9], axis=1)
        sel = (x >= x0) & (x <= x1) & (ztop >= h[idx] - self.dmax) & \
            (speed < dba.REST_SPEED)
        return np.median(d[sel]) if np.any(sel) else np.nan

    def at(self, series_t, series, t):
        return np.interp(t, series_t, series)

    def _phases(self):
        # ended: Allrun's run-length rule (damBreachAnalysis.breach_state)
        state = dba.breach_state(self.case)
        self.ended_change = state['height_change']
        self.ended_energy = state['energy_change']
        self.ended = state['done']
        self.emptied = state['gone'] is not None
        self.failed = self.Hres < FAILED*self.H0
        self.t_toe = self.t_back = self.t_head = self.t_end = None
        toe = (self.centres >= TOE - 0.25) & (self.centres <= TOE)
        h_toe = np.array([h[toe].mean() for h in self.profiles])
        low = np.nonzero(h_toe < h_toe[0] - 0.5*np.median(self.d_all))[0]
        self.t_toe = self.tp[low[0]] if len(low) else None
        flat = np.nonzero(self.slope < self.slope[0] - BACKWARD_DEG)[0]
        self.t_back = self.tp[flat[0]] if len(flat) else None
        if self.t_over >= 0:
            h_over = self.at(self.t, self.Hs, self.t_over)
            drop = np.nonzero((self.t > self.t_over) &
                              (self.Hs < h_over - HEADCUT*self.H0))[0]
            self.t_head = self.t[drop[0]] if len(drop) else None
        away = np.nonzero(np.abs(self.Hs - self.Hres) >= REBALANCE)[0]
        self.t_end = self.t[min(away[-1] + 1, len(self.t) - 1)] \
            if len(away) else self.t[0]
        # surface-layer grain size on the downstream half, first vs last 2 s
        sd = np.array(self.surface_d50)
        self.d50_surface_start = np.nanmean(sd[self.tp <= self.tp[0] + 2])
        self.d50_surface_end = np.nanmean(sd[self.tp >= self.tp[-1] - 2])
        self.slope_end = np.nanmean(self.slope[self.tp >= self.tp[-1] - 2])
        self.slope_start = np.nanmean(self.slope[self.tp <= self.tp[0] + 2])
        self.shape_start = shape_factor(self.profiles[0])
        last = np.mean([h for tp, h in zip(self.tp, self.profiles)
                        if tp >= self.tp[-1] - 2], axis=0)
        self.shape_end = shape_factor(last)
        self.profile_end = last
        # failure point (C1): the upstream-most bin that lost more than one
        # median grain diameter of height
        lost = np.nonzero(self.profiles[0] - last > np.median(self.d_all))[0]
        self.x_failure = self.centres[lost[0]] if len(lost) else np.nan


def fmt(v, f='%.3g'):
    return '-' if v is None or (isinstance(v, float) and np.isnan(v)) \
        else f % v


def decreasing(values):
    """Strictly decreasing, at least two values, none missing (a missing or
    NaN value is no pass)."""
    v = list(values)
    if any(x is None or np.isnan(x) for x in v):
        return False
    return len(v) >= 2 and all(a > b for a, b in zip(v, v[1:]))


def rate_peaks(t, rate, t_over, failed):
    """P12 on one run: the peaks of the lowering rate -dH/dt (rate: eq. 21's
    dH/dt per dump) after overtopping, split at the middle of that time:
    (threshold, first half's peaks, second half's, shape holds, shape's
    name). A peak: a local maximum above three times the median after
    overtopping and above 1 mm/s."""
    lower = -np.nan_to_num(np.asarray(rate, dtype=float))
    t = np.asarray(t, dtype=float)
    sel = t >= t_over
    tt, q = t[sel], lower[sel]
    thr = max(0.001, 3*np.median(np.abs(q))) if len(q) else 0.001
    peaks = [i for i in range(1, len(q) - 1)
             if q[i] > thr and q[i] >= q[i - 1] and q[i] > q[i + 1]]
    half = tt[0] + 0.5*(tt[-1] - tt[0]) if len(tt) else 0
    first = [q[i] for i in peaks if tt[i] < half]
    second = [q[i] for i in peaks if tt[i] >= half]
    if failed:
        # the seed on F4 (Fig. 11): "a significant rise in the dam height
        # reduction rate ... at the end of the breach, which is due to the
        # overall failure of the residual dam": the largest peak comes in
        # the second half
        shape = bool(second) and max(second) > max(first, default=0.0)
        return thr, first, second, shape, \
            'complete failure: largest peak in the second half'
    # fading: the peaks of the second half add up to less than those of
    # the first
    shape = bool(first) and sum(second) < sum(first)
    return thr, first, second, shape, \
        'fading: second half\'s sum below the first\'s'


def findings(runs):
    """The seed's findings P1-P12: (name, claim, evidence, holds)."""
    R = runs
    C = [R[n] for n in SCENARIOS[:4] if n in R]
    F = [R[n] for n in SCENARIOS[4:] if n in R]
    over = [r for r in R.values() if r.t_over >= 0]
    out = []

    ev, ok = [], True
    for r in R.values():
        if not r.has_toe_probe:
            ev.append('%s no toeWater probe' % r.name)
            ok = False
            continue
        good = r.t_seep is not None and (r.t_over < 0 or r.t_seep < r.t_over)
        ok &= good
        ev.append('%s seepage at the toe %s s, overtopping %s s'
                  % (r.name, fmt(r.t_seep, '%.1f'),
                     fmt(r.t_over, '%.1f') if r.t_over >= 0 else 'none'))
    out.append(('P1', 'seepage reaches the downstream toe before overtopping',
                ev, ok and bool(R)))

    if 'C1' in R:
        r = R['C1']
        in_crest = CREST[0] - dba.BIN <= r.x_failure <= CREST[1] + dba.BIN
        ok = r.t_over < 0 and in_crest and r.ended
        ev = ['C1 overtopping %s; the failure reaches x = %s m (crest %.3f-'
              '%.3f m, middle %.3f m); change over the last 20 s: height '
              '%.1f mm, [E] %.3f (ended: %s)'
              % ('none (%s)' % r.closest_text if r.t_over < 0
                 else 'at %.1f s' % r.t_over,
                 fmt(r.x_failure, '%.3f'), CREST[0], CREST[1],
                 0.5*(CREST[0] + CREST[1]), 1000*r.ended_change,
                 r.ended_energy, 'yes' if r.ended else 'no')]
    else:
        ok, ev = False, ['no C1 run']
    out.append(('P2', 'C1 does not overtop; its failure reaches the '
                'crest\'s middle and stops', ev, ok))

    others = [R[n] for n in SCENARIOS if n != 'C1' and n in R]
    ok = len(others) == 7 and all(r.t_over >= 0 for r in others)
    ev = ['%s %s' % (r.name, 'at %.1f s' % r.t_over if r.t_over >= 0
                     else 'no overtopping (%s)' % r.closest_text)
          for r in others]
    out.append(('P3', 'every other scenario overtops (F1 included)', ev, ok))

    ev, ok = [], bool(over)
    for r in sorted(over, key=lambda r: r.name):
        ts = [r.t_toe, r.t_back, r.t_head, r.t_end]
        present = [x for x in ts if x is not None]
        good = None not in ts[:3] and all(a <= b for a, b in
                                          zip(present, present[1:]))
        # (overtopping is reported with them: the toe and the slope may
        # move by seepage before it)
        ok &= good
        ev.append('%s toe erosion %s s, backward erosion %s s, overtopping '
                  '%.1f s, head-cut %s s, %s %s s%s'
                  % (r.name, fmt(r.t_toe, '%.1f'),
                                  fmt(r.t_back, '%.1f'), r.t_over,
                                  fmt(r.t_head, '%.1f'),
                                  'complete failure' if r.failed
                                  else 'rebalance', fmt(r.t_end, '%.1f'),
                                  '' if good else ' (out of order or missing)'))
    out.append(('P4', 'phases in order: toe erosion, backward erosion, '
                'head-cut, rebalance or complete failure', ev, ok))

    ev, ok = [], True
    for r in R.values():
        finer = r.d_moved_first is not None and \
            r.d_moved_first < np.mean(r.d_all)
        coarser = r.d50_surface_end > r.d50_surface_start
        if r.material == 'F' or r.t_over >= 0:
            ok &= finer and coarser
        ev.append('%s first 2 %% of grains to move (%s s): mean d %s mm '
                  '(dam %.1f mm); surface layer of the downstream slope d50 '
                  '%s -> %s mm'
                  % (r.name, fmt(r.t_moved_first, '%.1f'),
                     fmt(None if r.d_moved_first is None
                         else 1000*r.d_moved_first, '%.1f'),
                     1000*np.mean(r.d_all), fmt(1000*r.d50_surface_start,
                                                '%.1f'),
                     fmt(1000*r.d50_surface_end, '%.1f')))
    out.append(('P5', 'finer grains move first; a coarse layer forms on the '
                'downstream slope', ev, ok and bool(R)))

    ev, ok = [], True
    for group in (C, F):
        dur = [(r.name, None if r.t_head is None or r.t_toe is None
                else r.t_head - r.t_toe)
               for r in group if r.name != 'C1']
        if dur:
            ev.append(', '.join('%s %s s' % (n, fmt(d, '%.1f'))
                                for n, d in dur))
        ok &= decreasing([d for n, d in dur])
    out.append(('P6', 'the first two phases (toe erosion to head-cut) '
                'shorten as inflow rises', ev, ok))

    hc = [r.Hres for r in C]
    hf = [r.Hres for r in F]
    ok = len(C) == 4 and len(F) == 4 and decreasing(hc) and hc[-1] > 0 and \
        decreasing(hf) and F[-1].failed and \
        all(f.Hres < c.Hres for c, f in zip(C, F))
    ev = ['residual H [m]: ' + ', '.join('%s %.3f' % (r.name, r.Hres)
                                         for r in C + F),
          'F4 %s (complete failure under %.0f %% of H0)'
          % ('failed' if F and F[-1].failed else 'not failed', 100*FAILED)]
    out.append(('P7', 'residual height C1 > C2 > C3 > C4 > 0, F1 > F2 > F3 > '
                'F4 ~ 0, F_i < C_i', ev, ok))

    if 'C2' in R:
        r = R['C2']
        ok = r.ended and np.isfinite(r.Hres) and not r.failed and \
            r.t_over >= 0
        ev = ['C2 residual %.3f m of %.3f m; change over the last 20 s: '
              'height %.1f mm, [E] %.3f'
              % (r.Hres, r.H0, 1000*r.ended_change, r.ended_energy)]
    else:
        ok, ev = False, ['no C2 run']
    out.append(('P8', 'C2 ends in rebalance with a residual dam', ev, ok))

    ev, ok = [], True
    for group in (C, F):
        decay = []
        for r in group:
            t0 = r.t_over if r.t_over >= 0 else 0.0
            decay.append((r.at(r.t, r.E, t0) - r.at(r.t, r.E, t0 + 10))/10)
            flat = abs(r.at(r.t, r.E, r.t[-1]) - r.at(r.t, r.E, r.t[-1] - 20))
            ok &= flat < dba.LEVEL_ENERGY
            ev.append('%s [E] decay %.4f /s in the 10 s after %s, change '
                      'over the last 20 s %.3f, final %.3f'
                      % (r.name, decay[-1], 'overtopping' if r.t_over >= 0
                         else 'the start', flat, r.E_end))
        ok &= decreasing([r.E_end for r in group]) and \
            decreasing([-d for d in decay])
    ok &= len(C) == 4 and len(F) == 4 and \
        all(f.E_end < c.E_end for c, f in zip(C, F))
    out.append(('P9', '[E] decays, then levels off; higher inflow: faster '
                'decay, lower plateau; F below C', ev, ok))

    ev, ok = [], True
    for r in R.values():
        fn_falls = r.Fn[-1] < r.Fn[0]
        line = '%s mean |F_n| %.3f -> %.3f N' % (r.name, r.Fn[0], r.Fn[-1])
        good = fn_falls
        if r.t_over >= 0:
            before = r.at(r.t, r.Ff, r.t_over - 1)
            win = (r.t >= r.t_over) & (r.t <= r.t_over + 10)
            peak = r.Ff[win].max() if np.any(win) else np.nan
            # a rise: 5 % above the value before (the dump-to-dump noise
            # of the mean is about 0.1 %)
            good &= peak > 1.05*before and r.Ff[-1] < peak
            line += '; mean |F_f| %.4f N before overtopping, peak %.4f N ' \
                'within 10 s after, %.4f N at the end' % (before, peak,
                                                           r.Ff[-1])
        ok &= good
        ev.append(line)
    out.append(('P10', 'normal contact force falls; particle-fluid force rises '
                'at overtopping, then falls', ev, ok and bool(R)))

    ev, ok = [], True
    for group in (C, F):
        for r in group:
            # closer to a triangle (1) than to the initial trapezoid
            tri = r.shape_end < 0.5*(1 + r.shape_start)
            if r.t_over >= 0 and not r.failed:
                ok &= tri
            ev.append('%s shape factor (1 triangle) %.2f -> %.2f; '
                      'downstream slope %s -> %s deg'
                      % (r.name, r.shape_start, r.shape_end,
                         fmt(r.slope_start, '%.1f'), fmt(r.slope_end, '%.1f')))
        # every run that keeps a remnant (a failed one has no slope)
        slopes = [r.slope_end for r in group if not r.failed]
        ok &= decreasing(slopes)
    out.append(('P11', 'the remnant becomes triangular; the downstream slope '
                'flattens more at higher inflow', ev, ok))

    ev, ok = [], bool(over)
    for r in sorted(over, key=lambda r: r.name):
        thr, first, second, shape, kind = rate_peaks(r.t, r.rate, r.t_over,
                                                     r.failed)
        good = len(first) + len(second) >= 3 and shape
        ok &= good
        ev.append('%s %d peaks of -dH/dt above %.4f m/s after overtopping: '
                  '%d in the first half (sum %.3f, largest %.4f m/s), %d in '
                  'the second (sum %.3f, largest %.4f m/s); %s: %s'
                  % (r.name, len(first) + len(second), thr, len(first),
                     sum(first), max(first, default=0.0), len(second),
                     sum(second), max(second, default=0.0), kind,
                     'yes' if shape else 'no'))
    out.append(('P12', 'the height-change rate has several peaks, fading in '
                'time (a complete failure: rising at its end)', ev, ok))
    return out


def figures(runs, out, scale):
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    colour = {'1': 'tab:blue', '2': 'tab:green', '3': 'tab:orange',
              '4': 'tab:red'}
    style = {'C': '-', 'F': '--'}

    for fig_no, attr, ylabel, title in (
            (10, 'Hs', 'dam height H [mm] (2 s mean)', 'Dam height'),
            (8, 'E', '[E] = E/E(0)', 'Dimensionless total energy, eq. 20')):
        fig, ax = plt.subplots(figsize=(8, 5))
        for n in SCENARIOS:
            if n not in runs:
                continue
            r = runs[n]
            y = getattr(r, attr)*(1000 if attr == 'Hs' else 1)
            ax.plot(r.t, y, style[r.material], color=colour[r.level],
                    label='%s (%g l/s)' % (n, 1000*r.inflow))
        ax.set(xlabel='t [s]', ylabel=ylabel,
               title='%s, all scenarios (seed Fig. %d), %s scale'
               % (title, fig_no, scale))
        ax.legend(fontsize=8, ncol=2)
        fig.tight_layout()
        fig.savefig(os.path.join(out, 'fig%d.%s.png' % (fig_no, scale)),
                    dpi=110)
        plt.close(fig)

    def profiles(ax, r):
        pick = np.unique(np.linspace(0, len(r.tp) - 1, 8).round().astype(int))
        cmap = plt.get_cmap('viridis')
        for j, i in enumerate(pick[1:]):
            ax.plot(r.centres, r.profiles[i]*1000,
                    color=cmap(j/max(1, len(pick) - 2)), lw=1,
                    label='%g s' % r.tp[i])
        ax.plot(r.centres, r.profiles[0]*1000, 'k--', lw=1, label='t = 0')
        ax.set_xlim(2.5, 7)
        ax.legend(fontsize=6, ncol=2)
        return ', %g l/s' % (1000*r.inflow)

    def rates(ax, r):
        ax.plot(r.t, r.rate*1000, 'b-', lw=0.8)
        ax.axhline(0, color='grey', lw=0.5)
        if r.t_over >= 0:
            ax.axvline(r.t_over, color='r', lw=0.8, ls=':')
        return ''

    for fig_no, draw, ylabel, xlabel, title in (
            (9, profiles, 'surface of resting grains [mm]',
             'x along the bed [m]', 'Longitudinal profiles (seed Fig. 9)'),
            (11, rates, '(H(t+dt) - H(t))/dt [mm/s]',
             't [s] (red: overtopping)',
             'Height-change rate, eq. 21 (seed Fig. 11)')):
        fig, axes = plt.subplots(2, 4, figsize=(18, 7), sharex=True,
                                 sharey=True)
        for k, n in enumerate(SCENARIOS):
            ax = axes[k // 4, k % 4]
            if n not in runs:
                ax.set_title('%s: no run' % n)
                continue
            more = draw(ax, runs[n])
            ax.set_title('(%s) %s%s' % ('ABCDEFGH'[k], n, more))
            if k % 4 == 0:
                ax.set_ylabel(ylabel)
            if k >= 4:
                ax.set_xlabel(xlabel)
        fig.suptitle('%s, %s scale' % (title, scale))
        fig.tight_layout()
        fig.savefig(os.path.join(out, 'fig%d.%s.png' % (fig_no, scale)),
                    dpi=100)
        plt.close(fig)


def main(out, scale, cases):
    os.makedirs(out, exist_ok=True)
    runs = {}
    for case in cases:
        name = os.path.basename(os.path.abspath(case)).split('.')[0]
        if name not in SCENARIOS:
            sys.exit('damBreachAnalysis matrix: %s is not a scenario case '
                     '(<scenario>.<scale>)' % case)
        for f in ('damBreach.dat', 'damBreach.summary'):
            if not os.path.isfile(os.path.join(case, f)):
                sys.exit('damBreachAnalysis matrix: no %s/%s (run '
                         'damBreachAnalysis.py %s first)' % (case, f, case))
        runs[name] = Run(name, case)
    missing = [n for n in SCENARIOS if n not in runs]

    path = os.path.join(out, 'matrix.%s.dat' % scale)
    with open(path, 'w') as f:
        f.write('# Landslide dam breach, %s scale: the eight scenarios (seed '
                'Table 2); written by damBreachAnalysis.py matrix\n' % scale)
        f.write('# inflow_m3s: Table 2 (0.5 m flume)%s; t_overtop_s -1: no '
                'overtopping; wall_s: the run on one core (other runs may have '
                'shared the machine); cpu_s: its CPU time (ExecutionTime)\n'
                % ('; the 0.1 m slice carries 1/5 of it' if scale == 'small'
                   else ''))
        f.write('# scenario inflow_m3s material H0_m Hres_m t_overtop_s '
                'E_end grains_out wall_s cpu_s\n')
        for n in SCENARIOS:
            if n not in runs:
                continue
            r = runs[n]
            f.write('%-8s %.3f %s %.4f %.4f %.1f %.3f %d %.0f %.0f\n'
                    % (n, r.inflow, r.material, r.H0, r.Hres, r.t_over,
                       r.E_end, r.grains_out, r.wall, cpu_time(r.case)))
    print(open(path).read())

    path = os.path.join(out, 'phases.%s.dat' % scale)
    with open(path, 'w') as f:
        f.write('# start of each phase [s] (-: not reached); end: rebalance '
                'or complete failure; ended: over the last %g s the dam height '
                'changed by less than %g mm (change_mm) and [E] by less than '
                '%g (change_E), or every grain has left the flume (emptied)'
                '\n# scenario seepage_at_toe overtopping '
                'toe_erosion backward_erosion head_cut end end_kind end_time_s '
                'change_mm change_E ended\n'
                % (dba.ENDED_WINDOW, 1000*dba.ENDED_HEIGHT, dba.LEVEL_ENERGY))
        for n in SCENARIOS:
            if n not in runs:
                continue
            r = runs[n]
            f.write('%-8s %s %s %s %s %s %s %s %.1f %.1f %.3f %s\n'
                    % (n, fmt(r.t_seep, '%.1f'),
                       fmt(r.t_over if r.t_over >= 0 else None, '%.1f'),
                       fmt(r.t_toe, '%.1f'), fmt(r.t_back, '%.1f'),
                       fmt(r.t_head, '%.1f'), fmt(r.t_end, '%.1f'),
                       'failure' if r.failed else 'rebalance', r.t[-1],
                       1000*r.ended_change, r.ended_energy,
                       'emptied' if r.emptied else
                       'yes' if r.ended else 'no'))
    print(open(path).read())

    res = findings(runs)
    path = os.path.join(out, 'findings.%s.txt' % scale)
    with open(path, 'w') as f:
        f.write('# The seed\'s findings, checked on the %s-scale runs '
                '(damBreachAnalysis.py matrix)%s\n'
                % (scale, '; missing runs: ' + ' '.join(missing)
                   if missing else ''))
        # with runs missing no finding is shown for the seed's matrix: what
        # holds for the runs present says so, and the count is not 'hold'
        holds = 'holds on the runs present' if missing else 'holds'
        for key, claim, ev, ok in res:
            f.write('%s %s: %s\n' % (key, holds if ok else 'does not hold',
                                     claim))
            for e in ev:
                f.write('    %s\n' % e)
        held = sum(ok for *_, ok in res)
        if missing:
            f.write('# 0 of %d hold: %d of the eight runs missing (%s); %d '
                    'hold on the runs present\n'
                    % (len(res), len(missing), ' '.join(missing), held))
        else:
            f.write('# %d of %d hold\n' % (held, len(res)))
    print(open(path).read())

    figures(runs, out, scale)
    print('Written: %s/matrix.%s.dat, phases.%s.dat, findings.%s.txt, '
          'fig8/9/10/11.%s.png' % (out, scale, scale, scale, scale))
    return 0


VARIANTS = {
    '': 'tutorial (0.1 m slice, 50 mm cells, virtual sphere, no lift)',
    'dry': 'lake filled from a dry bed',
    'dryCo045': 'lake filled from a dry bed, maxCo 0.45: its spread',
    'Fdry': 'lake filled from a dry bed',
    'smooth': 'smooth bed (Table 3 grain-wall friction)',
    'w02': 'slice 0.2 m wide',
    'divided': 'divided void fraction',
    'centre': 'centre void fraction',
    'lift': 'Saffman + Magnus lift',
    'Fcoarse': 'coarser grading (15-40 mm)',
    'cell25': '25 mm cells',
    'semiCo1': 'semi-implicit MULES (MULESCorr yes), maxCo 1',
    'semiCo2': 'semi-implicit MULES (MULESCorr yes), maxCo 2',
    'semiCo2final': 'semi-implicit MULES, maxCo 2, rerun with the drag base',
    'ranks2': 'the tutorial on 2 MPI ranks (round-off spread; CPU of one rank)',
    'co045': 'the tutorial at maxCo 0.45 (steps 10 % shorter): the spread',
    'Fcentre': 'centre void fraction',
    'Fco045': 'the tutorial at maxCo 0.45 (steps 10 % shorter): the spread',
    'Flift': 'Saffman + Magnus lift',
    'cellPoint': 'fluid velocity at the grain centre (fluidVelocity cellPoint)',
    'FcellPoint': 'fluid velocity at the grain centre (fluidVelocity cellPoint)',
    'fluct': 'turbulent fluctuations (velocityFluctuation 0.75, 0.2 s)',
    'fluct06': 'turbulent fluctuations (velocityFluctuation 0.6, 0.2 s)',
}


EARLIER = ' [earlier run: no case on disk]'


def label_points(ax, points, fontsize=7):
    """Name each point (text, x, y, marker size in points) beside it,
    trying a few offsets and taking the first whose label box (estimated
    from its length) overlaps neither an earlier label nor another point's
    marker, so crowded points stay legible (a leader line where moved)."""
    ax.figure.canvas.draw()                      # the final axis limits
    to_px = ax.transData.transform
    scale = ax.figure.dpi/72.0                   # points to pixels
    centres = [to_px((x, y)) for _, x, y, _ in points]
    radii = [(ms/2 + 1)*scale for _, _, _, ms in points]
    # (side, dy in points): right or left of the marker, at five heights
    offsets = [(1, 3), (1, -10), (-1, 3), (-1, -10), (1, 12), (1, -19),
               (-1, 12), (-1, -19), (1, 21), (1, -28), (-1, 21), (-1, -28)]
    placed = []

    def box(i, side, dy, w, h):
        c = centres[i]
        x0 = c[0] + radii[i] if side > 0 else c[0] - radii[i] - w
        y0 = c[1] + dy*scale
        return x0, y0, x0 + w, y0 + h

    def clear(b, own):
        for c in placed:
            if b[0] < c[2] and c[0] < b[2] and b[1] < c[3] and c[1] < b[3]:
                return False
        return not any(b[0] - r < c[0] < b[2] + r and b[1] - r < c[1] < b[3] + r
                       for k, (c, r) in enumerate(zip(centres, radii))
                       if k != own)

    for i in sorted(range(len(points)), key=lambda k: -centres[k][1]):
        text, x, y, _ = points[i]
        w, h = 0.6*fontsize*scale*len(text), fontsize*scale
        side, dy = next((o for o in offsets if clear(box(i, *o, w, h), i)),
                        offsets[0])
        placed.append(box(i, side, dy, w, h))
        ax.annotate(text, (x, y), fontsize=fontsize,
                    xytext=(side*radii[i]/scale, dy),
                    textcoords='offset points',
                    ha='left' if side > 0 else 'right',
                    arrowprops=None if (side, dy) == offsets[0] else
                    dict(arrowstyle='-', lw=0.5, color='0.5',
                         shrinkA=0, shrinkB=3))


def earlier_rows(path, measured):
    """The rows of an existing chart file whose variant is not among those
    measured now (its case is not on this disk): kept, their description
    marked, so that rerunning one variant does not drop the others."""
    kept = []
    if not os.path.isfile(path):
        return kept
    for line in open(path):
        if line.startswith('#') or not line.strip():
            continue
        w = line.split()
        if len(w) < 7 or (w[0], w[1]) in measured:
            continue
        description = line.split(None, 6)[6].rstrip('\n')
        if not description.endswith(EARLIER):
            description += EARLIER
        kept.append((w[0], w[1], description, float(w[2]), float(w[3]),
                     float(w[4]), float(w[5])))
        print('coarseness: %s %s kept from %s (its case is not on disk)'
              % (w[0], w[1], path))
    return kept


def coarseness(out, scale, cases):
    """Residual height and overtopping time of each variant against its
    wall time: coarseness.<scale>.dat and .png in out."""
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    rows = []
    for case in cases:
        parts = os.path.basename(os.path.abspath(case)).split('.')
        scenario, tag = parts[0], '.'.join(parts[2:])
        s = summary(case)
        rows.append((scenario, tag or 'tutorial', VARIANTS.get(tag, tag),
                     s['residual dam height (last 10 % of the run) [m]'],
                     s['overtopping from t [s] (-1: none)'],
                     s['end time [s]'], cpu_time(case)))
    path = os.path.join(out, 'coarseness.%s.dat' % scale)
    rows += earlier_rows(path, set((r[0], r[1]) for r in rows))
    with open(path, 'w') as f:
        f.write('# How coarse can the scene be: variants of C2 and F2, %s '
                'scale (coarseness.sh)\n# scenario variant Hres_m '
                't_overtop_s end_s cpu_s  description\n' % scale)
        for r in rows:
            f.write('%-4s %-9s %.4f %.1f %.0f %.0f  %s\n'
                    % (r[0], r[1], r[3], r[4], r[5], r[6], r[2]))
    print(open(path).read())
    fig, ax = plt.subplots(1, 2, figsize=(14, 6))
    labels = ([], [])                # (text, x, y, marker size) per panel
    for r in rows:
        colour = 'tab:blue' if r[0] == 'C2' else 'tab:red'
        marker = '*' if r[1] == 'tutorial' else 'o'
        size = 16 if r[1] == 'tutorial' else 7
        face = 'none' if r[2].endswith(EARLIER) else colour
        for k, y in ((0, 1000*r[3]), (1, r[4])):
            ax[k].plot(r[6]/60, y, marker, color=colour, mfc=face, ms=size)
            labels[k].append(('%s %s' % (r[0], r[1]), r[6]/60, y, size))
    for k in (0, 1):
        ax[k].margins(x=0.15, y=0.08)
    ax[0].set(xlabel='CPU time of the run [min]',
              ylabel='residual dam height [mm]',
              title='Residual height against cost (star: the tutorial)')
    ax[1].set(xlabel='CPU time of the run [min]',
              ylabel='overtopping time [s] (-1: none)',
              title='Overtopping time against cost (blue C2, red F2; '
                    'open: earlier run)')
    fig.tight_layout()
    for k in (0, 1):                 # after the layout: the final positions
        label_points(ax[k], labels[k])
    fig.savefig(os.path.join(out, 'coarseness.%s.png' % scale), dpi=110)
    print('Written: %s/coarseness.%s.dat, .png' % (out, scale))
    return 0
