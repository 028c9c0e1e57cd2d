# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
"""Landslide dam breach: the eight scenarios together (seed Table 2).

    damBreachAnalysis.py matrix DIR SCALE CASE...

run by `Allrun -scenario all` after every case has its damBreach.dat and
damBreach.summary (damBreachAnalysis.py CASE). Writes, in DIR:

  matrix.<scale>.dat    one row per scenario: scenario, inflow (Table 2,
                        full 0.5 m flume; the small slice carries 1/5 of it),
                        material, H0, residual H, overtopping time (-1:
                        none), final [E], grains carried out of the flume,
                        wall time of the run
  phases.<scale>.dat    per scenario the start of each phase (P4), the
                        durations of toe erosion, backward erosion and
                        head-cut, and the longest of the three
  findings.<scale>.txt  the seed's findings P1-P12, each with the measured
                        evidence and "holds" / "does not hold" (with
                        runs missing: "holds on the runs present", and the
                        count says 0 of 12)

    damBreachAnalysis.py matrix DIR SCALE CASE... --second CASE...

two samples of the matrix (Allrun -sample b: every step 10 % shorter):
the second's matrix.<scale>.b.dat and phases.<scale>.b.dat beside the
first's, and findings.<scale>.txt judges each finding on both samples:
"holds" only where it holds in both, "holds in one sample only (a|b)"
where it holds in one; the count is of those that hold in both.
  fig8.<scale>.png      [E](t), all eight (seed Fig. 8)
  fig9.<scale>.png      longitudinal profiles, a grid A-H (seed Fig. 9)
  fig10.<scale>.png     dam height H(t), all eight (seed Fig. 10)
  fig11.<scale>.png     height-change rate, eq. 21 (seed Fig. 11)

The measures behind the phases and the findings: runs.py.
"""
import os
import sys

from .ended import ENDED_HEIGHT, ENDED_WINDOW, LEVEL_ENERGY
from .figures import matrix_figures
from .findings import findings, fmt
from .runs import Run, cpu_time
from .scenarios import SCENARIOS


def load_runs(cases):
    """{scenario: Run} of the cases (each <scenario>.<scale>[.<tag>], with
    its damBreach.dat and damBreach.summary)."""
    runs = {}
    for case in cases:
        name = os.path.basename(os.path.abspath(case)).split('.')[0]
        if name not in SCENARIOS:
            sys.exit('damBreachAnalysis matrix: %s is not a scenario case '
                     '(<scenario>.<scale>)' % case)
        for f in ('damBreach.dat', 'damBreach.summary'):
            if not os.path.isfile(os.path.join(case, f)):
                sys.exit('damBreachAnalysis matrix: no %s/%s (run '
                         'damBreachAnalysis.py %s first)' % (case, f, case))
        runs[name] = Run(name, case)
    return runs


def write_matrix(path, scale, runs):
    with open(path, 'w') as f:
        f.write('# Landslide dam breach, %s scale: the eight scenarios (seed '
                'Table 2); written by damBreachAnalysis.py matrix\n' % scale)
        f.write('# inflow_m3s: Table 2 (0.5 m flume)%s; t_overtop_s -1: no '
                'overtopping; wall_s: the run on one core (other runs may have '
                'shared the machine); cpu_s: its CPU time (ExecutionTime)\n'
                % ('; the 0.1 m slice carries 1/5 of it' if scale == 'small'
                   else ''))
        f.write('# scenario inflow_m3s material H0_m Hres_m t_overtop_s '
                'E_end grains_out wall_s cpu_s\n')
        for n in SCENARIOS:
            if n not in runs:
                continue
            r = runs[n]
            f.write('%-8s %.3f %s %.4f %.4f %.1f %.3f %d %.0f %.0f\n'
                    % (n, r.inflow, r.material, r.H0, r.Hres, r.t_over,
                       r.E_end, r.grains_out, r.wall, cpu_time(r.case)))


PHASES = ('toe_erosion', 'backward_erosion', 'head_cut')


def phase_durations(r):
    """How long toe erosion, backward erosion and head-cut lasted [s]: each
    from its start to the next one's (head-cut to the end); None where a
    start is missing or the next one comes before it."""
    starts = [r.t_toe, r.t_back, r.t_head, r.t_end]
    out = []
    for a, b in zip(starts, starts[1:]):
        out.append(b - a if a is not None and b is not None and b >= a
                   else None)
    return out


def write_phases(path, runs):
    with open(path, 'w') as f:
        f.write('# start of each phase [s] (-: not reached); end: rebalance '
                'or complete failure; ended: over the last %g s the dam height '
                'changed by less than %g mm (change_mm) and [E] by less than '
                '%g (change_E), or every grain has left the flume (emptied)'
                '; toe_s, back_s, head_s: how long toe erosion, backward '
                'erosion and head-cut lasted (each until the next phase '
                'starts, head-cut until the end), longest: the longest of '
                'the three (-: a phase missing or out of order)'
                '\n# scenario seepage_at_toe overtopping '
                'toe_erosion backward_erosion head_cut end end_kind end_time_s '
                'change_mm change_E ended toe_s back_s head_s longest\n'
                % (ENDED_WINDOW, 1000*ENDED_HEIGHT, LEVEL_ENERGY))
        for n in SCENARIOS:
            if n not in runs:
                continue
            r = runs[n]
            durations = phase_durations(r)
            longest = '-' if None in durations else \
                PHASES[max(range(3), key=lambda i: durations[i])]
            f.write('%-8s %s %s %s %s %s %s %s %.1f %.1f %.3f %s %s %s %s %s\n'
                    % (n, fmt(r.t_seep, '%.1f'),
                       fmt(r.t_over if r.t_over >= 0 else None, '%.1f'),
                       fmt(r.t_toe, '%.1f'), fmt(r.t_back, '%.1f'),
                       fmt(r.t_head, '%.1f'), fmt(r.t_end, '%.1f'),
                       'failure' if r.failed else 'rebalance', r.t[-1],
                       1000*r.ended_change, r.ended_energy,
                       'emptied' if r.emptied else
                       'yes' if r.ended else 'no',
                       fmt(durations[0], '%.1f'), fmt(durations[1], '%.1f'),
                       fmt(durations[2], '%.1f'), longest))


def verdict(ok_a, ok_b, holds):
    """A finding's word: on one sample (ok_b None) holds / does not hold;
    on two, holds only where both hold."""
    if ok_b is None or ok_a == ok_b:
        return holds if ok_a else 'does not hold'
    return 'holds in one sample only (%s)' % ('a' if ok_a else 'b')


def write_findings(path, scale, res, missing, res_b=None):
    """res (and res_b, the second sample's): lists of (key, claim,
    evidence, holds)."""
    with open(path, 'w') as f:
        f.write('# The seed\'s findings, checked on the %s-scale runs '
                '(damBreachAnalysis.py matrix)%s%s\n'
                % (scale, '; two samples (a, and b with every step 10 % '
                   'shorter): a finding holds where it holds in both'
                   if res_b else '',
                   '; missing runs: ' + ' '.join(missing) if missing else ''))
        # with runs missing no finding is shown for the seed's matrix: what
        # holds for the runs present says so, and the count is not 'hold'
        holds = 'holds on the runs present' if missing else 'holds'
        for i, (key, claim, ev, ok) in enumerate(res):
            ok_b = res_b[i][3] if res_b else None
            f.write('%s %s: %s\n' % (key, verdict(ok, ok_b, holds), claim))
            for e in ev:
                f.write('    %s%s\n' % ('a: ' if res_b else '', e))
            for e in (res_b[i][2] if res_b else []):
                f.write('    b: %s\n' % e)
        held = sum(ok and (res_b is None or res_b[i][3])
                   for i, (*_, ok) in enumerate(res))
        if res_b:
            f.write('# in sample a %d of %d hold, in sample b %d\n'
                    % (sum(ok for *_, ok in res), len(res),
                       sum(ok for *_, ok in res_b)))
        if missing:
            f.write('# 0 of %d hold: %d of the eight runs missing (%s); %d '
                    'hold on the runs present\n'
                    % (len(res), len(missing), ' '.join(missing), held))
        else:
            f.write('# %d of %d hold%s\n' % (held, len(res),
                                             ' in both samples' if res_b
                                             else ''))


def main(out, scale, cases):
    second = None
    if '--second' in cases:
        i = cases.index('--second')
        cases, second = cases[:i], cases[i + 1:]
        if not second:
            sys.exit('damBreachAnalysis matrix: --second needs the second '
                     'sample\'s cases')
    os.makedirs(out, exist_ok=True)
    runs = load_runs(cases)
    runs_b = load_runs(second) if second else None
    second_runs = runs_b or runs     # a scenario is missing from either
    missing = [n for n in SCENARIOS if n not in runs or n not in second_runs]

    samples = [('', runs)] + ([('.b', runs_b)] if runs_b else [])
    for suffix, rs in samples:
        path = os.path.join(out, 'matrix.%s%s.dat' % (scale, suffix))
        write_matrix(path, scale, rs)
        print(open(path).read())
        path = os.path.join(out, 'phases.%s%s.dat' % (scale, suffix))
        write_phases(path, rs)
        print(open(path).read())

    path = os.path.join(out, 'findings.%s.txt' % scale)
    write_findings(path, scale, findings(runs), missing,
                   findings(runs_b) if runs_b else None)
    print(open(path).read())

    matrix_figures(runs, out, scale)
    print('Written: %s/matrix.%s.dat, phases.%s.dat%s, findings.%s.txt, '
          'fig8/9/10/11.%s.png' % (out, scale, scale,
                                   ' (and their .b.dat)' if runs_b else '',
                                   scale, scale))
    return 0
