#!/usr/bin/python3
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
"""Landslide dam breach: the seed's analysis (Figs. 6-11) from one run.

    damBreachAnalysis.py CASE                 one run: tables and plots in CASE
    damBreachAnalysis.py compare OUT CASE...  several runs side by side
    damBreachAnalysis.py grading BUILD [--out FILE] [--grains FILE]
                                              the grading of a poured dam
    damBreachAnalysis.py ended CASE [--window 20] [--tolerance 0.005]
                               [--energyTolerance 0.02] [--maxTime 300]
                               [--pieceEnd T]
                                              exit 0 when the run should stop:
                                              the breach has ended (H and [E]
                                              level over the window) or the
                                              run has reached maxTime (its
                                              last complete piece ended at
                                              pieceEnd, as Allrun passes it;
                                              without it, within a dump
                                              interval after the last dump)
    damBreachAnalysis.py matrix DIR SCALE CASE... [--second CASE...]
                                              all eight scenarios: the matrix,
                                              the findings, Figs. 8-11 (with
                                              --second, the second sample's
                                              matrix too and the findings on
                                              both)
    damBreachAnalysis.py coarseness DIR SCALE CASE...
                                              the variants' chart
    damBreachAnalysis.py demStep DIR SCALE    C2 and F2 at each DEM step
                                              against CPU time (from DIR's
                                              coarseness.SCALE.dat)
    damBreachAnalysis.py findingsCost DIR SCALE LABEL=FOLDER...
                                              the seed's findings held
                                              against the CPU time of the
                                              whole matrix, one point per
                                              model (LABEL, one word; its
                                              results FOLDER with
                                              findings.SCALE.txt and
                                              matrix.SCALE[.b].dat) and
                                              sample; a matrix with runs
                                              missing is skipped
    damBreachAnalysis.py shields DIR SCALE CASE...
                                              the Shields number on the
                                              downstream face during
                                              overtopping (damBreach/shields.py)
    damBreachAnalysis.py deposit CASE... [--every 20]
                                              where the grains are: in the
                                              flume, on the bed downstream
                                              of the poured dam's toe (the
                                              deposit) and how many of those
                                              move, every 20 s
    damBreachAnalysis.py equalTime CASE...     the dam heights of these runs
                                              at the earliest end among them
                                              (mean over its last 10 %), and
                                              each run's own residual height
    damBreachAnalysis.py budget CASE... [--every 20]
                                              where the dam's mass is (kg):
                                              on its footprint, in the
                                              deposit downstream, out of the
                                              flume; per size class, the
                                              share of its mass off the
                                              footprint, every 20 s

Reads the DEM dumps CASE/post/particles.<step>.txt and contacts.<step>.txt
(DEM/in.dam writes them; step x demDt is the time, demDt the DEM step of
CASE/DEM/in.case, which Allrun writes: 1e-4 s for C, 5e-5 s for F, 2.5e-5 s
for F at full scale) and the water function objects in CASE/postProcessing.
Writes, in CASE:

  damBreach.dat      per dump: t, dam height H (eq. 21's H), its rate
                     (H(t+1) - H(t))/dt (eq. 21), dimensionless total energy
                     [E] (eq. 20) and its parts, grains left, mean normal and
                     tangential contact force, mean particle-fluid force, and
                     the water discharges in and out
  profiles.dat       longitudinal profiles (surface of the resting grains)
                     at chosen times: x, then one column per time
  damBreach.summary  initial and residual height, peak rate, final [E],
                     grains carried out, water balance closure
  damBreach.png, profiles.png

Definitions (the seed leaves them open; these are ours):
  surface h(x)  the top (z + r) of the highest grain at rest (|v| < 0.05 m/s)
                in each 50 mm bin along the flume, z normal to the bed;
                grains in transport are not the dam
  dam height H  max over x of h(x)
  [E]           (sum m g.h + 1/2 sum m v^2 + 1/2 sum I w^2)/E(t=0), heights
                measured upwards (against g) from the bed at the outlet, so
                every term is positive; I = 2/5 m r^2; grains carried out of
                the flume take their energy with them
  contact force mean |F_n| and |F_t| over the grain-grain contacts
  fluid force   mean |F_f| over the grains (drag + pressure gradient)
  water balance V(t_end) - V(t_1) against the integral of (Q_in - Q_out -
                Q_top) dt, relative to the water that came in

grading: the dam a build poured (BUILD/dam.grains, the dump DEM/in.buildDam
writes, or --grains) against its grading (BUILD/DEM/in.material.<material>:
the diameters of the particle templates and the mass-based weights of fix
pdd; material, demDt and width from BUILD/DEM/in.case). Prints and writes
(--out; the rows of the other materials in FILE are kept) per size class:
material, d [m], target and measured mass fraction, count; then the solid
fraction (grain volume over the trapezoid's volume, and in the core of the
dam) and the DEM step against the Rayleigh time of the smallest grain.
Exits 1 when a class misses its target mass fraction by more than
GRADING_TOLERANCE (3 points), a grain matches no class, or the DEM step
exceeds 20 % of the Rayleigh time.
"""
import sys

from damBreach import cli

if __name__ == '__main__':
    sys.exit(cli.main(sys.argv, __doc__))
