# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
"""How coarse can the scene be (coarseness.sh; damBreachAnalysis.py
coarseness DIR SCALE CASE...): residual height and overtopping time of
each variant of C2 and F2 against the CPU time of its run,
DIR/coarseness.<scale>.dat and .png."""
import math
import os
import sys

from .figures import pyplot
from .runs import cpu_time
from .summary import read_summary


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
    'dem30': 'DEM step 30 % of the 20 mm grains\' Rayleigh time (1.68e-4 s), to 80 s',
    'dem45': 'DEM step 45 % of the 20 mm grains\' Rayleigh time (2.52e-4 s), to 80 s',
    'Fdem30': 'DEM step 30 % of the 10 mm grains\' Rayleigh time (8.4e-5 s), to 80 s',
    'Fdem36': 'DEM step 1e-4 s, the seed\'s (36 % of the 10 mm grains\' Rayleigh time), to 80 s',
    'Fdem45': 'DEM step 45 % of the 10 mm grains\' Rayleigh time (1.26e-4 s), to 80 s',
    'turb': 'k-omega SST with the fluid fraction, fluctuations from k (the turbulent matrix, sample a)',
    'turb.b': 'k-omega SST, fluctuations from k, every step 10 % shorter (sample b)',
    'vs2spill': 'the bedload tutorial\'s default model: k-omega SST, eddies of the cell above, grain top, lift 0.2, sphere 2 d, floor spilled (sample a)',
    'vs2spill.b': 'the bedload default model, every step 10 % shorter (sample b)',
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


def coarseness_rows(cases):
    """(scenario, variant, description, residual H, overtopping time, end
    time, CPU time) of each case."""
    rows = []
    for case in cases:
        parts = os.path.basename(os.path.abspath(case)).split('.')
        scenario, tag = parts[0], '.'.join(parts[2:])
        s = read_summary(case)
        rows.append((scenario, tag or 'tutorial', VARIANTS.get(tag, tag),
                     s['residual dam height (last 10 % of the run) [m]'],
                     s['overtopping from t [s] (-1: none)'],
                     s['end time [s]'], cpu_time(case)))
    return rows


def coarseness_chart(rows, path):
    """Residual height and overtopping time against CPU time, one point
    per row (a star: the tutorial; open: an earlier run)."""
    plt = pyplot()
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
    fig.savefig(path, dpi=110)


def coarseness(out, scale, cases):
    """Residual height and overtopping time of each variant against its
    wall time: coarseness.<scale>.dat and .png in out."""
    rows = coarseness_rows(cases)
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
    coarseness_chart(rows, os.path.join(out, 'coarseness.%s.png' % scale))
    print('Written: %s/coarseness.%s.dat, .png' % (out, scale))
    return 0


# The DEM-step variants and the step of each, as a % of the smallest
# grains' Rayleigh time (the tutorial: 18 %), and each scenario's spread
# pair (the tutorial at maxCo 0.45)
DEM_STEPS = {'tutorial': 18, 'dem30': 30, 'dem45': 45,
             'Fdem30': 30, 'Fdem36': 36, 'Fdem45': 45}
SPREAD = {'C2': 'co045', 'F2': 'Fco045'}


def dem_step(out, scale):
    """Residual height and overtopping time of C2 and F2 at each DEM step
    against CPU time, with the spread of the numerics (the tutorial against
    its maxCo 0.45 pair) as a band around the tutorial's value; from
    coarseness.<scale>.dat (run coarseness first): demStep.<scale>.png"""
    path = os.path.join(out, 'coarseness.%s.dat' % scale)
    rows = {}
    for line in open(path):
        if line.startswith('#') or not line.strip():
            continue
        w = line.split()
        rows[(w[0], w[1])] = (float(w[2]), float(w[3]), float(w[5]))
    plt = pyplot()
    fig, ax = plt.subplots(1, 2, figsize=(13, 5.5))
    print('# scenario step_% Hres_m t_overtop_s cpu_s  '
          '(spread: the tutorial against its maxCo 0.45 pair)')
    for scenario, colour in (('C2', 'tab:blue'), ('F2', 'tab:red')):
        ref = rows.get((scenario, 'tutorial'))
        pair = rows.get((scenario, SPREAD[scenario]))
        if ref is None:
            raise SystemExit('demStep: no tutorial row for %s in %s'
                             % (scenario, path))
        points = sorted((DEM_STEPS[v], rows[(s, v)]) for (s, v) in rows
                        if s == scenario and v in DEM_STEPS)
        for k in (0, 1):
            if pair is not None:
                half = abs(ref[k] - pair[k])
                scale_k = 1000 if k == 0 else 1
                ax[k].axhspan(scale_k*(ref[k] - half), scale_k*(ref[k] + half),
                              color=colour, alpha=0.12)
            xs = [p[1][2]/60 for p in points]
            ys = [(1000 if k == 0 else 1)*p[1][k] for p in points]
            ax[k].plot(xs, ys, 'o-', color=colour, label=scenario)
            for p, x, y in zip(points, xs, ys):
                ax[k].annotate('%d %%' % p[0], (x, y), textcoords='offset points',
                               xytext=(5, 5), fontsize=8, color=colour)
        for p in points:
            print('%s %d %.4f %.1f %.0f' % (scenario, p[0], p[1][0], p[1][1],
                                            p[1][2]))
        if pair is not None:
            print('%s spread: %.4f m, %.1f s' % (scenario, abs(ref[0] - pair[0]),
                                                  abs(ref[1] - pair[1])))
    ax[0].set(xlabel='CPU time of the run to 80 s [min]',
              ylabel='residual dam height [mm]',
              title='Residual height against cost, DEM step as % of the '
                    'Rayleigh time')
    ax[1].set(xlabel='CPU time of the run to 80 s [min]',
              ylabel='overtopping time [s] (-1: none)',
              title='Overtopping time (band: the tutorial +- its maxCo 0.45 pair)')
    for k in (0, 1):
        ax[k].legend()
        ax[k].margins(x=0.12, y=0.12)
    fig.tight_layout()
    png = os.path.join(out, 'demStep.%s.png' % scale)
    fig.savefig(png, dpi=110)
    print('Written: %s' % png)
    return 0


def matrix_findings(directory, scale):
    """The findings held in each sample of a matrix (results/<tag>/
    findings.<scale>.txt: '# N of 12 hold' for one sample, '# in sample a
    N of 12 hold, in sample b M' for two) and the CPU time of its eight
    runs (matrix.<scale>.dat, .b.dat: cpu_s): [(sample, held, of, cpu_s)],
    None where runs are missing (the matrix is not whole)."""
    findings = os.path.join(directory, 'findings.%s.txt' % scale)
    text = open(findings).read()
    if 'missing runs' in text.split('\n', 1)[0]:
        return None
    held = {}
    for line in text.splitlines():
        w = line.split()
        if line.startswith('# in sample a '):
            held = {'a': int(w[4]), 'b': int(w[-1])}
            total = int(w[6])
        elif len(w) >= 5 and line.startswith('# ') and w[2] == 'of' \
                and w[4] == 'hold' and not held:
            held = {'a': int(w[1])}
            total = int(w[3])
    if not held:
        sys.exit('findingsCost: no count of the findings held in %s'
                 % findings)
    out = []
    for sample, suffix in (('a', ''), ('b', '.b')):
        if sample not in held:
            continue
        path = os.path.join(directory, 'matrix.%s%s.dat' % (scale, suffix))
        rows = [l.split() for l in open(path)
                if l.strip() and not l.startswith('#')]
        if len(rows) != 8:
            sys.exit('findingsCost: %s has %d scenarios, not the eight'
                     % (path, len(rows)))
        cpu = sum(float(r[-1]) for r in rows)
        if math.isnan(cpu):
            sys.exit('findingsCost: %s has a run without its CPU time'
                     % path)
        out.append((sample, held[sample], total, cpu))
    return out


def findings_cost(out, scale, entries):
    """The findings held against the CPU time of the whole matrix, one
    point per sample, for each model's matrix (entries: label=results
    folder): findingsCost.<scale>.dat and .png in out."""
    rows = []
    for entry in entries:
        if '=' not in entry:
            sys.exit('findingsCost: %s is not label=folder' % entry)
        label, directory = entry.split('=', 1)
        if not label or len(label.split()) != 1:
            sys.exit('findingsCost: the label of %s must be one word'
                     % entry)
        points = matrix_findings(directory, scale)
        if points is None:
            print('findingsCost: %s skipped: its matrix misses runs (%s)'
                  % (label, directory))
            continue
        rows += [(label, s, h, n, c, directory) for s, h, n, c in points]
    if not rows:
        sys.exit('findingsCost: no whole matrix among %s' % ' '.join(entries))
    path = os.path.join(out, 'findingsCost.%s.dat' % scale)
    with open(path, 'w') as f:
        f.write('# The seed\'s findings held against the CPU time of the '
                'eight %s-scale runs, per model and sample (damBreachAnalysis'
                '.py findingsCost)\n# model sample held of cpu_s  folder\n'
                % scale)
        for r in rows:
            f.write('%-12s %s %2d %2d %6.0f  %s\n' % r)
    print(open(path).read())
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(8, 5.5))
    labels = []
    for label, sample, held, total, cpu, _ in rows:
        marker = 'o' if sample == 'a' else 's'
        ax.plot(cpu/3600, held, marker, ms=8, color='tab:blue')
        labels.append(('%s (%s)' % (label, sample), cpu/3600, held, 8))
    ax.margins(x=0.2)
    ax.set_xlim(left=0)
    ax.axhline(9, color='0.5', ls='--', lw=1)
    ax.text(0, 9.1, ' goal: 9 of 12 in both samples', fontsize=8,
            color='0.3')
    ax.set(xlabel='CPU time of the eight runs [h]',
           ylabel='findings held (of 12)', ylim=(0, 12.5),
           title='The seed\'s findings against the cost of the matrix '
                 '(o sample a, s sample b)')
    fig.tight_layout()
    label_points(ax, labels)
    fig.savefig(os.path.join(out, 'findingsCost.%s.png' % scale), dpi=110)
    print('Written: %s/findingsCost.%s.dat, .png' % (out, scale))
    return 0
