#!/usr/bin/python3
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
"""The flagship's cost against its floors (benchmarks/flagshipCost/Allrun).

    flagshipCost.py OUT.dat runs/<scenario> ...

Reads, in each scenario's folder, the runs coupled.<r> (interDemFoam's
Timing split, CFD split and Coupling split lines, the particle count it
prints), demAlone.<r> (LIGGGHTS's loop time and its breakdown) and
cfdAlone.<r> (interFoam's ExecutionTime over its time steps), prints the
table and writes OUT.dat: per scenario and quantity the median over the
repeats and the range.

    dem_us          coupled DEM, us per grain-step
    demAlone_us     LIGGGHTS alone, us per grain-step (the floor)
    cfd_us          coupled CFD, us per cell-step (CFD split, in all)
    cfdAlone_us     interFoam, us per cell-step (its time loop)
    coupling_us     the coupling, us per particle-step (coupling split)
    total_s         the coupled run's ExecutionTime per simulated second
    floor_s         DEM alone + interFoam alone, per simulated second
and the ratios dem/demAlone, cfd/cfdAlone, total/floor; LIGGGHTS's own
breakdown of the DEM alone (pair, neigh, comm, output, modify, other, %).
"""
import glob
import os
import re
import statistics
import sys


def number(pattern, text, group=1):
    m = re.search(pattern, text, re.M)
    if not m:
        return None
    return float(m.group(group))


def execution_span(text):
    """Seconds of the time loop: the last ExecutionTime minus the first."""
    t = [float(x) for x in re.findall(r'^ExecutionTime = ([0-9.eE+-]+) s', text, re.M)]
    return (t[-1] - t[0], len(t) - 1) if len(t) > 1 else (None, 0)


def coupled(run):
    text = open(os.path.join(run, 'log.run')).read()
    case = open(os.path.join(run, 'DEM', 'in.case')).read()
    demDt = number(r'^variable\s+demDt\s+index\s+(\S+)', case)
    endTime = number(r'^endTime\s+(\S+);', open(os.path.join(run, 'system', 'controlDict')).read())
    grains = number(r'^DEM: time step \S+ s, couple_every \d+, (\d+) particle', text)
    dem = number(r'^Timing split: DEM (\S+) s', text)
    cells = number(r'^CFD split: .* (\d+) cells, \d+ steps', text)
    steps = number(r'^CFD split: .* \d+ cells, (\d+) steps', text)
    cfd = number(r'^CFD split: .*in all \S+ s \((\S+) us per cell-step\)', text)
    coupling = number(r'^Coupling split: .*particle steps, (\S+) us per particle', text)
    span, _ = execution_span(text)
    if None in (demDt, endTime, grains, dem, cells, steps, cfd, coupling, span):
        sys.exit('%s: a timing line is missing (the run did not end?)' % run)
    demSteps = endTime/demDt
    return dict(dem_us=1e6*dem/(grains*demSteps), cfd_us=cfd,
                coupling_us=coupling, total_s=span/endTime, grains=grains,
                cells=cells, demSteps=demSteps, endTime=endTime)


def dem_alone(run):
    text = open(os.path.join(run, 'log.run')).read()
    m = re.search(r'^Loop time of (\S+) on (\d+) procs for (\d+) steps with (\d+) atoms', text, re.M)
    if not m:
        sys.exit('%s: no loop time (LIGGGHTS did not end?)' % run)
    loop, steps, atoms = float(m.group(1)), int(m.group(3)), int(m.group(4))
    share = {}
    for name, pct in re.findall(r'^(\w+)\s+time \(%\) = \S+ \((\S+)\)', text, re.M):
        share[name.lower()] = float(pct)
    return dict(demAlone_us=1e6*loop/(atoms*steps), demAlone_loop=loop,
                **{'lig_' + k: v for k, v in share.items()})


def cfd_alone(run, cells, endTime):
    text = open(os.path.join(run, 'log.run')).read()
    span, steps = execution_span(text)
    if not span or not steps:
        sys.exit('%s: no time steps (interFoam did not end?)' % run)
    return dict(cfdAlone_us=1e6*span/(cells*steps), cfdAlone_s=span/endTime)


def median_range(values):
    v = [x for x in values if x is not None]
    return statistics.median(v), min(v), max(v)


def scenario(folder):
    rows = []
    for c in sorted(glob.glob(os.path.join(folder, 'coupled.*'))):
        r = c.rsplit('.', 1)[1]
        row = coupled(c)
        row.update(dem_alone(os.path.join(folder, 'demAlone.' + r)))
        row.update(cfd_alone(os.path.join(folder, 'cfdAlone.' + r),
                             row['cells'], row['endTime']))
        row['floor_s'] = row['demAlone_loop']/row['endTime'] + row['cfdAlone_s']
        row['dem_ratio'] = row['dem_us']/row['demAlone_us']
        row['cfd_ratio'] = row['cfd_us']/row['cfdAlone_us']
        row['total_ratio'] = row['total_s']/row['floor_s']
        rows.append(row)
    if not rows:
        sys.exit('%s: no runs' % folder)
    return rows


KEYS = ['dem_us', 'demAlone_us', 'dem_ratio', 'cfd_us', 'cfdAlone_us',
        'cfd_ratio', 'coupling_us', 'total_s', 'floor_s', 'total_ratio',
        'lig_pair', 'lig_neigh', 'lig_comm', 'lig_outpt', 'lig_modfy',
        'lig_other']


def main(out, folders):
    lines = ['# The flagship against its floors (benchmarks/flagshipCost/Allrun, flagshipCost.py)',
             '# per scenario and quantity: the median over the repeats, min, max',
             '# dem_us/demAlone_us: us per grain-step coupled/LIGGGHTS alone; cfd_us/cfdAlone_us: us per cell-step '
             'coupled/interFoam; coupling_us: us per particle-step; total_s/floor_s: s of run per simulated s, '
             'coupled/(LIGGGHTS alone + interFoam alone); lig_*: LIGGGHTS alone, % of its loop',
             '# scenario grains cells repeats quantity median min max']
    for folder in folders:
        name = os.path.basename(folder.rstrip('/'))
        rows = scenario(folder)
        print('%s: %d grains, %d cells, %d DEM steps, %d repeat(s)'
              % (name, rows[0]['grains'], rows[0]['cells'],
                 rows[0]['demSteps'], len(rows)))
        for k in KEYS:
            if not all(k in r for r in rows):
                continue
            m, lo, hi = median_range([r[k] for r in rows])
            print('  %-12s %9.4g   (%.4g .. %.4g)' % (k, m, lo, hi))
            lines.append('%s %d %d %d %s %.5g %.5g %.5g'
                         % (name, rows[0]['grains'], rows[0]['cells'],
                            len(rows), k, m, lo, hi))
    with open(out, 'w') as f:
        f.write('\n'.join(lines) + '\n')
    print('wrote %s' % out)


if __name__ == '__main__':
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2:])
