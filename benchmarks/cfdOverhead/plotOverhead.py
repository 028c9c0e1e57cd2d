#!/usr/bin/env python3
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
"""The CFD's cost per cell and time step of the runs of ./Allrun:

    plotOverhead.py RUNS OUT

reads RUNS/<run>/log.run and writes OUT/cfdOverhead.dat (one row per run,
us per cell-step: total wall time, the CFD's stages, the coupling) and
OUT/cfdOverhead.png, and prints the table."""
import os
import re
import sys

RUNS = ['interFoam', 'interFoamHeap', 'noParticles', 'frozen',
        'frozenSemiImplicit', 'frozenGAMG', 'frozenEnvelopeCholesky']
STAGES = ['phaseFraction', 'continuityCorrection', 'momentum', 'pressure',
          'other']


def read_run(log):
    text = open(log).read()
    steps = len(re.findall(r'^Time = ', text, re.M))
    cells = int(re.search(r'nCells:\s*(\d+)', text).group(1)) \
        if re.search(r'nCells:\s*(\d+)', text) else None
    clock = [float(x) for x in re.findall(r'ClockTime = ([0-9.eE+-]+) s', text)]
    cpu = [float(x) for x in re.findall(r'ExecutionTime = ([0-9.eE+-]+) s', text)]
    row = {'steps': steps, 'cells': cells, 'wall': clock[-1] if clock else None,
           'cpu': cpu[-1] if cpu else None}
    m = re.search(r'^Timing split: DEM ([0-9.eE+-]+) s, CFD ([0-9.eE+-]+) s, '
                  r'coupling ([0-9.eE+-]+) s', text, re.M)
    if m:
        row['dem'], row['cfd'], row['coupling'] = map(float, m.groups())
    m = re.search(r'^CFD split:(.*)$', text, re.M)
    if m:
        for stage in STAGES:
            s = re.search(stage + r' ([0-9.eE+-]+) s', m.group(1))
            row[stage] = float(s.group(1)) if s else None
        c = re.search(r'([0-9]+) cells', m.group(1))
        row['cells'] = int(c.group(1))
    return row


def main(runs, out):
    rows = {}
    for run in RUNS:
        log = os.path.join(runs, run, 'log.run')
        if os.path.exists(log):
            rows[run] = read_run(log)
    if not rows:
        sys.exit('plotOverhead.py: no runs in %s' % runs)
    cells = next(r['cells'] for r in rows.values() if r.get('cells'))
    cols = ['run', 'steps', 'cells', 'wall_us', 'cpu_us', 'cfd_us'] + \
        [s + '_us' for s in STAGES] + ['coupling_us', 'dem_us', 'cfdPlusCoupling_us']
    lines = ['# CFD cost per cell and time step [us] on the flagship mesh '
             '(benchmarks/cfdOverhead/Allrun; plotOverhead.py)',
             '# wall/cpu: the whole run (ClockTime/ExecutionTime at the end); '
             'cfd: Timing split CFD; stages: CFD split; nan: not measured '
             '(interFoam prints no split)',
             '# ' + ' '.join(cols)]
    table = {}
    for run, r in rows.items():
        n = r['steps']*cells
        us = lambda x: float('nan') if x is None else 1e6*x/n
        vals = [us(r.get('wall')), us(r.get('cpu')), us(r.get('cfd'))] + \
            [us(r.get(s)) for s in STAGES] + \
            [us(r.get('coupling')), us(r.get('dem'))]
        cfdc = vals[2] + vals[-2] if r.get('cfd') is not None else vals[0]
        vals.append(cfdc)
        table[run] = vals
        lines.append('%s %d %d ' % (run, r['steps'], cells) +
                     ' '.join('%.3g' % v for v in vals))
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, 'cfdOverhead.dat'), 'w') as f:
        f.write('\n'.join(lines) + '\n')
    print('\n'.join(lines))
    # the floor: interFoam with the heap kept as interDemFoam keeps it
    # (its whole run, CPU), else plain interFoam's
    refRun = 'interFoamHeap' if 'interFoamHeap' in table else 'interFoam'
    if refRun in table:
        ref = table[refRun][1]
        for run, vals in table.items():
            print('%-20s CFD + coupling %.3g us per cell-step = %.2f x '
                  "%s's whole run (CPU %.3g)" % (run, vals[-1], vals[-1]/ref, refRun, ref))

    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(8, 4.5))
    names = list(table)
    bottom = [0.0]*len(names)
    parts = [(s, 3 + i) for i, s in enumerate(STAGES)] + [('coupling', 3 + len(STAGES))]
    for label, k in parts:
        h = [0.0 if table[n][k] != table[n][k] else table[n][k] for n in names]
        ax.bar(names, h, bottom=bottom, label=label)
        bottom = [b + x for b, x in zip(bottom, h)]
    for ref in ('interFoam', 'interFoamHeap'):
        if ref in table:
            ax.bar([ref], [table[ref][1]], color='grey' if ref == 'interFoam' else 'dimgrey',
                   label='%s (whole run, CPU, no split)' % ref)
    ax.set_ylabel('us per cell and time step')
    ax.set_title('CFD cost on the flagship mesh (%d cells)' % cells)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, 'cfdOverhead.png'), dpi=100)


if __name__ == '__main__':
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
