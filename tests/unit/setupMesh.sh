#!/bin/bash
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
# CTest fixture of the unit tests: tests/run/meshCase with its blockMesh
. "${0%/*}/../cases/caseFunctions.sh"
rm -rf "$runDir/meshCase"; mkdir -p "$runDir"
cp -r "$testsDir/unit/meshCase" "$runDir/meshCase"
blockMesh -case "$runDir/meshCase" > "$runDir/meshCase/log.blockMesh" 2>&1 \
    || fail "blockMesh of the unit-test mesh"
n=$(sed -n 's/.*nCells:[[:space:]]*\([0-9]*\).*/\1/p' "$runDir/meshCase/constant/polyMesh/owner" | head -n 1)
check "cells of the unit-test mesh" "$n" 'v > 0' "the unit-test mesh has no cells"
pass "unit-test mesh ($n cells)"
