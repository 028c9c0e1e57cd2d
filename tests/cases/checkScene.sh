#!/bin/bash
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#------------------------------------------------------------------------------
# checkDemScene, the scene check before a run (docs/sceneCheck.md), on the
# single-particle settling case (d = 1 mm):
#   - a known failure region: the centre model with cells of d (20 x 20 x
#     200 cells of 1 mm): exit 1, a FAIL line naming centre and the stability
#     run that failed at dx/d = 1, nothing written in the case;
#   - a safe scene: the virtual sphere with cells of 2 d: exit 0, no FAIL,
#     and its predictions: the terminal velocity it derives (0.134 m/s, the
#     eq. 19 value 0.1341 within 1 %) and the virtual sphere's expected
#     error at dx/d = 2 (0.74 %, the mesh study's value);
#   - a coupling step in the measured blow-up region of explicit DEM drag
#     (deltaT 0.5 s = 3.6 tau_p): exit 1 naming the coupling step;
#   - the bed's expected Shields number (-shields) against the measured
#     onsets of bedload (etc/sceneMaps/bedloadOnset.dat: laminar 0.4-0.5,
#     k-omega SST 0.07-0.08 with the bedload tutorial's default grain-side
#     model, docs/erosion.md): at 0.35 this laminar case gets a WARN that a
#     turbulent run would move the bed and a laminar one not, naming that
#     model's settings (exit 0); control: at 0.05 "laminar flow is
#     enough", no such WARN;
#   - bad input: a missing DEM script: a clear error naming the script and
#     the keyword, no crash.
# Reference: the measured maps checkDemScene reads (the cell-size study's
# meshStudy.dat, the stability map and the drag-stability runs) and eq. 19,
# 0.1341 m/s. Measured: 0.134 m/s and 0.74 %, as the maps give them; the
# explicit drag's blow-up named at 1.8 tau_p (docs/sceneCheck.md).
#------------------------------------------------------------------------------
. "${0%/*}/caseFunctions.sh"

copyTutorial singleParticleSettling checkScene
cp -r 0.orig 0

# check <name> <expected exit> <pattern>...: run checkDemScene, compare
check_scene()
{
    local name="$1" expected="$2"; shift 2
    timeout 120 checkDemScene "${extra[@]}" > "log.$name" 2>&1 < /dev/null
    local rc=$?
    [ $rc -ne 124 ] || fail "$name: checkDemScene hung"
    [ $rc -lt 128 ] || fail "$name: checkDemScene crashed (signal $((rc - 128)))"
    [ $rc -eq "$expected" ] || fail "$name: exit $rc, expected $expected (log.$name)"
    for pat in "$@"
    do
        grep -q -- "$pat" "log.$name" || fail "$name: no '$pat' in log.$name"
    done
    echo "ok: $name (exit $rc)"
}

# 1. centre at dx = d: the measured failure region
sed -i 's/^Lx .*/Lx  0.02;/; s/^Ly .*/Ly  0.02;/; s/^nx .*/nx  20;/; s/^ny .*/ny  20;/; s/^nz .*/nz  200;/' \
    system/blockMeshDict
sed -i 's/^region .*/region          box block 0 0.02 0 0.02 0 0.2 units box/;
        s/^create_atoms .*/create_atoms    1 single 0.0105 0.0105 0.15 units box/' DEM/in.liggghts
runApplication blockMesh || fail "blockMesh"
setEntry constant/couplingProperties voidFraction centre
before=$(find . -newer log.blockMesh -type f | grep -v '^./log\.' | sort | md5sum)
extra=()
check_scene centreAtD 1 "FAIL  voidFraction centre: its stability run failed at dx/d = 1" \
    "d/dx              min 1, median 1, max 1"
after=$(find . -newer log.blockMesh -type f | grep -v '^./log\.' | sort | md5sum)
[ "$before" = "$after" ] || fail "checkDemScene wrote into the case"

# 2. the virtual sphere at dx = 2 d: safe
sed -i 's/^nx .*/nx  10;/; s/^ny .*/ny  10;/; s/^nz .*/nz  100;/' system/blockMeshDict
runApplication -o blockMesh || fail "blockMesh"
setEntry constant/couplingProperties voidFraction virtualSphere
echo "virtualSphereCoeffs { diameterRatio 4; sizeThreshold 0.25; }" >> constant/couplingProperties
check_scene virtualSphere2d 0 "checkDemScene: ok" "d/dx              min 0.5, median 0.5, max 0.5"
! grep -q "FAIL " log.virtualSphere2d || fail "virtualSphere2d: a FAIL line"
v=$(sed -n 's/.*particle Courant  [^ ]* at \([^ ]*\) m\/s (terminal velocity.*/\1/p' log.virtualSphere2d)
check "terminal velocity the check derives" "$v" 'v > 0.99*0.1341 && v < 1.01*0.1341' \
    "terminal velocity $v m/s, eq. 19 gives 0.1341 m/s"
e=$(awk '$1 == "*" && $2 == "virtualSphere" { print $3 }' log.virtualSphere2d)
check "virtual sphere's expected error at dx/d = 2" "$e" 'v > 0.73 && v < 0.75' \
    "expected error '$e' %, the mesh study measured 0.74 % at dx/d = 2"

# 3. a coupling step in explicit drag's measured blow-up region
setEntry constant/couplingProperties demDrag explicit
sed -i 's/couple\/cfd\/force\/implicit/couple\/cfd\/force/' DEM/in.liggghts
setEntry system/controlDict deltaT 0.5
check_scene couplingStep 1 "FAIL  the coupling step is 3.6 tau_p: the explicit DEM drag blew up at 1.8 tau_p"
setEntry system/controlDict deltaT 1e-4
setEntry constant/couplingProperties demDrag implicit
sed -i 's/couple\/cfd\/force /couple\/cfd\/force\/implicit /; s/couple\/cfd\/force$/couple\/cfd\/force\/implicit/' DEM/in.liggghts

# 4. the bed's Shields number against the measured onsets of bedload
#    (etc/sceneMaps/bedloadOnset.dat: laminar 0.4-0.5, k-omega SST 0.07-0.08
#    with the bedload tutorial's default grain-side model): this laminar
#    case at 0.35 moves no grain where a turbulent one would (WARN naming
#    that model's settings, exit 0); control: at 0.05 no model moves the
#    bed, laminar is enough (no such warning)
extra=(-shields 0.35)
check_scene shieldsBetween 0 "WARN  the bed's Shields number 0.35 lies between the turbulent onset of bedload (0.07-0.08, kOmegaSST) and the laminar one (0.4-0.5)" \
    "sampledAt cellAbove; }, fluidVelocity grainTop"
extra=(-shields 0.05)
check_scene shieldsLow 0 "laminar flow is enough: no measured model moves a bed at theta 0.05"
! grep -q "WARN  the bed's Shields number" log.shieldsLow \
    || fail "shieldsLow: warned about the bed's Shields number at 0.05"
extra=()

# 5. bad input: the DEM script is missing
setEntry constant/couplingProperties demScript '"DEM/in.nothere"'
timeout 120 checkDemScene > log.missingScript 2>&1 < /dev/null
rc=$?
[ $rc -ne 0 ] || fail "missingScript: checkDemScene succeeded"
[ $rc -ne 124 ] && [ $rc -lt 128 ] || fail "missingScript: hung or crashed (exit $rc)"
grep -q "in.nothere" log.missingScript && grep -q "demScript" log.missingScript \
    || fail "missingScript: the error names neither the script nor the keyword"
echo "ok: missingScript ($(grep -m1 'in.nothere' log.missingScript | sed 's/^ *//' | cut -c1-100))"

ls -d "${TMPDIR:-/tmp}"/checkDemScene.* > /dev/null 2>&1 \
    && fail "a scratch folder checkDemScene.* was left in ${TMPDIR:-/tmp}"

pass "checkDemScene: failure region, safe scene, blow-up step, the bed's Shields number and missing script as measured"
