# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
"""One scenario's run measured for the matrix (class Run): series from
damBreach.dat and damBreach.summary, profiles, slopes and grain sizes
from the DEM dumps, and the start of each phase.

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

import numpy as np

from .dumps import (BIN, FLUME_LENGTH, REST_SPEED, dump_files,
                    profile_edges, read_dump, surface_profile)
from .ended import breach_state
from .scenarios import INFLOW
from .summary import read_summary
from .water import read_probes

TOE = 4.372                # the initial downstream toe [m]
SMOOTH = 2.0               # s: H averaged over this window
BACKWARD_DEG = 3.0         # downstream slope flatter by this: backward erosion
HEADCUT = 0.10             # H below its overtopping value by this x H0
REBALANCE = 0.005          # m: H within this of the residual height
FAILED = 0.10              # residual height under this x H0: complete failure


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
    rows = {t: v[0] for t, v in read_probes(case, 'toeWater').items()}
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
    base = np.sum(h > 0.05*height)*BIN
    return np.sum(h)*BIN/(0.5*height*base)


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
        self.s = read_summary(case)
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
        dumps = dump_files(self.case, 'particles')
        edges = profile_edges()
        self.centres = 0.5*(edges[1:] + edges[:-1])
        first = read_dump(dumps[0][1])
        self.d_all = 2*first[:, 1]
        pos0 = {int(r[0]): r[3:6] for r in first}
        d0 = {int(r[0]): 2*r[1] for r in first}
        self.dmax = self.d_all.max()
        self.tp, self.profiles, self.slope = [], [], []
        self.d_moved_first = None       # mean d of the first grains to move
        self.t_moved_first = None
        self.surface_d50 = []
        for t, f in dumps:
            p = read_dump(f)
            if p.size == 0:
                continue
            h = surface_profile(p, edges)
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
        x0, x1 = self.centres[ic], self.centres[it] + BIN/2
        x, ztop, d = p[:, 3], p[:, 5] + p[:, 1], 2*p[:, 1]
        idx = np.clip(np.digitize(x, np.arange(0.0, FLUME_LENGTH +
                                                BIN/2, BIN)) - 1,
                      0, len(h) - 1)
        speed = np.linalg.norm(p[:, 6:9], axis=1)
        sel = (x >= x0) & (x <= x1) & (ztop >= h[idx] - self.dmax) & \
            (speed < REST_SPEED)
        return np.median(d[sel]) if np.any(sel) else np.nan

    def at(self, series_t, series, t):
        return np.interp(t, series_t, series)

    def _phases(self):
        # ended: Allrun's run-length rule (ended.breach_state)
        state = breach_state(self.case)
        self.ended_change = state['height_change']
        self.ended_energy = state['energy_change']
        self.ended = state['done']
        self.emptied = state['gone'] is not None
        self.failed = self.Hres < FAILED*self.H0
        self._phase_times()
        self._shapes()

    def _phase_times(self):
        """The start of toe erosion, backward erosion and head-cut (None:
        not reached) and the end (rebalance or complete failure)."""
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

    def _shapes(self):
        """The surface layer's grain size, the downstream slope and the
        profile's shape at the start and the end (first and last 2 s), and
        where the failure reached."""
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
