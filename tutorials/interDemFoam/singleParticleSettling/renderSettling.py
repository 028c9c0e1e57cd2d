#!/usr/bin/env pvbatch
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
"""Pictures of a coupled case seen from the side (ParaView, pvbatch).

    pvrender renderSettling.py [CASE] [--frames 4] [--window 0.04]
                               [--field U|voidfraction] [--out settling.png]

(pvrender, in the project's bin/, runs pvbatch on a private virtual X
server; `xvfb-run -a pvbatch ...` works too.) Writes CASE/<out>: a few write
times side by side, each the vertical mid-plane through the first particle
(or the domain's centre) coloured by the water's speed (--field U, where
alpha.water > 0.5, with the free surface alpha.water = 0.5 as a line) or by
the fluid volume fraction (--field voidfraction), and the particles as
spheres of their true diameter (Lagrangian cloud demParticles, glyph scaled
by d) coloured by speed; with voidfraction only the particles of the left
half, the field on the right. --window: the height (m) of the window that follows
the first particle; 0 shows the whole domain. --time T renders that one time
only (latest: the last); --raw writes that frame alone (tests count its
pixels).
"""
import os
import sys

# the drawing: bin/pvhelpers.py (side_view_main), shared with the packedBed
# tutorial's renderBed.py
sys.path.insert(0, os.path.join(
    os.environ.get('INTERDEMFOAM_DIR')
    or os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', '..'),
    'bin'))
import pvhelpers as pv  # noqa: E402

if __name__ == '__main__':
    pv.side_view_main()
