#!/usr/bin/python3
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
"""The DEM's load balance on a processor grid (benchmarks/demBalance).

    demBalance.py data DUMP COPIES OUT    a LIGGGHTS data file of the grains
                                          of a particle dump (id radius mass
                                          x y z ...), the box periodic
                                          across and COPIES slices side by
                                          side across (0.1 m each)
    demBalance.py table RESULTS LOG...    per run log (log.<label>.np<P>.
                                          <gx>x<gy>x<gz>), LIGGGHTS's
                                          end-of-run histograms: owned,
                                          ghost and neighbour-pair counts
                                          per rank (ave, max); the
                                          projection below; written to
                                          RESULTS and printed

The projection (its assumptions, docs/benchmarks.md): the DEM's time per
step is set by the slowest rank, and a rank's time is its neighbour pairs
(the pair loop is 85-88 % of LIGGGHTS's time on these grains; with newton
off a pair across a cut is computed on both sides). The core time per
grain-step relative to one rank is then P x max pairs / the pairs of one
rank (pairRatio); the same for owned + ghost grains (atomRatio) bounds the
per-grain work (neighbour builds, communication, fixes)."""
import math
import os
import re
import sys

SLICE = 0.1      # m, the small-scale slice's width (periodic across)


def write_data(dump, copies, out):
    with open(dump) as f:
        lines = f.read().split('\n')
    bounds = lines[lines.index('ITEM: BOX BOUNDS ff pp ff') + 1:][:3]
    (xlo, xhi), (ylo, yhi), (zlo, zhi) = \
        [tuple(float(v) for v in b.split()) for b in bounds]
    if abs(yhi - ylo - SLICE) > 1e-9:
        sys.exit('demBalance data: %s is %g m wide, not the %g m slice'
                 % (dump, yhi - ylo, SLICE))
    start = next(i for i, l in enumerate(lines) if l.startswith('ITEM: ATOMS'))
    cols = lines[start].split()[2:]
    ir, im, ix, iy, iz = [cols.index(c) for c in ('radius', 'mass', 'x',
                                                  'y', 'z')]
    grains = [l.split() for l in lines[start + 1:] if l.strip()]
    with open(out, 'w') as f:
        f.write('demBalance: %d grains of %s, %d slices across\n\n'
                % (len(grains)*copies, dump, copies))
        f.write('%d atoms\n2 atom types\n\n' % (len(grains)*copies))
        f.write('%g %g xlo xhi\n%g %g ylo yhi\n%g %g zlo zhi\n\nAtoms\n\n'
                % (xlo, xhi, ylo, ylo + copies*SLICE, zlo, zhi))
        n = 0
        rows = []
        for c in range(copies):
            for g in grains:
                r, m = float(g[ir]), float(g[im])
                rho = m/(4.0/3.0*math.pi*r**3)
                y = (float(g[iy]) - ylo) % SLICE + ylo + c*SLICE
                n += 1
                f.write('%d 1 %.6g %.6g %s %.9g %s\n'
                        % (n, 2*r, rho, g[ix], y, g[iz]))
                rows.append('%d %.6g %s %.9g %s' % (n, r, g[ix], y, g[iz]))
    # the same grains as a dump (bin/demGrid reads dumps)
    with open(out + '.dump', 'w') as f:
        f.write('ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n%d\n'
                'ITEM: BOX BOUNDS ff pp ff\n%g %g\n%g %g\n%g %g\n'
                'ITEM: ATOMS id radius x y z\n%s\n'
                % (n, xlo, xhi, ylo, ylo + copies*SLICE, zlo, zhi,
                   '\n'.join(rows)))
    print('demBalance: %s (and %s.dump): %d grains, box y %g..%g m'
          % (out, out, n, ylo, ylo + copies*SLICE))


def histogram(text, name):
    """(ave, max) of LIGGGHTS's end-of-run line "name: A ave M max m min"."""
    m = re.findall(r'^%s: +(\S+) ave (\S+) max' % name, text, re.M)
    if not m:
        return None
    return float(m[-1][0]), float(m[-1][1])


def table(results, logs):
    rows = []
    for log in logs:
        name = os.path.basename(log)
        m = re.fullmatch(r'log\.(\w+)\.np(\d+)\.(\d+)x(\d+)x(\d+)', name)
        if not m:
            sys.exit('demBalance table: %s is not log.<label>.np<P>.<gx>x<gy>x<gz>'
                     % log)
        text = open(log).read()
        stats = [histogram(text, k) for k in ('Nlocal', 'Nghost', 'Neighs')]
        loop = re.findall(r'^Loop time of (\S+) on \d+ procs for (\d+) steps '
                          r'with (\d+) atoms', text, re.M)
        if None in stats:
            sys.exit('demBalance table: %s has no end-of-run histograms '
                     '(the run failed?)' % log)
        # core time per grain-step (us): P x wall / (steps x grains)
        core = (int(m.group(2))*float(loop[-1][0])
                / (int(loop[-1][1])*int(loop[-1][2]))*1e6
                if loop and int(loop[-1][1]) > 0 else float('nan'))
        rows.append((m.group(1), int(m.group(2)),
                     '%s %s %s' % m.group(3, 4, 5), stats, core))
    rows.sort(key=lambda row: (row[0], row[1], row[3][2][1]))
    serial = {r[0]: r for r in rows if r[1] == 1}
    with open(results, 'w') as f:
        f.write('# DEM load balance (benchmarks/demBalance): per processor '
                'grid, LIGGGHTS end-of-run counts per rank\n'
                '# pairRatio = P x max neighbour pairs / pairs on one rank '
                '(the projected core time per grain-step over one rank\'s); '
                'atomRatio = P x max (owned + ghost) / grains on one rank; '
                'imbalance = max/ave pairs; coreUs = P x loop time / (steps '
                'x grains), us of core time per grain-step (a timing: '
                'meaningful only with a core per rank and nothing else '
                'running)\n'
                '# label P gx gy gz ownedAve ownedMax ghostAve ghostMax '
                'pairsAve pairsMax imbalance pairRatio atomRatio coreUs\n')
        for label, p, grid, (own, ghost, pairs), core in rows:
            if label not in serial:
                sys.exit('demBalance table: no one-rank run of %s' % label)
            one = serial[label][3]
            pair_ratio = p*pairs[1]/one[2][1]
            atom_ratio = p*max(own[1] + ghost[1], 1)/one[0][1]
            f.write('%-8s %2d %s %.0f %.0f %.0f %.0f %.0f %.0f %.2f %.2f %.2f '
                    '%.3f\n'
                    % (label, p, grid, own[0], own[1], ghost[0], ghost[1],
                       pairs[0], pairs[1], pairs[1]/pairs[0], pair_ratio,
                       atom_ratio, core))
    print(open(results).read())


def main(argv):
    if len(argv) == 5 and argv[1] == 'data':
        write_data(argv[2], int(argv[3]), argv[4])
    elif len(argv) >= 4 and argv[1] == 'table':
        table(argv[2], argv[3:])
    else:
        sys.exit(__doc__)
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
