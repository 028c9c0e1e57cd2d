#!/usr/bin/env pvbatch
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
"""Pictures of the packed bed (ParaView, pvbatch): the grains as spheres of
their true diameter coloured by speed, and the fluid volume fraction
(voidfraction) on the vertical mid-plane, at a few write times.

    pvrender renderBed.py CASE [--frames 3] [--out bed.png]

CASE: fixedBed.<law> or fluidize.<law>. The drawing is bin/pvhelpers.py's
side view (the singleParticleSettling tutorial's renderSettling.py, same
options) with the whole domain in view and the voidfraction field.
"""
import os
import sys

sys.path.insert(0, os.path.join(
    os.environ.get('INTERDEMFOAM_DIR')
    or os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', '..'),
    'bin'))
import pvhelpers as pv  # noqa: E402

pv.side_view_main(defaults={'window': 0.0, 'field': 'voidfraction',
                            'frames': 3, 'speedMax': 0.05,
                            'voidMin': 0.3, 'out': 'bed.png'},
                  title='Packed bed: grains and fluid volume fraction')
