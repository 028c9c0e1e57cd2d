# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
"""The command line of damBreachAnalysis.py (its docstring is the usage):
one function per command, each calling the module that does the job."""
import argparse
import os
import sys

from . import coarseness, compare, dam, deposit, ended, matrix, shields, summary


def grading_command(args):
    ap = argparse.ArgumentParser(prog='damBreachAnalysis.py grading')
    ap.add_argument('build')
    ap.add_argument('--out')
    ap.add_argument('--grains')
    ap.add_argument('--scale')
    a = ap.parse_args(args)
    return 0 if dam.grading(a.build, a.out, a.grains, a.scale) else 1


def ended_command(args):
    ap = argparse.ArgumentParser(prog='damBreachAnalysis.py ended')
    ap.add_argument('case')
    ap.add_argument('--window', type=float, default=ended.ENDED_WINDOW)
    ap.add_argument('--tolerance', type=float, default=ended.ENDED_HEIGHT)
    ap.add_argument('--energyTolerance', type=float,
                    default=ended.LEVEL_ENERGY)
    ap.add_argument('--maxTime', type=float, default=300.0)
    ap.add_argument('--pieceEnd', type=float, default=None)
    a = ap.parse_args(args)
    return 0 if ended.ended(a.case, a.window, a.tolerance, a.maxTime,
                            a.energyTolerance, a.pieceEnd) else 1


def cases_every_command(name, run):
    """The command `name` (CASE... [--every 20]), running run(cases, every)."""
    def command(args):
        ap = argparse.ArgumentParser(prog='damBreachAnalysis.py ' + name)
        ap.add_argument('cases', nargs='+')
        ap.add_argument('--every', type=float, default=20.0)
        a = ap.parse_args(args)
        run(a.cases, a.every)
    return command


# command: (the fewest arguments after it, what runs it)
COMMANDS = {
    'grading': (1, grading_command),
    'ended': (1, ended_command),
    'matrix': (3, lambda a: matrix.main(a[0], a[1], a[2:])),
    'coarseness': (3, lambda a: coarseness.coarseness(a[0], a[1], a[2:])),
    'demStep': (2, lambda a: coarseness.dem_step(a[0], a[1])),
    'findingsCost': (3, lambda a: coarseness.findings_cost(a[0], a[1],
                                                           a[2:])),
    'shields': (3, lambda a: shields.main(a[0], a[1], a[2:])),
    'deposit': (1, cases_every_command('deposit', deposit.deposit)),
    'budget': (1, cases_every_command('budget', deposit.budget)),
    'compare': (2, lambda a: compare.compare(a[0], a[1:])),
    'equalTime': (2, compare.equal_time),
}


def main(argv, usage):
    """Run the command of argv (sys.argv); its exit status (None: 0).
    A single argument is a case to analyse; anything else prints usage."""
    if len(argv) >= 2 and argv[1] in COMMANDS \
            and len(argv) - 2 >= COMMANDS[argv[1]][0]:
        return COMMANDS[argv[1]][1](argv[2:])
    if len(argv) == 2 and argv[1] in ('-h', '-help', '--help'):
        print(usage)
        return 0
    if len(argv) == 2 and not os.path.isdir(argv[1]):
        sys.exit('damBreachAnalysis.py: %s is no case folder (nor one of the'
                 ' commands %s)\n\n%s'
                 % (argv[1], ', '.join(sorted(COMMANDS)), usage))
    if len(argv) == 2:
        return summary.analyse(argv[1])
    sys.exit(usage)
