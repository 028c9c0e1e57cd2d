# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
"""The seed's findings P1-P12 on the runs present (a dict scenario ->
runs.Run), one function each, each returning (name, claim, evidence
lines, holds). A finding that needs a run that is missing does not hold;
rankings (decreasing) fail on a missing or NaN value."""
import numpy as np

from .dumps import BIN
from .ended import LEVEL_ENERGY
from .runs import FAILED
from .scenarios import SCENARIOS

CREST = (3.428, 3.729)     # the initial crest, x along the bed [m]


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


def groups(R):
    """The C runs and the F runs present, in the order of Table 2."""
    return ([R[n] for n in SCENARIOS[:4] if n in R],
            [R[n] for n in SCENARIOS[4:] if n in R])


def overtopped(R):
    """The runs whose lake overtopped the crest."""
    return [r for r in R.values() if r.t_over >= 0]


def p1_seepage_first(R):
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
    return ('P1', 'seepage reaches the downstream toe before overtopping',
            ev, ok and bool(R))


def p2_c1_stops(R):
    if 'C1' in R:
        r = R['C1']
        in_crest = CREST[0] - BIN <= r.x_failure <= CREST[1] + BIN
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
    return ('P2', 'C1 does not overtop; its failure reaches the '
            'crest\'s middle and stops', ev, ok)


def p3_others_overtop(R):
    others = [R[n] for n in SCENARIOS if n != 'C1' and n in R]
    ok = len(others) == 7 and all(r.t_over >= 0 for r in others)
    ev = ['%s %s' % (r.name, 'at %.1f s' % r.t_over if r.t_over >= 0
                     else 'no overtopping (%s)' % r.closest_text)
          for r in others]
    return ('P3', 'every other scenario overtops (F1 included)', ev, ok)


def p4_phase_order(R):
    over = overtopped(R)
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
    return ('P4', 'phases in order: toe erosion, backward erosion, '
            'head-cut, rebalance or complete failure', ev, ok)


def p5_fine_first(R):
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
    return ('P5', 'finer grains move first; a coarse layer forms on the '
            'downstream slope', ev, ok and bool(R))


def p6_phases_shorten(R):
    ev, ok = [], True
    for group in groups(R):
        dur = [(r.name, None if r.t_head is None or r.t_toe is None
                else r.t_head - r.t_toe)
               for r in group if r.name != 'C1']
        if dur:
            ev.append(', '.join('%s %s s' % (n, fmt(d, '%.1f'))
                                for n, d in dur))
        ok &= decreasing([d for n, d in dur])
    return ('P6', 'the first two phases (toe erosion to head-cut) '
            'shorten as inflow rises', ev, ok)


def p7_residual_height(R):
    C, F = groups(R)
    hc = [r.Hres for r in C]
    hf = [r.Hres for r in F]
    ok = len(C) == 4 and len(F) == 4 and decreasing(hc) and hc[-1] > 0 and \
        decreasing(hf) and F[-1].failed and \
        all(f.Hres < c.Hres for c, f in zip(C, F))
    ev = ['residual H [m]: ' + ', '.join('%s %.3f' % (r.name, r.Hres)
                                         for r in C + F),
          'F4 %s (complete failure under %.0f %% of H0)'
          % ('failed' if F and F[-1].failed else 'not failed', 100*FAILED)]
    return ('P7', 'residual height C1 > C2 > C3 > C4 > 0, F1 > F2 > F3 > '
            'F4 ~ 0, F_i < C_i', ev, ok)


def p8_c2_rebalances(R):
    if 'C2' in R:
        r = R['C2']
        ok = r.ended and np.isfinite(r.Hres) and not r.failed and \
            r.t_over >= 0
        ev = ['C2 residual %.3f m of %.3f m; change over the last 20 s: '
              'height %.1f mm, [E] %.3f'
              % (r.Hres, r.H0, 1000*r.ended_change, r.ended_energy)]
    else:
        ok, ev = False, ['no C2 run']
    return ('P8', 'C2 ends in rebalance with a residual dam', ev, ok)


def p9_energy(R):
    C, F = groups(R)
    ev, ok = [], True
    for group in (C, F):
        decay = []
        for r in group:
            t0 = r.t_over if r.t_over >= 0 else 0.0
            decay.append((r.at(r.t, r.E, t0) - r.at(r.t, r.E, t0 + 10))/10)
            flat = abs(r.at(r.t, r.E, r.t[-1]) - r.at(r.t, r.E, r.t[-1] - 20))
            ok &= flat < LEVEL_ENERGY
            ev.append('%s [E] decay %.4f /s in the 10 s after %s, change '
                      'over the last 20 s %.3f, final %.3f'
                      % (r.name, decay[-1], 'overtopping' if r.t_over >= 0
                         else 'the start', flat, r.E_end))
        ok &= decreasing([r.E_end for r in group]) and \
            decreasing([-d for d in decay])
    ok &= len(C) == 4 and len(F) == 4 and \
        all(f.E_end < c.E_end for c, f in zip(C, F))
    return ('P9', '[E] decays, then levels off; higher inflow: faster '
            'decay, lower plateau; F below C', ev, ok)


def p10_forces(R):
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
    return ('P10', 'normal contact force falls; particle-fluid force rises '
            'at overtopping, then falls', ev, ok and bool(R))


def p11_remnant(R):
    ev, ok = [], True
    for group in groups(R):
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
    return ('P11', 'the remnant becomes triangular; the downstream slope '
            'flattens more at higher inflow', ev, ok)


def p12_rate_peaks(R):
    over = overtopped(R)
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
    return ('P12', 'the height-change rate has several peaks, fading in '
            'time (a complete failure: rising at its end)', ev, ok)


FINDINGS = [p1_seepage_first, p2_c1_stops, p3_others_overtop, p4_phase_order,
            p5_fine_first, p6_phases_shorten, p7_residual_height,
            p8_c2_rebalances, p9_energy, p10_forces, p11_remnant,
            p12_rate_peaks]


def findings(runs):
    """The seed's findings P1-P12: (name, claim, evidence, holds)."""
    return [finding(runs) for finding in FINDINGS]
