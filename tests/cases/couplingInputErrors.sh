#!/bin/bash
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#------------------------------------------------------------------------------
# Mis-set coupled cases stop with a clear message that names the file and
# the keyword (never a crash, a hang or a silent default):
#   - the DEM script lacks 'fix ... couple/cfd/force'
#   - couple_every differs from deltaT/timestep (fixed steps)
#   - deltaT is not a whole number of DEM steps
#   - the DEM script does not exist
#   - an unknown voidFraction / momentumCoupling / force model (the valid
#     names are listed)
#   - a restart from a time at which every particle had left (no DEM state)
#   - a case written before demDrag existed (couple/cfd/force, no demDrag)
#     runs with explicit drag, says so in one 'DEM drag:' line, and gives
#     a particle history identical (cmp) to the same case with demDrag
#     explicit; demDrag implicit with that fix stops naming both
#   - an error LIGGGHTS reports in a 2-rank run (Error::one, which calls
#     MPI_Abort) ends with its message, the command and its script line
#   - and the rest of docs/reliability.md's table of bad inputs (46 runs in
#     all:
#     'did you mean' for misspelt keywords, wrong types, ranges, missing
#     sub-dictionaries, file coupling, a DEM box smaller than the mesh,
#     restarts without demRestartScript or DEM state, a non-finite particle
#     also on 2 ranks, bad fluidVelocity and velocityFluctuation values,
#     eddyLifetime, size or sampledAt outside source turbulence or not a
#     known word, WibergSmithLift without liftCoefficient, out of range or
#     without gravity)
#     and its warnings (Rayleigh time, particles outside the mesh);
#   - the output guard: 3000 identical LIGGGHTS lines run to the end, 12000
#     are stopped.
# Reference: the messages quoted in docs/reliability.md. Measured: each stops
# non-zero within 120 s with its message (or warns and runs on); on 2 ranks
# the non-finite particle ends both ranks, exit 1 after 1 s.
#------------------------------------------------------------------------------
. "${0%/*}/caseFunctions.sh"

copyTutorial singleParticleSettling couplingInputErrors
narrowSettlingColumn
setEntry system/controlDict endTime 3e-4
setEntry system/controlDict writeInterval 1e-4
restore0Dir > /dev/null
runApplication blockMesh || fail "blockMesh"
runApplication setFields || fail "setFields"
cp DEM/in.liggghts DEM/in.liggghts.good
cp DEM/in.settings DEM/in.settings.good
cp constant/couplingProperties couplingProperties.good
cp system/controlDict controlDict.good

# expectError <name> <pattern>...: the solver fails and prints every pattern
expectError()
{
    local name="$1"; shift
    timeout 120 interDemFoam > "log.$name" 2>&1 < /dev/null
    local rc=$?
    [ $rc -ne 0 ] || fail "$name: the run succeeded"
    [ $rc -ne 124 ] || fail "$name: the run hung"
    [ $rc -lt 128 ] || fail "$name: the run crashed (signal $((rc - 128)))"
    for pat in "$@"
    do
        grep -q -- "$pat" "log.$name" || fail "$name: no '$pat' in log.$name"
    done
    echo "ok: $name ($(grep -m1 -A1 -- "$1" "log.$name" | head -n 1 | cut -c1-100))"
    cp DEM/in.liggghts.good DEM/in.liggghts
    cp DEM/in.settings.good DEM/in.settings
    cp couplingProperties.good constant/couplingProperties
    cp controlDict.good system/controlDict
}

# expectWarning <name> <pattern>...: the solver runs to the end and prints
# every pattern (guards that warn and go on)
expectWarning()
{
    local name="$1"; shift
    timeout 120 interDemFoam > "log.$name" 2>&1 < /dev/null \
        || fail "$name: the run failed (log.$name)"
    grep -q "^End" "log.$name" || fail "$name: the run did not end"
    for pat in "$@"
    do
        grep -q -- "$pat" "log.$name" || fail "$name: no '$pat' in log.$name"
    done
    echo "ok: $name ($(grep -m1 -- "$1" "log.$name" | cut -c1-100))"
    cp DEM/in.liggghts.good DEM/in.liggghts
    cp DEM/in.settings.good DEM/in.settings
    cp couplingProperties.good constant/couplingProperties
    cp controlDict.good system/controlDict
    [ -n "$keepTimes" ] || rm -rf 0.000[1-9]*
}

# the well-set case runs (else the errors below would prove nothing)
timeout 300 interDemFoam > log.good 2>&1 < /dev/null || fail "the well-set case fails (log.good)"
grep -q "^End" log.good || fail "the well-set case did not end"

sed -i '/couple\/cfd\/force/d' DEM/in.settings
expectError noForceFix "couple/cfd/force" "in.liggghts"

sed -i 's/couple_every 10/couple_every 5/' DEM/in.settings
expectError coupleEveryMismatch "couple_every 5" "10 DEM steps" "in.liggghts"

setEntry system/controlDict deltaT 1.5e-5
expectError deltaTNotWhole "not a whole number of DEM steps" "controlDict"

sed -i 's#DEM/in.liggghts#DEM/missing.liggghts#' constant/couplingProperties
expectError noScript "Cannot open the DEM script" "missing.liggghts" "demScript"

sed -i 's/^voidFraction .*/voidFraction      centroid;/' constant/couplingProperties
expectError badVoidFraction "centroid" "voidFraction" "centre" "divided" "couplingProperties"

sed -i 's/^momentumCoupling .*/momentumCoupling  implicit;/' constant/couplingProperties
expectError badMomentumCoupling "implicit" "momentumCoupling" "semiImplicit" "couplingProperties"

sed -i 's/^forces .*/forces ( DiFeliceDrag buoyancy );/' constant/couplingProperties
expectError badForce "buoyancy" "pressureGradient" "couplingProperties"

# couplingProperties: keywords, types, ranges, sub-dictionaries
echo "minVoidfraction 0.3;" >> constant/couplingProperties
expectError unknownKeyword "Unknown keyword 'minVoidfraction'" "Did you mean 'minVoidFraction'" "couplingProperties"

sed -i 's/^minVoidFraction .*/minVoidFraction   low;/' constant/couplingProperties
expectError wrongType "minVoidFraction" "couplingProperties"

sed -i 's/^minVoidFraction .*/minVoidFraction   0;/' constant/couplingProperties
expectError floorOutOfRange "minVoidFraction 0" "> 0 and < 1" "couplingProperties"

sed -i 's/^forces .*/forces ( DiFeliceDrag DiFeliceDrag );/' constant/couplingProperties
expectError forceTwice "listed twice" "forces"

sed -i '/^forces /d' constant/couplingProperties
expectError noForces "forces" "couplingProperties"

sed -i 's/^voidFraction .*/voidFraction      virtualSphere;/' constant/couplingProperties
expectError noVirtualSphereCoeffs "virtualSphereCoeffs" "couplingProperties"

sed -i 's/^voidFraction .*/voidFraction      virtualSphere;/' constant/couplingProperties
echo "virtualSphereCoeffs { diameterRatio 0.5; sizeThreshold 0.25; }" >> constant/couplingProperties
expectError diameterRatioRange "diameterRatio 0.5" ">= 1" "virtualSphereCoeffs"

sed -i 's/^voidFraction .*/voidFraction      diffusion;/' constant/couplingProperties
echo "diffusionCoeffs { bandwidth -0.003; nSteps 3; }" >> constant/couplingProperties
expectError negativeBandwidth "bandwidth -0.003" "> 0" "diffusionCoeffs"

echo "outsideParticles drop;" >> constant/couplingProperties
expectError badOutsidePolicy "outsideParticles 'drop'" "ignore" "delete"

echo "fluidVelocity centre;" >> constant/couplingProperties
expectError badFluidVelocity "fluidVelocity 'centre'" "voidFractionAverage" "cellPoint" "grainTop" "couplingProperties"

echo "velocityFluctuation { intensity -0.1; eddyTime 0.1; }" >> constant/couplingProperties
expectError negativeIntensity "intensity -0.1" ">= 0" "velocityFluctuation"

echo "velocityFluctuation { intensity 0.5; }" >> constant/couplingProperties
expectError noEddyTime "eddyTime" "velocityFluctuation"

echo "velocityFluctuation { intensity 0.5; eddytime 0.1; }" >> constant/couplingProperties
expectError misspeltEddyTime "Unknown keyword 'eddytime'" "intensity, eddyTime and seed" "velocityFluctuation"

echo "velocityFluctuation { intensity 0.5; eddyTime 0.1; seed -1; }" >> constant/couplingProperties
expectError negativeSeed "seed -1" ">= 0" "velocityFluctuation"

echo "velocityFluctuation { intensity 0.5; eddyTime 0.1; eddyLifetime turnover; }" >> constant/couplingProperties
expectError lifetimeWithFixed "Unknown keyword 'eddyLifetime'" "intensity, eddyTime and seed" "velocityFluctuation"

echo "velocityFluctuation { source turbulence; eddyLifetime longest; }" >> constant/couplingProperties
expectError unknownEddyLifetime "eddyLifetime 'longest'" "crossing" "turnover" "velocityFluctuation"

echo "velocityFluctuation { source turbulence; size energy; }" >> constant/couplingProperties
expectError unknownFluctuationSize "size 'energy'" "shearStress" "velocityFluctuation"

echo "velocityFluctuation { intensity 0.5; eddyTime 0.1; size shearStress; }" >> constant/couplingProperties
expectError sizeWithFixed "Unknown keyword 'size'" "intensity, eddyTime and seed" "velocityFluctuation"

echo "velocityFluctuation { source turbulence; sampledAt top; }" >> constant/couplingProperties
expectError unknownSampledAt "sampledAt 'top'" "average" "grainTop" "cellAbove" "velocityFluctuation"

echo "velocityFluctuation { intensity 0.5; eddyTime 0.1; sampledAt grainTop; }" >> constant/couplingProperties
expectError sampledAtWithFixed "Unknown keyword 'sampledAt'" "intensity, eddyTime and seed" "velocityFluctuation"

# the bed lift's coefficient: required, in range
sed -i 's/^forces .*/forces ( DiFeliceDrag WibergSmithLift );/' constant/couplingProperties
expectError liftNoCoefficient "WibergSmithLift needs liftCoefficient" "WibergSmithLiftCoeffs" "between 0 and 2"

sed -i 's/^forces .*/forces ( DiFeliceDrag WibergSmithLift );/' constant/couplingProperties
echo "WibergSmithLiftCoeffs { liftCoefficient 3; }" >> constant/couplingProperties
expectError liftCoefficientRange "liftCoefficient 3" "between 0 and 2" "WibergSmithLiftCoeffs"

# a grain's top and bottom are found against gravity: none, no lift
cp constant/g g.good
sed -i 's/^value .*/value           (0 0 0);/' constant/g
sed -i 's/^forces .*/forces ( DiFeliceDrag WibergSmithLift );/' constant/couplingProperties
echo "WibergSmithLiftCoeffs { liftCoefficient 0.2; }" >> constant/couplingProperties
expectError liftNoGravity "(WibergSmithLift)" "needs gravity" "constant/g"
cp g.good constant/g

# the DEM script and the mesh
sed -i 's/^region .*/region          box block 0 0.02 0 0.02 0 0.1 units box/' DEM/in.liggghts
sed -i 's/^create_atoms .*/create_atoms    1 single 0.01 0.01 0.05 units box/' DEM/in.liggghts
expectError demBoxTooSmall "does not cover the fluid mesh" "in.liggghts"

sed -i 's/couple_every 10 mpi/couple_every 10 file/' DEM/in.settings
expectError fileCoupling "couple_every <N> mpi" "in.settings"

sed -i 's/couple_every 10 mpi/couple_every ${n} mpi/' DEM/in.settings
expectError coupleEveryVariable "whole number" "in.settings"

sed -i 's/^include .*/include         DEM\/in.nothere/' DEM/in.liggghts
expectError missingInclude "Cannot open the DEM script" "in.nothere"

# restart
setEntry system/controlDict startFrom latestTime
sed -i '/^demRestartScript/d' constant/couplingProperties
expectError restartNoScript "demRestartScript" "read_restart"

setEntry system/controlDict startFrom latestTime
mv 0.0003/liggghts.restart 0.0003/liggghts.restart.kept
expectError restartNoDemState "Cannot restart at t = 0.0003 s" "0.0003/liggghts.restart"
mv 0.0003/liggghts.restart.kept 0.0003/liggghts.restart

# The output guard: a script may repeat a line a few thousand times (2880
# create_atoms lines each print "Created 1 atoms" in benchmarks/dpmFoam):
# 3000 repeats must run; 12000 (above the guard's 10000) must be stopped
for i in $(seq 3000); do echo 'print "the same line"'; done >> DEM/in.liggghts
timeout 120 interDemFoam > log.repeats3000 2>&1 < /dev/null \
    || fail "repeats3000: 3000 repeated lines stopped the run (log.repeats3000)"
grep -q "^End" log.repeats3000 || fail "repeats3000: the run did not end"
[ "$(grep -c '^the same line' log.liggghts)" -ge 3000 ] \
    || fail "repeats3000: fewer than 3000 repeated lines in log.liggghts"
echo "ok: repeats3000 (3000 identical lines in a row: the run ends)"
cp DEM/in.liggghts.good DEM/in.liggghts
rm -rf 0.000[1-9]*
for i in $(seq 12000); do echo 'print "the same line"'; done >> DEM/in.liggghts
expectError repeats12000 "LIGGGHTS wrote the same line more than 10000 times"

# A case written before demDrag existed (couple/cfd/force, no demDrag)
# runs with explicit drag, says so in one log line, and moves its particle
# exactly as the same case with demDrag explicit; demDrag implicit with the
# old fix still stops
sed -i 's#couple/cfd/force/implicit#couple/cfd/force#' DEM/in.settings
keepTimes=yes expectWarning oldCase "DEM drag: explicit (the DEM script" \
    "sets no demDrag"
[ "$(grep -c '^DEM drag:' log.oldCase)" -eq 1 ] \
    || fail "oldCase: not one 'DEM drag:' line"
cp particleHistory.dat particleHistory.oldCase
rm -rf 0.000[1-9]*
sed -i 's#couple/cfd/force/implicit#couple/cfd/force#' DEM/in.settings
echo "demDrag explicit;" >> constant/couplingProperties
expectWarning explicitSet "DEM drag: explicit"
cmp -s particleHistory.dat particleHistory.oldCase \
    || fail "oldCase: the particle history differs from demDrag explicit's"
[ "$(grep -vc '^#' particleHistory.oldCase)" -ge 3 ] \
    || fail "oldCase: fewer than 3 rows in particleHistory.dat"
echo "ok: oldCase moves its particle as demDrag explicit does ($(grep -vc '^#' particleHistory.oldCase) rows identical)"
sed -i 's#couple/cfd/force/implicit#couple/cfd/force#' DEM/in.settings
echo "demDrag implicit;" >> constant/couplingProperties
expectError oldFixImplicit "demDrag implicit" "couple/cfd/force/implicit" "couplingProperties"

# guards that warn and go on, and one that stops
sed -i 's/^timestep .*/timestep        5e-5/; s/couple_every 10/couple_every 2/' DEM/in.settings
expectWarning rayleighTime "Rayleigh time" "Use a timestep of at most 20 %"

sed -i 's/^region .*/region          box block 0 0.02 0 0.02 0 0.3 units box/' DEM/in.liggghts
sed -i 's/^create_atoms .*/create_atoms    1 single 0.01 0.01 0.25 units box/' DEM/in.liggghts
expectWarning outsideIgnored "particle(s) outside the fluid mesh" "outsideParticles ignore"

# two particles, one above the mesh: it is deleted, the other goes on
sed -i 's/^region .*/region          box block 0 0.02 0 0.02 0 0.3 units box/' DEM/in.liggghts
sed -i 's/^create_atoms .*/&\ncreate_atoms    1 single 0.01 0.01 0.25 units box/' DEM/in.liggghts
sed -i 's/^set             atom 1 .*/&\nset             atom 2 diameter 0.001 density 2500/' DEM/in.liggghts
echo "outsideParticles delete;" >> constant/couplingProperties
expectWarning outsideDeleted "Deleted 1 particle(s) outside the fluid mesh" "Particles: 1 in the DEM"
! grep -q "left the DEM domain" log.outsideDeleted \
    || fail "outsideDeleted: a deletion was also reported as a loss of LIGGGHTS"

# the only particle deleted: the DEM runs on empty
sed -i 's/^region .*/region          box block 0 0.02 0 0.02 0 0.3 units box/' DEM/in.liggghts
sed -i 's/^create_atoms .*/create_atoms    1 single 0.01 0.01 0.25 units box/' DEM/in.liggghts
echo "outsideParticles delete;" >> constant/couplingProperties
keepTimes=yes expectWarning outsideDeletedAll "Deleted 1 particle(s) outside the fluid mesh" "Particles: 0 in the DEM"
! grep -q "left the DEM domain" log.outsideDeletedAll \
    || fail "outsideDeletedAll: a deletion was also reported as a loss of LIGGGHTS"
# no DEM restart file when the DEM is empty: a marker says why, and a
# restart from that time stops with that reason (not a generic "missing")
[ -f 0.0003/liggghts.restart.emptied ] && [ ! -f 0.0003/liggghts.restart ] \
    || fail "outsideDeletedAll: no 0.0003/liggghts.restart.emptied marker"
setEntry system/controlDict startFrom latestTime
setEntry system/controlDict endTime 5e-4
expectError restartEmptied "every DEM particle had left the domain" \
    "liggghts.restart.emptied" "Cannot restart at t = 0.0003"
rm -rf 0.000[1-9]*

sed -i 's/^velocity .*/velocity        all set 0 0 -1e400 units box/' DEM/in.liggghts
expectError nonFiniteParticle "non-finite position" "DEM blew up"

# in parallel: an error ends every rank, with the message, and nothing hangs
rm -rf 0.000[1-9]* processor*
runApplication decomposePar -force > /dev/null || fail "decomposePar"
sed -i 's/^velocity .*/velocity        all set 0 0 -1e400 units box/' DEM/in.liggghts
start=$(date +%s)
timeout 120 mpirun --allow-run-as-root --oversubscribe -np 2 interDemFoam -parallel \
    > log.parallelError 2>&1 < /dev/null
rc=$?
[ $rc -ne 124 ] || fail "parallel error: the run hung"
[ $rc -ne 0 ] || fail "parallel error: the run succeeded"
grep -q "non-finite position" log.parallelError || fail "parallel error: no message"
echo "ok: parallelError (exit $rc after $(( $(date +%s) - start )) s, every rank ended)"
cp DEM/in.liggghts.good DEM/in.liggghts

# an error of LIGGGHTS itself (Error::one on every rank, which calls
# MPI_Abort): the run ends with LIGGGHTS's message, the command and its
# line in the script, not a bare MPI_ABORT
sed -i 's/^variable *zp .*/variable zp equal z[1]*${nothere}/' DEM/in.settings
timeout 120 mpirun --allow-run-as-root --oversubscribe -np 2 interDemFoam -parallel \
    > log.parallelLiggghts 2>&1 < /dev/null
rc=$?
[ $rc -ne 124 ] && [ $rc -ne 0 ] || fail "parallelLiggghts: hung or succeeded (exit $rc)"
for pat in "LIGGGHTS stopped with an error" "illegal variable" "DEM/in.settings line"
do
    grep -q -- "$pat" log.parallelLiggghts || fail "parallelLiggghts: no '$pat'"
done
echo "ok: parallelLiggghts ($(grep -m1 'DEM/in.settings line' log.parallelLiggghts | sed 's/^ *//'))"
cp DEM/in.settings.good DEM/in.settings

pass "coupled-case input errors are reported clearly"
