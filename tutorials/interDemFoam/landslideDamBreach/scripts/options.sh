# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
# Allrun's options (sourced by Allrun; the options themselves: Allrun's
# header): parseOptions reads the command line into the variables below,
# checkOptions checks them all (scripts/options.py, one place for every
# check and its message) and sets the run's settings derived from them.

# the defaults
scenario=C2
scale=small
endTime=""
lakeLevel=unset
nProcs=1
buildDam=""
setupOnly=no
maxCo=0.5
semiImplicitAlpha=no
jobs=2
tag=""
widthOption=""
cellSize=0.05
voidFraction=""
sphereRatio=""
forces=""
fluidVelocity=""
fluctuation=""
eddyLifetime=""
fluctuationSize=""
fluctuationAt=""
lift=""
turbulence=laminar
minVoidFraction=""
voidFractionFloor=""
grading=""
bed=rough
maxTimeOption=""
demGrid=auto
demStep=""
resume=no
sample=a

# parseOptions "$@": the command line into the variables above; exits on an
# unknown option (or -buildDam without materials)
parseOptions()
{
    while [ $# -gt 0 ]
    do
        case "$1" in
            -scenario) scenario="$2"; shift ;;
            -scale)    scale="$2"; shift ;;
            -endTime)  endTime="$2"; shift ;;
            -parallel) nProcs="$2"; shift ;;
            -jobs)     jobs="$2"; shift ;;
            -tag)      tag="$2"; shift ;;
            -width)    widthOption="$2"; shift ;;
            -cellSize) cellSize="$2"; shift ;;
            -voidFraction) voidFraction="$2"; shift ;;
            -sphereRatio) sphereRatio="$2"; shift ;;
            -forces)   forces="$2"; shift ;;
            -fluidVelocity) fluidVelocity="$2"; shift ;;
            -fluctuation) fluctuation="$2"; shift ;;
            -eddyLifetime) eddyLifetime="$2"; shift ;;
            -fluctuationSize) fluctuationSize="$2"; shift ;;
            -fluctuationAt) fluctuationAt="$2"; shift ;;
            -lift)     lift="$2"; shift ;;
            -turbulence) turbulence="$2"; shift ;;
            -minVoidFraction) minVoidFraction="$2"; shift ;;
            -voidFractionFloor) voidFractionFloor="$2"; shift ;;
            -grading)  grading="$2"; shift ;;
            -bed)      bed="$2"; shift ;;
            -setupOnly) setupOnly=yes ;;
            -resume)   resume=yes ;;
            -maxCo)    maxCo="$2"; shift ;;
            -semiImplicitAlpha) semiImplicitAlpha=yes ;;
            -maxTime)  maxTimeOption="$2"; shift ;;
            -demGrid)  demGrid="$2"; shift ;;
            -demStep)  demStep="$2"; shift ;;
            -sample)   sample="$2"; shift ;;
            -lakeLevel) lakeLevel="$2"; shift ;;
            -buildDam) buildDam="$2"; shift
                       [ -n "$buildDam" ] || { echo "Allrun: -buildDam needs materials (C, F or \"C F\")"; exit 1; } ;;
            *) echo "Allrun: unknown option '$1' (use -scenario, -scale, -endTime, -parallel, -jobs, -lakeLevel, -buildDam, -setupOnly, -resume, -tag, -width, -cellSize, -voidFraction, -sphereRatio, -forces, -fluidVelocity, -fluctuation, -eddyLifetime, -fluctuationSize, -fluctuationAt, -lift, -turbulence, -minVoidFraction, -voidFractionFloor, -grading, -bed, -maxCo, -semiImplicitAlpha, -maxTime, -demGrid, -demStep, -sample)"; exit 1 ;;
        esac
        shift
    done
}

# checkOptions: every option checked (the first wrong one named, with what
# it takes: exits 1), then the settings of the run set: the scale's width,
# cells across and sides (width nCells sides yBoundary sideWalls), the lake
# (lakeLevel), the run's length (endTime untilEnded maxEnd pieceLength),
# the scenarios (scenario, "all" expanded) and the fluctuation's numbers
# (intensity eddyTime)
checkOptions()
{
    local settings
    settings=$(/usr/bin/python3 scripts/options.py \
        scenario="$scenario" scale="$scale" endTime="$endTime" \
        lakeLevel="$lakeLevel" parallel="$nProcs" buildDam="$buildDam" \
        setupOnly="$setupOnly" maxCo="$maxCo" \
        semiImplicitAlpha="$semiImplicitAlpha" jobs="$jobs" tag="$tag" \
        width="$widthOption" cellSize="$cellSize" voidFraction="$voidFraction" \
        sphereRatio="$sphereRatio" \
        forces="$forces" fluidVelocity="$fluidVelocity" \
        fluctuation="$fluctuation" eddyLifetime="$eddyLifetime" \
        fluctuationSize="$fluctuationSize" fluctuationAt="$fluctuationAt" \
        lift="$lift" \
        turbulence="$turbulence" \
        minVoidFraction="$minVoidFraction" \
        voidFractionFloor="$voidFractionFloor" \
        grading="$grading" bed="$bed" maxTime="$maxTimeOption" \
        demGrid="$demGrid" demStep="$demStep" resume="$resume" \
        sample="$sample") \
        || { echo "$settings"; exit 1; }
    eval "$settings"
}
