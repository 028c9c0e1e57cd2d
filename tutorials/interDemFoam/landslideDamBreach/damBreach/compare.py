# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
"""Several runs side by side (damBreachAnalysis.py compare OUT CASE...,
which Allrun runs after several scenarios): OUT.png (dam height, [E],
outflow) and OUT.txt (one line per run from its summary)."""
import os

import numpy as np

from .figures import pyplot
from .summary import last_tenth, read_summary


def compare(out, cases):
    plt = pyplot()

    fig, ax = plt.subplots(1, 3, figsize=(15, 4.5))
    lines = []
    for case in cases:
        d = np.loadtxt(os.path.join(case, 'damBreach.dat'))
        name = os.path.basename(os.path.abspath(case))
        ax[0].plot(d[:, 0], d[:, 1]*1000, label=name)
        ax[1].plot(d[:, 0], d[:, 3], label=name)
        ax[2].plot(d[:, 0], d[:, 14]*1000, label=name)
        s = read_summary(case)
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


def equal_time(cases):
    """The dam heights of several runs at the same time: T, the earliest
    of their end times, and each run's mean height over the last 10 % of
    [t0, T] (t0 its first time, 0 in every run: the dam's restart starts
    the clock), as damBreach.summary takes its residual height over the
    last 10 % of its own run. Runs that end at different times (the run length
    follows the breach, Allrun) compare there as they stood together."""
    data = [(c, np.loadtxt(os.path.join(c, 'damBreach.dat'))) for c in cases]
    end = min(d[-1, 0] for _, d in data)
    print('# T = %g s, the earliest end of these runs; H(T): the mean dam '
          'height over [%g, %g] s' % (end, 0.9*end, end))
    print('%-24s %8s %10s %12s' % ('case', 'end [s]', 'H(T) [m]',
                                   'residual [m]'))
    for case, d in data:
        t, h = d[:, 0], d[:, 1]
        window, tail = last_tenth(t, end), last_tenth(t)
        print('%-24s %8.1f %10.4f %12.4f' % (case, t[-1], h[window].mean(),
                                             h[tail].mean()))
