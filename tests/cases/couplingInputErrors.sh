#!/bin/bash
#------------------------------------------------------------------------------
# Mis-set coupled cases stop with a clear message that names the file and
# the keyword (never a crash, a hang or a silent default):
#   - the DEM script lacks 'fix ... couple/cfd/force'
#   - couple_every differs from deltaT/timestep (fixed steps)
#   - deltaT is not a whole number of DEM steps
#   - the DEM script does not exist
#   - an unknown voidFraction / momentumCoupling / force model (the valid
#     names are listed)
#------------------------------------------------------------------------------
. "${0%/*}/caseFunctions.sh"

copyTutorial singleParticleSettling couplingInputErrors
narrowSettlingColumn
setEntry system/controlDict endTime 3e-4
restore0Dir > /dev/null
runApplication blockMesh || fail "blockMesh"
runApplication setFields || fail "setFields"
cp DEM/in.liggghts DEM/in.liggghts.good
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
    cp couplingProperties.good constant/couplingProperties
    cp controlDict.good system/controlDict
}

# the well-set case runs (else the errors below would prove nothing)
timeout 300 interDemFoam > log.good 2>&1 < /dev/null || fail "the well-set case fails (log.good)"
grep -q "^End" log.good || fail "the well-set case did not end"

sed -i '/couple\/cfd\/force/d' DEM/in.liggghts
expectError noForceFix "couple/cfd/force" "in.liggghts"

sed -i 's/couple_every 10/couple_every 5/' DEM/in.liggghts
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

pass "coupled-case input errors are reported clearly"
