# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
"""Several runs side by side (damBreachAnalysis.py compare OUT CASE...,
which Allrun runs after several scenarios): OUT.png (dam height, [E],
outflow) and OUT.txt (one line per run from its summary)."""
import os

import numpy as np

from .figures import pyplot
from .summary import read_summary


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
