#!/bin/bash
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#------------------------------------------------------------------------------
# No input makes the solver crash. A small coupled case (one 1 mm sphere
# settling from air into water in a 20 mm column of 4 mm cells, 20 coupling
# steps) is run once per mutation of its input, one input changed at a
# time, as a new user would: every couplingProperties keyword removed or
# given a bad value, DEM script lines removed or given bad numbers,
# controlDict times, transport properties, gravity, initial fields and the
# mesh (the list below, MUTATIONS, 97 of them).
# Asserts, for every mutation: the run ends with exit 0 (and "End"), or
# with a clear error: exit 1 and a "FOAM FATAL" line; never a signal (a
# crash), a hang (60 s) or a non-zero exit without an error line (a silent
# abort). Each mutation also says what it must give:
#   ok               exit 0
#   warn:<p>;<p>     exit 0, every pattern in the log (a warning)
#   error:<p>;<p>    the clear error, every pattern in the log (the file,
#                    the keyword, the value, what is allowed)
#   any              exit 0 or a clear error
# Prints the counts (exit 0, clear error, signal, hang, silent abort).
# Reference: issue #51's mutation study (70 mutations on such a case: 6
# floating-point crashes, 1 silent MPI_ABORT, 3 silent runs before the
# guards). Measured: all 97 pass, 23 with exit 0 and 74 with a clear
# error, none crashes, hangs or aborts silently (61 s on 2 cores).
# Negative control: a solver built without the transportProperties guard
# (caseInputCheck::transportProperties not called in createFields.H)
# failed 5 mutations: tp_rho0 and tp_nu0 ended in the floating-point stop,
# whose message names neither the keyword nor its value, and tp_nuNeg,
# tp_rhoAirNeg and tp_sigmaNeg ran without a word.
#
#   inputFuzz.sh                all mutations, two at a time
#   inputFuzz.sh one <name>     one mutation (used by the loop; for debugging)
#------------------------------------------------------------------------------
. "${0%/*}/caseFunctions.sh"
self="$(cd "${0%/*}" && pwd -P)/${0##*/}"

fuzzDir="$runDir/inputFuzz"
base="$fuzzDir/base"

# name | expectation | stage (solver: the solver only; mesh: blockMesh,
# setFields and the solver) | the edit, run in the case folder
MUTATIONS=$(cat <<'EOF'
cp_noDemScript        | error:demScript                          | solver | sed -i '/^demScript /d' constant/couplingProperties
cp_badDemScript       | error:Cannot open the DEM script;none.liggghts | solver | sed -i 's#^demScript .*#demScript "DEM/none.liggghts";#' constant/couplingProperties
cp_noVoidFraction     | error:voidFraction                       | solver | sed -i '/^voidFraction /d' constant/couplingProperties
cp_badVoidFraction    | error:Unknown voidFraction model centroid;centre | solver | sed -i 's/^voidFraction .*/voidFraction centroid;/' constant/couplingProperties
cp_noMinVoidFraction  | error:minVoidFraction                    | solver | sed -i '/^minVoidFraction /d' constant/couplingProperties
cp_minVoidFraction0   | error:minVoidFraction 0;> 0 and < 1      | solver | sed -i 's/^minVoidFraction .*/minVoidFraction 0;/' constant/couplingProperties
cp_minVoidFraction1   | error:minVoidFraction 1;> 0 and < 1      | solver | sed -i 's/^minVoidFraction .*/minVoidFraction 1;/' constant/couplingProperties
cp_minVoidFractionWord| error:minVoidFraction                    | solver | sed -i 's/^minVoidFraction .*/minVoidFraction low;/' constant/couplingProperties
cp_noForces           | error:forces                             | solver | sed -i '/^forces /d' constant/couplingProperties
cp_forcesEmpty        | warn:lists no force model                | solver | sed -i 's/^forces .*/forces ( );/' constant/couplingProperties
cp_forceUnknown       | error:Unknown forces model buoyancy;pressureGradient | solver | sed -i 's/^forces .*/forces ( DiFeliceDrag buoyancy );/' constant/couplingProperties
cp_forceTwice         | error:listed twice                       | solver | sed -i 's/^forces .*/forces ( DiFeliceDrag DiFeliceDrag );/' constant/couplingProperties
cp_forceLift          | ok                                       | solver | sed -i 's/^forces .*/forces ( DiFeliceDrag pressureGradient SaffmanLift MagnusLift );/' constant/couplingProperties
cp_viscousNoScheme    | error:div((mu*dev2(T(grad(U)))));fvSchemes | solver | sed -i 's/^forces .*/forces ( DiFeliceDrag pressureGradient viscousForce );/' constant/couplingProperties
cp_noMomentumCoupling | error:momentumCoupling                    | solver | sed -i '/^momentumCoupling /d' constant/couplingProperties
cp_badMomentumCoupling| error:Unknown momentumCoupling model implicit;semiImplicit | solver | sed -i 's/^momentumCoupling .*/momentumCoupling implicit;/' constant/couplingProperties
cp_explicitCoupling   | ok                                       | solver | sed -i 's/^momentumCoupling .*/momentumCoupling explicit;/' constant/couplingProperties
cp_unknownKeyword     | error:Unknown keyword 'minVoidfraction';Did you mean 'minVoidFraction' | solver | echo 'minVoidfraction 0.3;' >> constant/couplingProperties
cp_floorTreatmentBad  | error:voidFractionFloor;spil;clip;spill | solver | echo 'voidFractionFloor spil;' >> constant/couplingProperties
cp_floorSpill         | ok                                       | solver | echo 'voidFractionFloor spill;' >> constant/couplingProperties
cp_demDragBad         | error:demDrag 'sometimes';implicit       | solver | echo 'demDrag sometimes;' >> constant/couplingProperties
cp_demDragExplicit    | ok                                       | solver | echo 'demDrag explicit;' >> constant/couplingProperties
cp_outsideBad         | error:outsideParticles 'drop';delete     | solver | echo 'outsideParticles drop;' >> constant/couplingProperties
cp_fluidVelocityBad   | error:fluidVelocity 'centre';cellPoint;grainTop | solver | echo 'fluidVelocity centre;' >> constant/couplingProperties
cp_cellPoint          | ok                                       | solver | echo 'fluidVelocity cellPoint;' >> constant/couplingProperties
cp_grainTop           | ok                                       | solver | echo 'fluidVelocity grainTop;' >> constant/couplingProperties
cp_exchangeBad        | error:Unknown exchange model fast;manyToMany | solver | echo 'exchange fast;' >> constant/couplingProperties
cp_centre             | ok                                       | solver | sed -i 's/^voidFraction .*/voidFraction centre;/' constant/couplingProperties
cp_vsNoCoeffs         | error:virtualSphereCoeffs                | solver | sed -i 's/^voidFraction .*/voidFraction virtualSphere;/' constant/couplingProperties
cp_virtualSphere      | ok                                       | solver | sed -i 's/^voidFraction .*/voidFraction virtualSphere;/' constant/couplingProperties; echo 'virtualSphereCoeffs { diameterRatio 4; sizeThreshold 0.25; }' >> constant/couplingProperties
cp_vsRatio            | error:diameterRatio 0.5;>= 1             | solver | sed -i 's/^voidFraction .*/voidFraction virtualSphere;/' constant/couplingProperties; echo 'virtualSphereCoeffs { diameterRatio 0.5; sizeThreshold 0.25; }' >> constant/couplingProperties
cp_vsThreshold0       | error:sizeThreshold 0;> 0                | solver | sed -i 's/^voidFraction .*/voidFraction virtualSphere;/' constant/couplingProperties; echo 'virtualSphereCoeffs { diameterRatio 4; sizeThreshold 0; }' >> constant/couplingProperties
cp_vsTypo             | error:Unknown keyword 'diameterratio';Did you mean 'diameterRatio' | solver | sed -i 's/^voidFraction .*/voidFraction virtualSphere;/' constant/couplingProperties; echo 'virtualSphereCoeffs { diameterratio 4; sizeThreshold 0.25; }' >> constant/couplingProperties
cp_diffusion          | ok                                       | solver | sed -i 's/^voidFraction .*/voidFraction diffusion;/' constant/couplingProperties; echo 'diffusionCoeffs { bandwidth 0.003; nSteps 2; }' >> constant/couplingProperties
cp_diffusionBandwidth | error:bandwidth -0.003;> 0              | solver | sed -i 's/^voidFraction .*/voidFraction diffusion;/' constant/couplingProperties; echo 'diffusionCoeffs { bandwidth -0.003; nSteps 2; }' >> constant/couplingProperties
cp_diffusionSteps0    | error:nSteps 0;>= 1                      | solver | sed -i 's/^voidFraction .*/voidFraction diffusion;/' constant/couplingProperties; echo 'diffusionCoeffs { bandwidth 0.003; nSteps 0; }' >> constant/couplingProperties
cp_fluctuation        | ok                                       | solver | echo 'velocityFluctuation { intensity 0.5; eddyTime 0.01; }' >> constant/couplingProperties
cp_fluctIntensity     | error:intensity -0.1;>= 0                | solver | echo 'velocityFluctuation { intensity -0.1; eddyTime 0.1; }' >> constant/couplingProperties
cp_fluctNoEddyTime    | error:eddyTime                           | solver | echo 'velocityFluctuation { intensity 0.5; }' >> constant/couplingProperties
cp_fluctEddyTime0     | error:eddyTime 0;> 0                     | solver | echo 'velocityFluctuation { intensity 0.5; eddyTime 0; }' >> constant/couplingProperties
cp_fluctSeed          | error:seed -1;>= 0                       | solver | echo 'velocityFluctuation { intensity 0.5; eddyTime 0.1; seed -1; }' >> constant/couplingProperties
dem_timestep0         | error:timestep 0;must be > 0             | solver | sed -i 's/^timestep .*/timestep 0/' DEM/in.settings
dem_timestepNeg       | error:timestep                           | solver | sed -i 's/^timestep .*/timestep -1e-5/' DEM/in.settings
dem_diameter0         | error:diameter 0;diameter > 0            | solver | sed -i 's/diameter 0.001/diameter 0/' DEM/in.liggghts
dem_diameterNeg       | error:LIGGGHTS stopped with an error;Invalid diameter;in.liggghts line | solver | sed -i 's/diameter 0.001/diameter -0.001/' DEM/in.liggghts
dem_diameterHuge      | error:does not fit in the domain;0.2     | solver | sed -i 's/diameter 0.001/diameter 0.2/' DEM/in.liggghts
dem_diameterCells     | warn:was measured at                     | solver | sed -i 's/diameter 0.001/diameter 0.006/' DEM/in.liggghts
dem_density0          | error:density                            | solver | sed -i 's/density 2500/density 0/' DEM/in.liggghts
dem_noSet             | error:does not fit in the domain         | solver | sed -i '/^set /d' DEM/in.liggghts
dem_noNve             | warn:no time-integration fix             | solver | sed -i '/nve\/sphere/d' DEM/in.settings
dem_noCoupleFix       | error:couple/cfd;in.liggghts             | solver | sed -i '/couple\/cfd couple_every/d' DEM/in.settings
dem_noForceFix        | error:couple/cfd/force;in.liggghts       | solver | sed -i '/couple\/cfd\/force/d' DEM/in.settings
dem_oldForceFix       | warn:DEM drag: explicit (the DEM script  | solver | sed -i 's#couple/cfd/force/implicit#couple/cfd/force#' DEM/in.settings
dem_oldForceImplicit  | error:demDrag implicit;couple/cfd/force/implicit | solver | sed -i 's#couple/cfd/force/implicit#couple/cfd/force#' DEM/in.settings; echo 'demDrag implicit;' >> constant/couplingProperties
dem_coupleEvery5      | error:couple_every 5;10 DEM steps        | solver | sed -i 's/couple_every 10/couple_every 5/' DEM/in.settings
dem_coupleFile        | error:couple_every <N> mpi               | solver | sed -i 's/couple_every 10 mpi/couple_every 10 file/' DEM/in.settings
dem_coupleEvery0      | error:couple_every                       | solver | sed -i 's/couple_every 10/couple_every 0/' DEM/in.settings
dem_pairTypo          | error:LIGGGHTS stopped with an error;Unknown command;DEM/in.settings line | solver | sed -i 's/^pair_coeff .*/pair_coef * */' DEM/in.settings
dem_pairModelBad      | error:LIGGGHTS stopped with an error     | solver | sed -i 's/^pair_style .*/pair_style gran model hooke2 tangential history/' DEM/in.settings
dem_noPairStyle       | error:LIGGGHTS stopped with an error     | solver | sed -i '/^pair_style /d; /^pair_coeff /d' DEM/in.settings
dem_noGravity         | ok                                       | solver | sed -i '/^fix *gravi /d' DEM/in.settings
dem_youngs0           | error:youngsModulus 0;must be > 0        | solver | sed -i 's/youngsModulus peratomtype .*/youngsModulus peratomtype 0/' DEM/in.settings
dem_restitution2      | error:LIGGGHTS stopped with an error;coefficientRestitution | solver | sed -i 's/coefficientRestitution peratomtypepair 1 .*/coefficientRestitution peratomtypepair 1 2/' DEM/in.settings
dem_noMaterial        | error:LIGGGHTS stopped with an error     | solver | sed -i '/property\/global/d' DEM/in.settings
dem_velocityInf       | error:non-finite position;DEM blew up    | solver | sed -i 's/^velocity .*/velocity all set 0 0 -1e400 units box/' DEM/in.liggghts
dem_velocityFast      | any                                      | solver | sed -i 's/^velocity .*/velocity all set 0 0 -50 units box/' DEM/in.liggghts
dem_atomOutside       | any                                      | solver | sed -i 's/^create_atoms .*/create_atoms 1 single 0.01 0.01 0.5 units box/' DEM/in.liggghts
dem_boxSmall          | error:does not cover the fluid mesh      | solver | sed -i 's/^region .*/region box block 0 0.02 0 0.02 0 0.1 units box/; s/^create_atoms .*/create_atoms 1 single 0.01 0.01 0.05 units box/' DEM/in.liggghts
dem_missingInclude    | error:Cannot open the DEM script;in.nothere | solver | sed -i 's#^include .*#include DEM/in.nothere#' DEM/in.liggghts
dem_unknownVariable   | error:LIGGGHTS stopped with an error     | solver | sed -i 's/^variable *zp .*/variable zp equal z[1]*${nothere}/' DEM/in.settings
cd_deltaT0            | error:deltaT 0;> 0                       | solver | foamDictionary -entry deltaT -set 0 system/controlDict
cd_deltaTNeg          | error:deltaT -0.0001;> 0                 | solver | foamDictionary -entry deltaT -set -1e-4 system/controlDict
cd_deltaTNotWhole     | error:not a whole number of DEM steps    | solver | foamDictionary -entry deltaT -set 1.5e-5 system/controlDict
cd_writeInterval0     | error:writeInterval 0;> 0                | solver | foamDictionary -entry writeInterval -set 0 system/controlDict
cd_writeIntervalNeg   | error:writeInterval -0.001;> 0           | solver | foamDictionary -entry writeInterval -set -1e-3 system/controlDict
cd_endTime0           | ok                                       | solver | foamDictionary -entry endTime -set 0 system/controlDict
cd_endTimeNeg         | any                                      | solver | foamDictionary -entry endTime -set -1 system/controlDict
cd_writeControlBad    | error:writeControl                       | solver | foamDictionary -entry writeControl -set sometimes system/controlDict
cd_maxCo0             | error:maxCo 0;> 0                        | solver | foamDictionary -entry adjustTimeStep -set yes system/controlDict; foamDictionary -entry maxCo -set 0 system/controlDict
cd_adjustable         | ok                                       | solver | foamDictionary -entry adjustTimeStep -set yes system/controlDict; foamDictionary -entry maxDeltaT -set 2e-4 system/controlDict
cd_hugeStep           | any                                      | solver | foamDictionary -entry deltaT -set 0.05 system/controlDict; foamDictionary -entry endTime -set 0.5 system/controlDict; foamDictionary -entry writeInterval -set 0.1 system/controlDict; sed -i 's/couple_every 10/couple_every 5000/' DEM/in.settings
tp_rho0               | error:rho 0;transportProperties;> 0     | solver | foamDictionary -entry water/rho -set 0 constant/transportProperties
tp_rhoAirNeg          | error:rho -1;transportProperties;> 0    | solver | foamDictionary -entry air/rho -set -1 constant/transportProperties
tp_nuNeg              | error:nu -1e-06;transportProperties;> 0 | solver | foamDictionary -entry water/nu -set -1e-06 constant/transportProperties
tp_nu0                | error:nu 0;transportProperties;> 0      | solver | foamDictionary -entry air/nu -set 0 constant/transportProperties
tp_sigmaNeg           | error:sigma -0.07;>= 0                  | solver | foamDictionary -entry sigma -set -0.07 constant/transportProperties
tp_rhoWord            | error:rho                               | solver | foamDictionary -entry water/rho -set heavy constant/transportProperties
g_huge                | error:Gravity;at most 2000              | solver | sed -i 's/^value .*/value (0 0 -1e6);/' constant/g
g_zero                | any                                     | solver | sed -i 's/^value .*/value (0 0 0);/' constant/g
g_up                  | any                                     | solver | sed -i 's/^value .*/value (0 0 9.81);/' constant/g
U_huge                | error:initial field U;1e+30;at most 1000 | solver | sed -i 's/^internalField .*/internalField uniform (0 0 1e30);/' 0/U
U_nan                 | any                                     | solver | sed -i 's/^internalField .*/internalField uniform (0 0 nan);/' 0/U
p_rgh_huge            | any                                     | solver | sed -i 's/^internalField .*/internalField uniform 1e300;/' 0/p_rgh
alpha_two             | any                                     | solver | sed -i 's/^internalField .*/internalField uniform 2;/' 0/alpha.water
mesh_oneCellWide      | any                                     | mesh   | sed -i 's/^nx .*/nx 1;/; s/^ny .*/ny 1;/' system/blockMeshDict
mesh_coarse           | ok                                      | mesh   | sed -i 's/^nx .*/nx 2;/; s/^ny .*/ny 2;/; s/^nz .*/nz 10;/' system/blockMeshDict
dem_poisson           | error:poissonsRatio 0.7                 | solver | sed -i 's/poissonsRatio peratomtype .*/poissonsRatio peratomtype 0.7/' DEM/in.settings
EOF
)

# The well-set case, meshed once
setupBase()
{
    rm -rf "$fuzzDir"
    mkdir -p "$fuzzDir"
    cp -r "$INTERDEMFOAM_TUTORIALS/singleParticleSettling" "$base"
    cd "$base" || fail "cannot enter $base"
    ./Allclean > /dev/null 2>&1
    narrowSettlingColumn
    setEntry system/controlDict endTime 2e-3
    setEntry system/controlDict writeInterval 1e-3
    restore0Dir > /dev/null
    runApplication blockMesh || fail "blockMesh of the base case"
    runApplication setFields || fail "setFields of the base case"
}

# one <name>: apply the mutation in a copy of the base case, run, judge;
# writes <name>/verdict: "<name> <class> <PASS|FAIL> <why>"
runOne()
{
    local name="$1" line expect stage edit
    line=$(echo "$MUTATIONS" | awk -F'|' -v n="$name" '{ k = $1; gsub(/ /, "", k) } k == n')
    [ -n "$line" ] || fail "no mutation $name"
    expect=$(echo "$line" | cut -d'|' -f2 | sed 's/^ *//; s/ *$//')
    stage=$(echo "$line" | cut -d'|' -f3 | tr -d ' ')
    edit=$(echo "$line" | cut -d'|' -f4- | sed 's/^ *//')

    local dir="$fuzzDir/$name"
    rm -rf "$dir"
    cp -r "$base" "$dir"
    cd "$dir" || exit 1
    rm -f log.*
    bash -c "$edit" > log.edit 2>&1 || { echo "$name setup FAIL the edit failed: $edit" > verdict; return; }

    local rc=0
    : > log.run
    if [ "$stage" = mesh ]
    then
        rm -rf 0 && cp -r 0.orig 0
        for app in blockMesh setFields
        do
            timeout 60 "$app" >> log.run 2>&1 < /dev/null
            rc=$?
            [ $rc -eq 0 ] || break
        done
    fi
    if [ $rc -eq 0 ]
    then
        timeout 60 interDemFoam >> log.run 2>&1 < /dev/null
        rc=$?
    fi

    local class
    if [ $rc -eq 0 ]
    then
        grep -q "^End" log.run && class=exit0 || class=silentAbort
    elif [ $rc -eq 124 ]
    then
        class=hang
    elif [ $rc -ge 128 ]
    then
        class=signal
    elif [ $rc -eq 1 ] && grep -q -- "--> FOAM FATAL" log.run
    then
        class=clearError
    else
        class=silentAbort
    fi

    local verdict=PASS why=""
    case "$class" in
        exit0|clearError) ;;
        *) verdict=FAIL; why="exit $rc" ;;
    esac
    local kind="${expect%%:*}" pats=""
    [ "$kind" != "$expect" ] && pats="${expect#*:}"
    if [ $verdict = PASS ]
    then
        case "$kind" in
            ok)    [ $class = exit0 ] || { verdict=FAIL; why="expected exit 0"; } ;;
            warn)  [ $class = exit0 ] || { verdict=FAIL; why="expected exit 0 with a warning"; } ;;
            error) [ $class = clearError ] || { verdict=FAIL; why="expected a clear error"; } ;;
            any)   ;;
            *)     verdict=FAIL; why="unknown expectation '$expect'" ;;
        esac
    fi
    if [ $verdict = PASS ] && [ -n "$pats" ]
    then
        local IFS=';' p
        for p in $pats
        do
            grep -q -F -- "$p" log.run || { verdict=FAIL; why="no '$p' in the log"; break; }
        done
    fi
    echo "$name $class $verdict $why" > verdict
}

if [ "$1" = one ]
then
    runOne "$2"
    cat "$fuzzDir/$2/verdict"
    exit 0
fi

setupBase
# the well-set case runs (else the errors would prove nothing)
cp -r "$base" "$fuzzDir/wellSet"
(cd "$fuzzDir/wellSet" && timeout 120 interDemFoam > log.run 2>&1 < /dev/null) \
    || fail "the well-set case fails ($fuzzDir/wellSet/log.run)"
grep -q "^End" "$fuzzDir/wellSet/log.run" || fail "the well-set case did not end"
! grep -q "^Warning" "$fuzzDir/wellSet/log.run" \
    || fail "the well-set case warns: $(grep -m1 '^Warning' "$fuzzDir/wellSet/log.run")"

names=$(echo "$MUTATIONS" | awk -F'|' '{ k = $1; gsub(/ /, "", k); print k }')
n=$(echo "$names" | wc -l)
[ "$n" -ge 60 ] || fail "only $n mutations (at least 60)"
[ "$(echo "$names" | sort | uniq -d)" = "" ] || fail "a mutation name twice"

start=$(date +%s)
echo "$names" | xargs -P 2 -I{} bash "$self" one {} > /dev/null
echo "ran $n mutations in $(( $(date +%s) - start )) s"

results=$(cat "$fuzzDir"/*/verdict 2>/dev/null)
[ "$(echo "$results" | wc -l)" -eq "$n" ] || fail "verdicts of $(echo "$results" | wc -l) mutations, expected $n"
for c in exit0 clearError signal hang silentAbort
do
    printf "%-12s %3d\n" "$c" "$(echo "$results" | awk -v c=$c '$2 == c' | wc -l)"
done
failed=$(echo "$results" | awk '$3 != "PASS"')
if [ -n "$failed" ]
then
    echo "$failed"
    fail "$(echo "$failed" | wc -l) of $n mutations failed (logs: $fuzzDir/<name>/log.run)"
fi
pass "$n mutations: each ended with exit 0 or a clear error, as expected"
