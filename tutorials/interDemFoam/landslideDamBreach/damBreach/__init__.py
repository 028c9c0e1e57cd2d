# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
"""The landslide dam breach's analysis (the command lines:
damBreachAnalysis.py and damBreachResume.py beside this folder).

One module per job; each imports only those above it in this list, so
there is no import circle:

  dumps       a case's DEM step, its LIGGGHTS dumps, gravity; the surface
              profile and the energy of one dump
  water       the water function objects: series, probes, water balance,
              lake level
  scenarios   the seed's Table 2: the eight scenarios and their inflows
  ended       the run-length rule (Allrun after each piece, the matrix)
  dam         the poured dam: its shape and the grading check of a build
  figures     the plots of one run and of the eight (seed Figs. 8-11)
  summary     one run: damBreach.dat, profiles.dat, damBreach.summary
  compare     several runs side by side
  deposit     where the grains are, every so many seconds
  shields     the Shields number on the downstream face
  resume      where a stopped run goes on (Allrun -resume)
  runs        one scenario's run measured for the matrix (class Run)
  findings    the seed's findings P1-P12, one function each
  coarseness  the variants' chart (coarseness.sh)
  matrix      the eight runs together: tables, findings, figures
  cli         the command line of damBreachAnalysis.py
"""
