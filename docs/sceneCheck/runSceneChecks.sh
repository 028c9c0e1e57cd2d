#!/bin/bash
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
cd "${0%/*}" || exit                                # Run from this directory
[ -n "$WM_PROJECT_DIR" ] || { . ../../etc/bashrc || exit 1; }
#------------------------------------------------------------------------------
# checkDemScene on every tutorial and the benchmark scene, each set up
# afresh in runs/<scene> as its Allrun sets it up (no coupled run), and the
# checkDemScene log in runs/<scene>/log.checkDemScene. Prints and writes
# sceneChecks.dat: one row per scene with the check's figures and verdict.
# docs/sceneCheck.md sets them against what the runs measured.
#------------------------------------------------------------------------------
T=../../tutorials/interDemFoam
rm -rf runs && mkdir -p runs
here=$PWD

fresh()    # fresh <tutorial> <name>: a clean copy in runs/<name>
{
    cp -r "$T/$1" "runs/$2" && ( cd "runs/$2" && { ./Allclean > /dev/null 2>&1 || true; } )
}

# the settling particle (d = 1 mm, cells 4 mm, divided)
fresh singleParticleSettling settling
( cd runs/settling && cp -r 0.orig 0 && blockMesh > log.blockMesh 2>&1 )

# the cell-size study's three runs (tests/cases/cellSizeSettling.sh: a
# 12 x 12 x 40 mm column): virtual sphere at dx = d and 2 d, centre at d
for run in virtualSphere-1 virtualSphere-2 centre-1
do
    model=${run%-*}; ratio=${run#*-}
    fresh singleParticleSettling "cellSize.$run"
    (
        cd "runs/cellSize.$run" && cp -r 0.orig 0
        n=$(awk -v r=$ratio 'BEGIN { printf "%d", 12/r + 0.5 }')
        nz=$(awk -v r=$ratio 'BEGIN { printf "%d", 40/r + 0.5 }')
        sed -i "s/^Lx .*/Lx  0.012;/; s/^Ly .*/Ly  0.012;/; s/^Lz .*/Lz  0.04;/;
                s/^nx .*/nx  $n;/; s/^ny .*/ny  $n;/; s/^nz .*/nz  $nz;/" system/blockMeshDict
        sed -i "s/^region .*/region          box block 0 0.012 0 0.012 0 0.04 units box/;
                s/^create_atoms .*/create_atoms    1 single 0.006 0.006 0.034 units box/" DEM/in.liggghts
        foamDictionary -entry voidFraction -set $model constant/couplingProperties > /dev/null
        grep -q virtualSphereCoeffs constant/couplingProperties \
            || echo "virtualSphereCoeffs { diameterRatio 4; sizeThreshold 0.25; }" >> constant/couplingProperties
        blockMesh > log.blockMesh 2>&1
    )
done

# the packed bed (825 beads of 2 mm poured, Rong drag)
fresh packedBed packedBed
( cd runs/packedBed && cp -r 0.orig 0 && blockMesh > log.blockMesh 2>&1 \
    && liggghts -in DEM/in.pour -echo none -log log.pour > /dev/null )

# the dam-break box (no particles)
fresh damBreakBox damBreakBox
( cd runs/damBreakBox && blockMesh > log.blockMesh 2>&1 )

# bedload: the small channel at theta = 0.3, 0.05 s (its Allrun pours the
# bed and sets the case up; the short run only makes the case)
fresh bedload bedload
# (its analysis of so short a run fails; only the case is needed)
( cd runs/bedload && ./Allrun -size small -theta 0.3 -endTime 0.05 > log.Allrun 2>&1 )
[ -d runs/bedload/small.theta.0.3 ] && mv runs/bedload/small.theta.0.3 runs/bedload.theta.0.3

# the flagship, C2 and F2 at the small scale (Allrun -setupOnly)
fresh landslideDamBreach flagship
( cd runs/flagship && ./Allrun -scenario C2 -tag check -setupOnly > log.C2 2>&1 \
    && ./Allrun -scenario F2 -tag check -setupOnly > log.F2 2>&1 )
mv runs/flagship/C2.small.check runs/flagship.C2 2>/dev/null
mv runs/flagship/F2.small.check runs/flagship.F2 2>/dev/null

# the benchmark scene: the settling suspension of 1000 beads (4 mm, 12 mm cells)
../../benchmarks/scene/makeScene 1000 "$here/runs/scene" > runs/log.makeScene 2>&1

printf '# checkDemScene on the tutorials and the benchmark scene (docs/sceneCheck/runSceneChecks.sh)\n' > sceneChecks.dat
printf '# scene exit model particles dOverDx_median dOverDx_max demStep_pctRayleigh couplingStep_tauP particleCourant expectedError_pct fails warns\n' >> sceneChecks.dat
for c in settling cellSize.virtualSphere-1 cellSize.virtualSphere-2 cellSize.centre-1 \
         packedBed damBreakBox bedload.theta.0.3 flagship.C2 flagship.F2 scene
do
    if [ ! -d "runs/$c" ]
    then
        echo "$c: not set up (see runs/)"; printf '%s setupFailed\n' "$c" >> sceneChecks.dat; continue
    fi
    ( cd "runs/$c" && checkDemScene > log.checkDemScene 2>&1 < /dev/null )
    rc=$?
    log="runs/$c/log.checkDemScene"
    model=$(sed -n 's/.*voidFraction \([A-Za-z]*\), demDrag.*/\1/p' "$log")
    awk -v c="$c" -v rc=$rc -v m="${model:--}" '
        /^    particles / { n = $2 }
        /^    d\/dx / { med = $5; sub(",", "", med); mx = $7; sub(/ .*/, "", mx) }
        /^    DEM step .*% of the Rayleigh/ { for (i = 1; i <= NF; i++) if ($(i+1) == "%") r = $i }
        /^    coupling step / { for (i = 1; i <= NF; i++) if ($(i+1) == "tau_p") { t = $i; break } }
        /^    particle Courant / { co = $3 }
        /^    \* / { e = $3 }
        /^    FAIL / { f++ }
        /^    WARN / { w++ }
        END { printf "%s %d %s %s %s %s %s %s %s %s %d %d\n", c, rc, m, n ? n : "-",
                 med ? med : "-", mx ? mx : "-", r ? r : "-", t ? t : "-",
                 co ? co : "-", e ? e : "-", f, w }' "$log" >> sceneChecks.dat
    echo "$c: exit $rc ($(grep -c '^    FAIL' "$log") FAIL, $(grep -c '^    WARN' "$log") WARN)"
done
cat sceneChecks.dat
