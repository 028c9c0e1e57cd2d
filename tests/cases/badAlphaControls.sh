#!/bin/bash
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#------------------------------------------------------------------------------
# Bad input: phase-fraction controls interDemFoam cannot honour stop the run
# with a message naming the file and the keyword (never a silent default):
#   - alphaApplyPrevCorr yes (the last step's correction flux is no guess
#     once the particles have changed eps)
#   - nAlphaSubCycles 0
#   - icAlpha 0.5 (interFoam's isotropic compression)
# Reference: the messages quoted in docs/reliability.md, row 24. Measured:
# each stops with FatalIOError naming system/fvSolution; no number.
#------------------------------------------------------------------------------
. "${0%/*}/caseFunctions.sh"

copyTutorial damBreakBox badAlphaControls
restore0Dir > /dev/null
runApplication blockMesh || fail "blockMesh"
cp system/fvSolution fvSolution.good

# expectAlphaError <name> <key> <value> <message>
expectAlphaError()
{
    cp fvSolution.good system/fvSolution
    setEntry system/fvSolution "solvers/\"alpha.water.*\"/$2" "$3"
    if timeout 120 interDemFoam > "log.$1" 2>&1 < /dev/null
    then
        fail "$1: interDemFoam accepted $2 $3"
    fi
    grep -q "FOAM FATAL IO ERROR" "log.$1" || fail "$1: no FatalIOError (see log.$1)"
    grep -q -- "$4" "log.$1" || fail "$1: message does not say '$4'"
    grep -q "system/fvSolution" "log.$1" || fail "$1: message does not name system/fvSolution"
    grep -q "Segmentation\|sigSegv" "log.$1" && fail "$1: crashed instead of a clean error"
    echo "ok: $1 ($(grep -m1 -- "$4" "log.$1" | sed 's/^ *//' | cut -c1-100))"
}

expectAlphaError prevCorr alphaApplyPrevCorr yes "alphaApplyPrevCorr yes is not supported"
expectAlphaError noSubCycles nAlphaSubCycles 0 "nAlphaSubCycles (0) must be at least 1"
expectAlphaError isoCompression icAlpha 0.5 "icAlpha 0.5 and scAlpha 0"
pass "unsupported phase-fraction controls rejected"
