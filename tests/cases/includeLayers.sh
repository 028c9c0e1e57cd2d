#!/bin/bash
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#------------------------------------------------------------------------------
# The library's ground floor holds: no file of src/demCoupling includes a
# header of a room on its own floor or a higher one (bin/includeLayers:
# core 0; restart, locate, exchange, forces, diagnostics 1; demEngine,
# voidFraction 2; momentumCoupling, fluid 3; controls 4; sceneCheck 5;
# particleCloud 6; solverIncludes 7).
# Reference: the floors above (issue #50: "nothing on the ground floor
# includes a room above it"). Measured: 0 arrows back up (the tree before
# core/ existed had 9 with the same floors, particleData.H in
# particleCloud/ included by 8 rooms' headers).
# Negative control: a copy of the tree whose core/particleData.H includes
# particleCloud.H must fail, naming that arrow.
#------------------------------------------------------------------------------
. "${0%/*}/caseFunctions.sh"

out=$("$INTERDEMFOAM_DIR/bin/includeLayers" 2>&1)
rc=$?
echo "$out" | tail -n 3
[ $rc -eq 0 ] || fail "include arrows back up in src/demCoupling:
$out"
echo "$out" | grep -q "^0 include arrow(s) back up" \
    || fail "no count of arrows in: $out"

# negative control: one arrow from the ground floor to the top
rm -rf "$runDir/includeLayers"
mkdir -p "$runDir/includeLayers"
cp -r "$INTERDEMFOAM_DIR/src/demCoupling" "$runDir/includeLayers/"
rm -rf "$runDir/includeLayers/demCoupling/lnInclude" \
       "$runDir/includeLayers/demCoupling/Make/linux64"*
echo '#include "particleCloud.H"' \
    >> "$runDir/includeLayers/demCoupling/core/particleData.H"
bad=$("$INTERDEMFOAM_DIR/bin/includeLayers" "$runDir/includeLayers/demCoupling" 2>&1)
[ $? -ne 0 ] || fail "negative control: an include from core/ to particleCloud/ passed"
echo "$bad" | grep -q "core/particleData.H -> particleCloud/particleCloud.H" \
    || fail "negative control: the arrow is not named: $bad"
echo "ok: negative control ($(echo "$bad" | head -n 1))"

pass "no include arrow runs back up in src/demCoupling"
