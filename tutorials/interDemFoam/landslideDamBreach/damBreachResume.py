#!/usr/bin/python3
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
"""Where an interrupted landslide-dam run goes on (Allrun -resume):

    damBreachResume.py CASE [--dry-run]

The rule and the cleaning are damBreach/resume.py's (its docstring is the
usage this prints without a case)."""
import sys

from damBreach import resume

if __name__ == "__main__":
    sys.exit(resume.main(sys.argv[1:]))
