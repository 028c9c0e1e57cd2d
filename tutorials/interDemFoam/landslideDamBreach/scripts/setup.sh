# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
# Setting a case up (sourced by Allrun): the dam poured once per material
# and scale (buildDam), the case folder with its DEM files and dictionaries
# (setupCase), then, in the case, the fields and the mesh (prepareCase).

# DEM settings of a case; $1: folder, $2: dam file
writeDemSettings()
{
    cat > "$1"/DEM/in.case <<EOF
# Written by Allrun: scenario $scenario, scale $scale
variable        width index $width
variable        yBoundary index $yBoundary
variable        sideWalls index $sideWalls
variable        material index $materialFile
variable        damFile index $2
variable        demDt index $demDt
variable        demGrid index "${demGrid/auto/* * *}"
variable        dumpEvery index $(/usr/bin/python3 -c "print(int(round(0.5/$demDt)))")
variable        vtkEvery index $(/usr/bin/python3 -c "print(int(round(2/$demDt)))")
EOF
}

# The grading (in.material.<name>) of material $1 at this scale and the DEM
# step it needs (at most 20 % of the Rayleigh time of the smallest grains,
# Table 3's shear modulus: 20 mm 5.6e-4 s, 15 mm 4.2e-4 s, 10 mm 2.8e-4 s,
# 5 mm 1.4e-4 s); $2 = run: the case's step, -demStep's fraction of that
# Rayleigh time when given, times demStepScale (-sample b: 0.9); the dam is
# always poured at the default
setMaterial()
{
    material=$1
    local rayleigh
    case "$scale/$material" in
        */C)     materialFile=C;     demDt=1e-4;   rayleigh=5.6e-4 ;; # 20-40 mm: 18 %
        small/F) materialFile=F;     demDt=5e-5;   rayleigh=2.8e-4 ;; # 10-40 mm: 18 %
        full/F)  materialFile=Ffull; demDt=2.5e-5; rayleigh=1.4e-4 ;; # 5-50 mm: 18 %
        */Fcoarse) materialFile=Fcoarse; demDt=7.5e-5; rayleigh=4.2e-4 ;; # 15-40 mm: 18 %
    esac
    if [ "$2" = run ] && [ -n "$demStep" ]
    then
        demDt=$(/usr/bin/python3 -c "print('%.3g' % ($demStep*$rayleigh))")
    fi
    # the matrix's second sample (-sample b): 0.9 x the step
    if [ "$2" = run ] && [ "${demStepScale:-1}" != 1 ]
    then
        demDt=$(/usr/bin/python3 -c "print('%.3g' % ($demStepScale*$demDt))")
    fi
    damName=$material.$scale
    [ "$scale" = small ] && [ "$width" != 0.1 ] && damName=$damName.w$width
    damFile=DEM/dam.$damName.restart
}

# The dam of material $1, poured once per material and scale (LIGGGHTS
# alone), its grading checked; $2 = force: build it again
buildDam()
{
setMaterial "$1"
if [ -f "$damFile" ] && [ -f "${damFile%.restart}.grading" ] && [ "$2" != force ]
then
    return 0
fi
rm -f "$damFile" "${damFile%.restart}.grading" "${damFile%.restart}.grains"
echo "Building the dam: material $material, $scale scale, DEM step $demDt s (LIGGGHTS)"
rm -rf build.$damName
mkdir -p build.$damName/DEM results
cp DEM/in.* build.$damName/DEM/
writeDemSettings build.$damName ../$damFile
(
    cd build.$damName || return 1
    if [ "$nProcs" -gt 1 ]
    then
        mpirun -np "$nProcs" liggghts -in DEM/in.buildDam -echo none -log log.buildDam > log.buildDam.screen 2>&1
    else
        liggghts -in DEM/in.buildDam -echo none -log log.buildDam > log.buildDam.screen 2>&1
    fi
) || { echo "Allrun: LIGGGHTS failed building the dam: see build.$damName/log.buildDam"; return 1; }
[ -f "$damFile" ] && [ -f build.$damName/dam.grains ] \
    || { echo "Allrun: no $damFile or grains written: see build.$damName/log.buildDam"; return 1; }
# the grading: printed, written to results/grading.<scale>.dat; a class
# more than 3 points off its mass share fails the build
case "$damName" in
    C.$scale|F.$scale) gradingFile=results/grading.$scale.dat ;;
    *) gradingFile=results/grading.$damName.dat ;;  # variants: their own
esac
/usr/bin/python3 damBreachAnalysis.py grading build.$damName \
    --out $gradingFile --scale $scale \
    > build.$damName/log.grading 2>&1
status=$?
cat build.$damName/log.grading
if [ $status -ne 0 ]
then
    mv -f "$damFile" "$damFile.rejected"
    echo "Allrun: the dam of material $material is not its grading (build.$damName/log.grading); kept as $damFile.rejected, not used"
    return 1
fi
cp build.$damName/log.grading "${damFile%.restart}.grading"
cp build.$damName/dam.grains "${damFile%.restart}.grains"
}

# The DEM's processor grid of a run on $nProcs ranks (-demGrid auto, the
# default): the grid whose busiest rank computes the fewest neighbour pairs
# on the dam's grains (bin/demGrid; docs/benchmarks.md, DEM load balance);
# on one rank, or without the dam's grains (a dam poured before they were
# kept), LIGGGHTS's choice "* * *"
chooseDemGrid()
{
[ "$demGrid" = auto ] || return 0
demGrid="* * *"
[ "$nProcs" -gt 1 ] || return 0
local grains="${damFile%.restart}.grains" skin
[ -f "$grains" ] || { [ -f build.$damName/dam.grains ] && cp build.$damName/dam.grains "$grains"; }
if [ ! -f "$grains" ]
then
    echo "Allrun: no $grains (the dam was poured before its grains were kept): the DEM's processor grid is LIGGGHTS's choice; -buildDam $material pours it again, or set -demGrid"
    return 0
fi
skin=$(sed -n 's/^neighbor *\([0-9.eE+-]*\) .*/\1/p' DEM/in.common)
demGrid=$("$INTERDEMFOAM_DIR"/bin/demGrid "$grains" "$nProcs" --skin "$skin" --best) \
    || { echo "Allrun: bin/demGrid failed on $grains"; return 1; }
echo "Allrun: the DEM's processor grid on $nProcs ranks, from the dam's grains: $demGrid (bin/demGrid)"
}

# The bed of the case $dir: Table 3's particle-geometry friction (-bed
# smooth) or the rolling friction of a grain in a pocket (-bed pocket)
# instead of the grain-grain values (rough)
setBed()
{
if [ "$bed" = smooth ]
then
    sed -i -e 's/^\(fix *m4 .*peratomtypepair 2\) .*/\1 0.81 0.54 0.54 0.54/' \
           -e 's/^\(fix *m5 .*peratomtypepair 2\) .*/\1 0.275 0.12 0.12 0.12/' "$dir"/DEM/in.common
    grep -q "peratomtypepair 2 0.81 0.54 0.54 0.54" "$dir"/DEM/in.common \
        && grep -q "peratomtypepair 2 0.275 0.12 0.12 0.12" "$dir"/DEM/in.common \
        || { echo "Allrun: -bed smooth: could not set the bed's friction in $dir/DEM/in.common"; return 1; }
elif [ "$bed" = pocket ]
then
    sed -i -e 's/^\(fix *m5 .*peratomtypepair 2\) .*/\1 0.275 0.577 0.577 0.577/' "$dir"/DEM/in.common
    grep -q "peratomtypepair 2 0.275 0.577 0.577 0.577" "$dir"/DEM/in.common \
        || { echo "Allrun: -bed pocket: could not set the bed's rolling friction in $dir/DEM/in.common"; return 1; }
fi
return 0
}

# system/caseSettings of the case $dir (read by blockMeshDict, the
# boundary conditions and setFieldsDict)
writeCaseSettings()
{
cat > "$dir"/system/caseSettings <<EOF
// Written by Allrun: scenario $scenario ($material, $discharge m3/s in the
// full 0.5 m flume), scale $scale
width           $width;
nCellsAcross    $nCells;
nCellsAlong     $(/usr/bin/python3 -c "print(round(7/$cellSize))");
nCellsInlet     $(/usr/bin/python3 -c "print(round(0.05/$cellSize))");
nCellsAbove     $(/usr/bin/python3 -c "print(round(0.45/$cellSize))");
sideType        $sides;
sideU           $( [ $sides = cyclic ] && echo cyclic || echo noSlip );
sideScalar      $( [ $sides = cyclic ] && echo cyclic || echo zeroGradient );
sidePressure    $( [ $sides = cyclic ] && echo cyclic || echo fixedFluxPressure );
inflowRate      $inflowRate;    // m3/s into this flume ($width m wide)
lakeLevel       ${lakeLevel:-0};
// the corner of setFieldsDict's lake box: (3, -1, lakeLevel) - 10 m
// horizontally - 2 m vertically (the real world's directions)
lakeBoxOrigin   $(/usr/bin/python3 -c "
import math; c, s = math.cos(math.radians(5)), math.sin(math.radians(5))
print('(%.7g -1 %.7g)' % (3 - 10*c + 2*s, ${lakeLevel:-0} - 10*s - 2*c))");
EOF
}

# The controls of the case $dir from the options: end time, Courant
# numbers, the phase fraction's solver, the coupling's variants, ranks
setControls()
{
foamDictionary -entry endTime -set "$endTime" "$dir"/system/controlDict > /dev/null
if [ "$maxCo" != 0.5 ]
then
    for key in maxCo maxAlphaCo
    do
        foamDictionary -entry $key -set "$maxCo" "$dir"/system/controlDict > /dev/null || return 1
    done
    foamDictionary -entry maxDeltaT -set "$(/usr/bin/python3 -c "print('%g' % (0.01*$maxCo))")" \
        "$dir"/system/controlDict > /dev/null || return 1
fi
if [ "$semiImplicitAlpha" = yes ]
then
    for kv in "MULESCorr yes" "nLimiterIter 5" "solver smoothSolver" \
              "smoother symGaussSeidel" "tolerance 1e-10" "relTol 0"
    do
        set -- $kv
        foamDictionary -entry "solvers/\"alpha.water.*\"/$1" -set "$2" "$dir"/system/fvSolution > /dev/null || return 1
    done
fi
[ -n "$voidFraction" ] && foamDictionary -entry voidFraction -set "$voidFraction" "$dir"/constant/couplingProperties > /dev/null
if [ -n "$sphereRatio" ]
then
    foamDictionary -entry virtualSphereCoeffs/diameterRatio -set "$sphereRatio" "$dir"/constant/couplingProperties > /dev/null || return 1
fi
[ -n "$forces" ] && foamDictionary -entry forces -set "( $forces )" "$dir"/constant/couplingProperties > /dev/null
if [ -n "$lift" ]
then
    # bed lift (WibergSmithLift) added to the forces unless -forces has it
    local withLift="${forces:-DiFeliceDrag pressureGradient}"
    case " $withLift " in
        *" WibergSmithLift "*) ;;
        *) withLift="$withLift WibergSmithLift" ;;
    esac
    foamDictionary -entry forces -set "( $withLift )" "$dir"/constant/couplingProperties > /dev/null || return 1
    foamDictionary -entry WibergSmithLiftCoeffs -add "{ liftCoefficient $lift; }" \
        "$dir"/constant/couplingProperties > /dev/null || return 1
fi
if [ -n "$fluidVelocity" ]
then
    foamDictionary -entry fluidVelocity -add "$fluidVelocity" "$dir"/constant/couplingProperties > /dev/null || return 1
fi
if [ "$fluidVelocity" = roughnessLayer ]
then
    # the flow between the crests (roughnessLayerLogLaw.H) over the dam's
    # d84 by mass (DEM/in.material.<material>: both small dams 40 mm), with
    # the bedload channel's roughness 2.9 D (case.turbulentBed), packing
    # 0.56 (the dams' cores 0.557-0.584, results/grading.small.dat), crests
    # 0.25 D above the zero plane and troughs 1 D below them
    d84=$(/usr/bin/python3 - "DEM/in.material.$materialFile" <<'EOF2'
import re, sys
# the LIGGGHTS commands, comments dropped
text = '\n'.join(l.split('#')[0] for l in open(sys.argv[1]).read().splitlines())
radius = dict(re.findall(r'fix\s+(\S+)\s+all\s+particletemplate/sphere\b.*?\bradius\s+constant\s+(\S+)', text))
words = re.search(r'particledistribution/discrete\s+\S+\s+\d+\s+(.*)', text).group(1).split()
classes = sorted((2*float(radius[words[i]]), float(words[i + 1])) for i in range(0, len(words), 2))
total, cumulative = sum(f for d, f in classes), 0.0
for d, f in classes:
    cumulative += f/total
    if cumulative >= 0.84 - 1e-9:
        print('%g' % d)
        break
EOF2
) && [ -n "$d84" ] || { echo "Allrun: no d84 from DEM/in.material.$materialFile for -fluidVelocity roughnessLayer"; return 1; }
    foamDictionary -entry roughnessLayerCoeffs -add "{ roughness 2.9; bedSolidFraction 0.56; roughnessDiameter $d84; crestAboveZeroPlane 0.25; layerDepth 1; }" \
        "$dir"/constant/couplingProperties > /dev/null || return 1
fi
if [ -n "$minVoidFraction" ]
then
    foamDictionary -entry minVoidFraction -set "$minVoidFraction" "$dir"/constant/couplingProperties > /dev/null || return 1
fi
if [ -n "$voidFractionFloor" ]
then
    foamDictionary -entry voidFractionFloor -add "$voidFractionFloor" "$dir"/constant/couplingProperties > /dev/null || return 1
fi
if [ "$fluctuation" = turbulence ]
then
    local entries=""
    [ -n "$eddyLifetime" ] && entries=" eddyLifetime $eddyLifetime;"
    [ -n "$fluctuationSize" ] && entries="$entries size $fluctuationSize;"
    [ -n "$fluctuationAt" ] && entries="$entries sampledAt $fluctuationAt;"
    foamDictionary -entry velocityFluctuation -add "{ source turbulence;$entries }" \
        "$dir"/constant/couplingProperties > /dev/null || return 1
elif [ -n "$fluctuation" ]
then
    foamDictionary -entry velocityFluctuation -add "{ intensity $intensity; eddyTime $eddyTime; }" \
        "$dir"/constant/couplingProperties > /dev/null || return 1
fi
if [ "$turbulence" != laminar ]
then
    cp constant/turbulenceProperties.$turbulence "$dir"/constant/turbulenceProperties
fi
foamDictionary -entry numberOfSubdomains -set "$nProcs" "$dir"/system/decomposeParDict > /dev/null
return 0
}

# The case $dir of this scenario (replaced if there): the dam of its
# material (poured first if needed), the tutorial's dictionaries and DEM
# files, and its settings
setupCase()
{
buildDam "$material" || return 1
setMaterial "$material" run
chooseDemGrid || return 1
rm -rf "$dir"
mkdir -p "$dir"/DEM "$dir"/post
cp -r 0.orig constant system "$dir"/
cp DEM/in.* "$dir"/DEM/
setBed || return 1
cp "$damFile" "$dir"/DEM/dam.restart
writeDemSettings "$dir" DEM/dam.restart
writeCaseSettings
setControls
}

# In the case: the initial fields, the mesh, the lake, and Allrun.run (how
# the case runs, for -resume: damBreachResume.py)
prepareCase()
{
cp -r 0.orig 0
runApplication blockMesh || return 1
if [ -n "$lakeLevel" ]
then
    runApplication setFields || return 1
fi
cat > Allrun.run <<EOF
# Written by Allrun: how this case runs (read by Allrun -resume)
firstEnd    $endTime
pieceLength $pieceLength
untilEnded  $untilEnded
maxEnd      $maxEnd
nProcs      $nProcs
demDt       $demDt
EOF
}
