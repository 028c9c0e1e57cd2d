# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
"""The run-length rule, one place for Allrun (damBreachAnalysis.py ended,
after each piece of a run) and the matrix: a run goes on while, over the
last 20 s, the dam height changed by 5 mm or more or [E] by 0.02 or more,
and some grain is left; it stops at the longest run of its scale."""
import glob
import os
import sys

import numpy as np

from .dumps import (dump_files, energy, profile_edges, read_dump,
                             read_gravity, surface_profile)

LEVEL_ENERGY = 0.02    # [E] changed by less than this over 20 s: levelled off
                       # (P9; the run-length rule of ended)
ENDED_WINDOW = 20.0    # s: the run-length rule's window (Allrun, the matrix)
ENDED_HEIGHT = 0.005   # m: the dam height changed by less than this over it


def height_at(case, times, span=2.0):
    """The dam height H averaged over the dumps in [t - span, t] for each
    t of times (one grain more or less on the crest moves H by its
    diameter; the mean over a few dumps is the dam's height)."""
    dumps = dump_files(case, 'particles')
    edges = profile_edges()
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


def reached(case, t_end, max_time, piece_end=None):
    """True when the run has reached max_time: the end of its last
    complete piece, piece_end (Allrun's nominal end, 200 for the piece to
    200 s), is max_time. The last dump is no measure of it: dumps come
    every round(0.5/demDt) steps, so with the steps 10 % shorter of a
    matrix's sample b (demDt 9e-5 s) they are 0.50004 s apart and the last
    before a piece's end at 200 s is at 199.516 s. Without piece_end (the
    rule applied by hand) the piece is taken to end within one dump
    interval after the last dump."""
    end = piece_end
    if end is None:
        dumps = dump_files(case, 'particles')
        end = t_end + (dumps[-1][0] - dumps[-2][0] if len(dumps) > 1 else 0.0)
    return end >= max_time - 1e-6


def ended(case, window, tolerance, max_time, energy_tolerance,
          piece_end=None):
    """True when the run should stop: breach_state's rule (every grain
    has left, or over the last window seconds the dam height changed by
    less than tolerance and [E] by less than energy_tolerance), or the run
    has reached max_time (the longest run of its scale; said so): its
    last complete piece ended at piece_end (reached)."""
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
    if not done and reached(case, state['t_end'], max_time, piece_end):
        print('%s: NOT ENDED: the run has reached %g s, the longest run of '
              'its scale (Allrun -maxTime); stopped and analysed as it is'
              % (case, max_time))
        return True
    return done
