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
  phases.<scale>.dat    per scenario the start of each phase (P4)
  findings.<scale>.txt  the seed's findings P1-P12, each with the measured
                        evidence and "holds" / "does not hold" (with
                        runs missing: "holds on the runs present", and the
                        count says 0 of 12)
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


def write_phases(path, runs):
    with open(path, 'w') as f:
        f.write('# start of each phase [s] (-: not reached); end: rebalance '
                'or complete failure; ended: over the last %g s the dam height '
                'changed by less than %g mm (change_mm) and [E] by less than '
                '%g (change_E), or every grain has left the flume (emptied)'
                '\n# scenario seepage_at_toe overtopping '
                'toe_erosion backward_erosion head_cut end end_kind end_time_s '
                'change_mm change_E ended\n'
                % (ENDED_WINDOW, 1000*ENDED_HEIGHT, LEVEL_ENERGY))
        for n in SCENARIOS:
            if n not in runs:
                continue
            r = runs[n]
            f.write('%-8s %s %s %s %s %s %s %s %.1f %.1f %.3f %s\n'
                    % (n, fmt(r.t_seep, '%.1f'),
                       fmt(r.t_over if r.t_over >= 0 else None, '%.1f'),
                       fmt(r.t_toe, '%.1f'), fmt(r.t_back, '%.1f'),
                       fmt(r.t_head, '%.1f'), fmt(r.t_end, '%.1f'),
                       'failure' if r.failed else 'rebalance', r.t[-1],
                       1000*r.ended_change, r.ended_energy,
                       'emptied' if r.emptied else
                       'yes' if r.ended else 'no'))


def write_findings(path, scale, res, missing):
    with open(path, 'w') as f:
        f.write('# The seed\'s findings, checked on the %s-scale runs '
                '(damBreachAnalysis.py matrix)%s\n'
                % (scale, '; missing runs: ' + ' '.join(missing)
                   if missing else ''))
        # with runs missing no finding is shown for the seed's matrix: what
        # holds for the runs present says so, and the count is not 'hold'
        holds = 'holds on the runs present' if missing else 'holds'
        for key, claim, ev, ok in res:
            f.write('%s %s: %s\n' % (key, holds if ok else 'does not hold',
                                     claim))
            for e in ev:
                f.write('    %s\n' % e)
        held = sum(ok for *_, ok in res)
        if missing:
            f.write('# 0 of %d hold: %d of the eight runs missing (%s); %d '
                    'hold on the runs present\n'
                    % (len(res), len(missing), ' '.join(missing), held))
        else:
            f.write('# %d of %d hold\n' % (held, len(res)))


def main(out, scale, cases):
    os.makedirs(out, exist_ok=True)
    runs = load_runs(cases)
    missing = [n for n in SCENARIOS if n not in runs]

    path = os.path.join(out, 'matrix.%s.dat' % scale)
    write_matrix(path, scale, runs)
    print(open(path).read())

    path = os.path.join(out, 'phases.%s.dat' % scale)
    write_phases(path, runs)
    print(open(path).read())

    path = os.path.join(out, 'findings.%s.txt' % scale)
    write_findings(path, scale, findings(runs), missing)
    print(open(path).read())

    matrix_figures(runs, out, scale)
    print('Written: %s/matrix.%s.dat, phases.%s.dat, findings.%s.txt, '
          'fig8/9/10/11.%s.png' % (out, scale, scale, scale, scale))
    return 0
