#!/usr/bin/python3
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
"""Single-sphere settling: each drag law (through the library, with the
dragSettling utility) against measured spheres settling in water.

Measurements: Mordant & Pinton (2000), Eur. Phys. J. B 18, 343-352: terminal
velocity V and the time to 95 % of it, tau_95, of a glass sphere of 0.5 mm
and 1.5 mm and a steel sphere of 0.8 mm (density ratios 2.56, 2.56, 7.71).
Their table reaches us through the validation set of the Basilisk
settling-sphere test (A. Ghigo, "Exponential fit from Mordant et al., 2000";
case 1 also in ddeepwel/part_settling_matlab); water at nu = 0.89e-6 m2/s
(the value that reproduces the Galileo numbers quoted with them).

At eps = 1 Gidaspow's law is Schiller-Naumann's and Rong's is Di Felice's, so
two curves cover the four laws. Writes settlingExperiments.dat and .png;
run from anywhere after ./Allwmake and . etc/bashrc.
"""
import os, subprocess, sys

RHO_F = 997.0
NU = 0.89e-6
MU = NU*RHO_F
# name, d [m], rhoP/rhoF, V [m/s], tau95 [s]
BEADS = [
    ('glass 0.5 mm', 0.5e-3, 2.56, 0.0741, 0.055),
    ('steel 0.8 mm', 0.8e-3, 7.71, 0.316, 0.108),
    ('glass 1.5 mm', 1.5e-3, 2.56, 0.218, 0.142),
]
LAWS = [('SchillerNaumannDrag', 'Schiller-Naumann (= Gidaspow at eps = 1)'),
        ('DiFeliceDrag', 'Di Felice (= Rong at eps = 1)')]


def settle(law, d, ratio, cvm):
    out = subprocess.run(
        ['dragSettling', '-drag', law, '-d', repr(d), '-rhoP',
         repr(ratio*RHO_F), '-rhoF', repr(RHO_F), '-mu', repr(MU),
         '-addedMass', repr(cvm)],
        check=True, capture_output=True, text=True).stdout
    w = out.split('drag ', 1)[1].split()
    vals = dict(zip(w[1::2], w[2::2]))
    return float(vals['vTerminal']), float(vals['tau95'])


def main():
    rows = []
    for name, d, ratio, V, tau in BEADS:
        for law, _ in LAWS:
            v0, t0 = settle(law, d, ratio, 0.0)
            v1, t1 = settle(law, d, ratio, 0.5)
            rows.append((name, law, d, ratio, V, tau, v0, t0, t1))
    with open('settlingExperiments.dat', 'w') as f:
        f.write('# bead law d rhoP/rhoF V_meas tau95_meas V_law tau95_law '
                'tau95_law_addedMass0.5\n')
        for r in rows:
            f.write('"%s" %s %.4g %.3g %.4g %.4g %.5g %.5g %.5g\n' % r)
    print('%-14s %-20s %9s %9s %8s %10s %10s %12s' % (
        'bead', 'law', 'V meas', 'V law', 'error', 'tau95 meas',
        'tau95 law', '+added mass'))
    for r in rows:
        print('%-14s %-20s %9.4f %9.4f %+7.1f%% %10.3f %10.3f %12.3f' % (
            r[0], r[1], r[4], r[6], 100*(r[6]/r[4] - 1), r[5], r[7], r[8]))
    if '--noPlot' in sys.argv:
        return
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(10, 4.2))
    x = range(len(BEADS))
    for k, (law, label) in enumerate(LAWS):
        sel = [r for r in rows if r[1] == law]
        off = (k - 0.5)*0.3
        a1.bar([i + off for i in x], [100*(r[6]/r[4] - 1) for r in sel], 0.3,
               label=label)
        a2.bar([i + off for i in x], [r[7]/r[5] for r in sel], 0.3,
               label=label + ', no added mass')
        a2.plot([i + off for i in x], [r[8]/r[5] for r in sel], 'k_', ms=18,
                mew=2, label='with added mass 0.5' if k == 0 else None)
    for a in (a1, a2):
        a.set_xticks(list(x))
        a.set_xticklabels([b[0] for b in BEADS])
        a.grid(alpha=0.3, axis='y')
    a1.axhline(0, color='k', lw=0.8)
    a1.set_ylabel('terminal velocity: law / measured - 1 [%]')
    a2.axhline(1, color='k', lw=0.8)
    a2.set_ylabel('tau_95: law / measured')
    a1.legend(fontsize=8)
    a2.legend(fontsize=8)
    fig.suptitle('Settling spheres in water: drag laws vs Mordant & Pinton (2000)')
    fig.tight_layout()
    fig.savefig('settlingExperiments.png', dpi=120)


if __name__ == '__main__':
    main()
