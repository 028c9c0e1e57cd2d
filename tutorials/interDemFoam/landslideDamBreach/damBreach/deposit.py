# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
"""Where the grains are (damBreachAnalysis.py deposit CASE...): in the
flume, on the bed downstream of the poured dam's toe (the deposit) and
how many of those move."""
import numpy as np

from .dam import dam_downstream_toe
from .dumps import REST_SPEED, dump_files, read_dump


def dumps_every(case, every):
    """(t, rows) of the case's particle dumps every `every` seconds (the
    dump nearest each multiple of it: with demDt 9e-5 s, a matrix's
    sample b, the dumps are 0.50004 s apart and miss the multiples), and
    its last."""
    dumps = dump_files(case, 'particles')
    if not dumps:
        return
    times = np.array([t for t, f in dumps])
    interval = np.median(np.diff(times)) if len(times) > 1 else every
    chosen = []
    for k in range(int(round(times[-1]/every)) + 1):
        i = int(np.argmin(np.abs(times - k*every)))
        if abs(times[i] - k*every) <= 0.5*interval + 1e-9 and i not in chosen:
            chosen.append(i)
    if len(dumps) - 1 not in chosen:
        chosen.append(len(dumps) - 1)
    for i in chosen:
        yield dumps[i][0], read_dump(dumps[i][1])


def deposit(cases, every):
    """Per case, every `every` seconds of its dumps (and its last): grains
    in the flume, grains downstream of the poured dam's toe, and of those
    the ones moving (faster than REST_SPEED): is the deposit at rest or
    being carried out of the flume?"""
    toe = dam_downstream_toe()
    print('# x > %.3f m: downstream of the poured dam; moving: faster than '
          '%g m/s' % (toe, REST_SPEED))
    print('%-22s %7s %8s %11s %8s %10s' % ('case', 't [s]', 'flume',
          'downstream', 'moving', 'dam moving'))
    for case in cases:
        for t, p in dumps_every(case, every):
            if p.size == 0:
                print('%-22s %7.1f %8d %11d %8d %10d' % (case, t, 0, 0, 0, 0))
                continue
            down = p[:, 3] > toe
            moving = np.linalg.norm(p[:, 6:9], axis=1) > REST_SPEED
            print('%-22s %7.1f %8d %11d %8d %10d'
                  % (case, t, len(p), down.sum(), (down & moving).sum(),
                     (~down & moving).sum()))


def budget(cases, every):
    """Per case, every `every` seconds of its dumps (and its last): where
    the dam's mass is, in kg: on the poured dam's footprint (x up to its
    downstream toe), downstream of it on the bed (the deposit) and out of
    the flume (the first dump's mass less the flume's); then, per size
    class (diameter, mm), the share of the class's mass that has left the
    footprint (deposit and out). Which grains did the breach take, and are
    they still in the flume?"""
    toe = dam_downstream_toe()
    print('# footprint: x <= %.3f m (the poured dam); deposit: x > %.3f m; '
          'out: left the flume; masses in kg; per class: share of its mass '
          'off the footprint' % (toe, toe))
    for case in cases:
        dumps = dump_files(case, 'particles')
        if not dumps:
            print('%-22s no particle dumps in %s/post' % (case, case))
            continue
        first = read_dump(dumps[0][1])
        d_first = np.round(2000*first[:, 1], 1)
        classes = np.unique(d_first)
        m0 = np.array([first[d_first == d, 2].sum() for d in classes])
        print('%-22s %7s %9s %8s %7s  %s' % (
            'case', 't [s]', 'footprint', 'deposit', 'out',
            ' '.join('%6.0fmm' % d for d in classes)))
        for t, p in dumps_every(case, every):
            if p.size == 0:
                p = np.zeros((0, 9))
            d = np.round(2000*p[:, 1], 1)
            on = p[:, 3] <= toe
            foot, dep = p[on, 2].sum(), p[~on, 2].sum()
            off = [1 - p[on & (d == c), 2].sum()/m for c, m in
                   zip(classes, m0)]
            print('%-22s %7.1f %9.2f %8.2f %7.2f  %s' % (
                case, t, foot, dep, round(m0.sum() - foot - dep, 2) + 0.0,
                ' '.join('%8.3f' % s for s in off)))
