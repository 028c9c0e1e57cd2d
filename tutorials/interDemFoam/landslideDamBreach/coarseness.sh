#!/bin/bash
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
cd "${0%/*}" || exit                                # Run from this directory
[ -n "$WM_PROJECT_DIR" ] || { . ../../../etc/bashrc || exit 1; }
#------------------------------------------------------------------------------
# How coarse can the scene be? Variants of C2 (and F2) at the small scale,
# two at a time, each run until its breach has ended as the tutorial's runs
# (Allrun), then one chart of residual height and overtopping time against
# wall time, with the tutorial's own C2 and F2 (./Allrun -scenario all):
# results/coarseness.small.png and .dat (damBreachAnalysis.py coarseness).
#
#   ./coarseness.sh                       every variant below
#   ./coarseness.sh dry w02 divided       these only
#
#   dry      C2, the lake filled by the river from a dry bed (the tutorial
#            starts it half full)
#   dryCo045 dry at maxCo 0.45: the dry start's own spread of the numerics
#   Fdry     F2, the lake filled by the river from a dry bed
#   smooth   C2 on a smooth bed (Table 3's particle-geometry friction 0.54
#            and rolling friction 0.12; the tutorial's bed is rough)
#   w02      C2, a slice 0.2 m wide (4 cells across) instead of 0.1 m
#   divided  C2, the divided void-fraction model instead of the virtual sphere
#   centre   C2, the centre void-fraction model
#   lift     C2, with Saffman and Magnus lift
#   Fcoarse  F2 with a coarser grading (15-40 mm, DEM/in.material.Fcoarse)
#   cell25   C2, 25 mm cells instead of 50 mm
#   semiCo1  C2, semi-implicit MULES (MULESCorr yes) at maxCo 1 (the
#            tutorial: explicit at 0.5; maxDeltaT scales with it)
#   semiCo2  C2, semi-implicit MULES at maxCo 2
#   ranks2   C2 on 2 MPI ranks: the same run with sums in another order,
#            a round-off spread
#   co045    C2 at maxCo 0.45 (steps 10 % shorter than the tutorial's): the
#            spread of the numerics the others are judged against
#   Fcentre  F2, the centre void-fraction model (F's 10-20 mm grains are a
#            fifth to two fifths of a cell)
#   Fco045   F2 at maxCo 0.45: F's spread of the numerics
#   Flift    F2 with Saffman and Magnus lift
#   cellPoint  C2, the fluid velocity at each grain's centre (fluidVelocity
#            cellPoint) instead of its virtual sphere's average
#   FcellPoint F2, the same
#   dem30, dem45   C2 with the DEM step at 30 % and 45 % of the 20 mm
#            grains' Rayleigh time (the tutorial: 18 %, 1e-4 s), to 80 s
#            (where the tutorial's C2 and F2 ended)
#   Fdem30, Fdem36, Fdem45   F2 at 30 %, 36 % (1e-4 s, the seed's step)
#            and 45 % of the 10 mm grains' Rayleigh time, to 80 s
#------------------------------------------------------------------------------
all="dry dryCo045 Fdry smooth w02 divided centre lift Fcoarse cell25 semiCo1 semiCo2 ranks2 co045 Fcentre Fco045 Flift cellPoint FcellPoint dem30 dem45 Fdem30 Fdem36 Fdem45"
variants=${*:-$all}

# the force models of the lift variants (the tutorial's plus both lifts)
liftForces="DiFeliceDrag pressureGradient SaffmanLift MagnusLift"
options()
{
    case "$1" in
        dry)     echo "-scenario C2 -lakeLevel \"\"" ;;
        dryCo045) echo "-scenario C2 -lakeLevel \"\" -maxCo 0.45" ;;
        Fdry)    echo "-scenario F2 -lakeLevel \"\"" ;;
        smooth)  echo "-scenario C2 -bed smooth" ;;
        w02)     echo "-scenario C2 -width 0.2" ;;
        divided) echo "-scenario C2 -voidFraction divided" ;;
        centre)  echo "-scenario C2 -voidFraction centre" ;;
        lift)    echo "-scenario C2 -forces \"$liftForces\"" ;;
        Fcoarse) echo "-scenario F2 -grading Fcoarse" ;;
        cell25)  echo "-scenario C2 -cellSize 0.025" ;;
        semiCo1) echo "-scenario C2 -semiImplicitAlpha -maxCo 1" ;;
        semiCo2) echo "-scenario C2 -semiImplicitAlpha -maxCo 2" ;;
        ranks2)  echo "-scenario C2 -parallel 2" ;;
        co045)   echo "-scenario C2 -maxCo 0.45" ;;
        Fcentre) echo "-scenario F2 -voidFraction centre" ;;
        Fco045)  echo "-scenario F2 -maxCo 0.45" ;;
        Flift)   echo "-scenario F2 -forces \"$liftForces\"" ;;
        cellPoint)  echo "-scenario C2 -fluidVelocity cellPoint" ;;
        FcellPoint) echo "-scenario F2 -fluidVelocity cellPoint" ;;
        dem30)   echo "-scenario C2 -demStep 0.3 -endTime 80" ;;
        dem45)   echo "-scenario C2 -demStep 0.45 -endTime 80" ;;
        Fdem30)  echo "-scenario F2 -demStep 0.3 -endTime 80" ;;
        Fdem36)  echo "-scenario F2 -demStep 0.357 -endTime 80" ;;
        Fdem45)  echo "-scenario F2 -demStep 0.45 -endTime 80" ;;
        *) return 1 ;;
    esac
}
for v in $variants
do
    options "$v" > /dev/null \
        || { echo "coarseness.sh: unknown variant '$v' ($all)"; exit 1; }
done

# the dams of the variants first (one at a time: they share results/)
for v in $variants
do
    case "$v" in
        w02)     ./Allrun -buildDam C -width 0.2 -tag w02 | tail -2 || exit 1 ;;
        Fcoarse) ./Allrun -buildDam Fcoarse -tag Fcoarse | tail -2 || exit 1 ;;
    esac
done

running=0
for v in $variants
do
    if [ "$running" -ge 2 ]
    then
        wait -n
        running=$((running - 1))
    fi
    echo "coarseness.sh: starting $v ($(date +%H:%M:%S)): ./Allrun $(options "$v") -tag $v"
    ( eval ./Allrun $(options "$v") -tag "$v" > log.coarseness.$v 2>&1 \
        && echo "coarseness.sh: $v done ($(date +%H:%M:%S))" \
        || echo "coarseness.sh: $v FAILED: see log.coarseness.$v" ) &
    running=$((running + 1))
done
wait
cases=""
for c in C2.small F2.small
do
    [ -f $c/damBreach.summary ] && cases="$cases $c" \
        || echo "coarseness.sh: no $c/damBreach.summary (./Allrun -scenario all): the chart goes without it"
done
# every variant case on disk (any tag, also ones run by hand with
# ./Allrun -tag); the chart keeps earlier rows whose case is not here,
# marked "[earlier run: no case on disk]" (open symbols)
for c in C2.small.* F2.small.*
do
    [ -f "$c/damBreach.summary" ] && cases="$cases $c"
done
/usr/bin/python3 damBreachAnalysis.py coarseness results small $cases
