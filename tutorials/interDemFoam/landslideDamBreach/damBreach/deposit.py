# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
"""Where the grains are (damBreachAnalysis.py deposit CASE...): in the
flume, on the bed downstream of the poured dam's toe (the deposit) and
how many of those move."""
import numpy as np

from .dam import dam_downstream_toe
from .dumps import REST_SPEED, dump_files, read_dump


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
        dumps = dump_files(case, 'particles')
        for i, (t, f) in enumerate(dumps):
            last = i == len(dumps) - 1
            if not last and abs(t/every - round(t/every)) > 1e-6:
                continue
            p = read_dump(f)
            if p.size == 0:
                print('%-22s %7.1f %8d %11d %8d %10d' % (case, t, 0, 0, 0, 0))
                continue
            down = p[:, 3] > toe
            moving = np.linalg.norm(p[:, 6:9], axis=1) > REST_SPEED
            print('%-22s %7.1f %8d %11d %8d %10d'
                  % (case, t, len(p), down.sum(), (down & moving).sum(),
                     (~down & moving).sum()))
