# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
"""The seed's Table 2: the eight scenarios, material C (coarse, uniform)
or F (widely graded) at four inflows."""

SCENARIOS = ['C1', 'C2', 'C3', 'C4', 'F1', 'F2', 'F3', 'F4']
INFLOW = {'1': 0.005, '2': 0.01, '3': 0.015, '4': 0.02}   # Table 2, m3/s
