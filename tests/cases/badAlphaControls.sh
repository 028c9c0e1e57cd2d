#!/bin/bash
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#------------------------------------------------------------------------------
# Bad input: interDemFoam solves the phase fraction once per step; asking for
# sub-cycles must stop the run with a message naming the file and keyword.
#------------------------------------------------------------------------------
. "${0%/*}/caseFunctions.sh"

copyTutorial damBreakBox badAlphaControls
restore0Dir > /dev/null
runApplication blockMesh || fail "blockMesh"
setEntry system/fvSolution 'solvers/"alpha.water.*"/nAlphaSubCycles' 3

if interDemFoam > log.interDemFoam 2>&1 < /dev/null
then
    fail "interDemFoam accepted nAlphaSubCycles 3"
fi
grep -q "FOAM FATAL IO ERROR" log.interDemFoam || fail "no FatalIOError (see log)"
grep -q "nAlphaSubCycles must be 1 (is 3)" log.interDemFoam || fail "message does not name nAlphaSubCycles"
grep -q "system/fvSolution" log.interDemFoam || fail "message does not name system/fvSolution"
grep -q "Segmentation\|sigSegv" log.interDemFoam && fail "crashed instead of a clean error"
pass "nAlphaSubCycles 3 rejected: $(grep -m1 'nAlphaSubCycles must' log.interDemFoam | sed 's/^ *//')"
