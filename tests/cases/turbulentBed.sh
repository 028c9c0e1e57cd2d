#!/bin/bash
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#------------------------------------------------------------------------------
# Turbulence with the fluid fraction eps, over and in a fixed bed of grains
# (tests/cases/turbulentBed: a periodic channel 0.06 x 0.04 m, three layers
# of 10 mm spheres on a simple cubic lattice, eps 0.476, bed surface at
# z = 0.03 m; water of depth h = 0.1 m above it driven by rho g S, so that
# tau_b = rho g S h = 0.9025 Pa, u* = 0.030 m/s, u* d/nu = 300: fully
# rough; air above; k-omega SST with eps in its equations, the grains
# damping it (turbulenceDragDamping); cells 10 x 10 x 5 mm; 40 s, the flow
# steady to 0.1 % over the last 5 s). analyse.py reads the last fields.
# Asserts (interDemFoam):
#   - the grains damp the turbulence inside the bed: k one grain below the
#     surface (z 15-20 mm) is below 1 % of k one grain above it (35-40 mm).
#     Why 1 %: the bed's permeability length sqrt(K) is 0.47 mm (Kozeny-
#     Carman, K = d^2 eps^3/(180 (1 - eps)^2)), and turbulence enters a
#     permeable bed a few sqrt(K) deep (Breugem, Boersma & Uittenbogaard
#     2006, J. Fluid Mech. 562:35); one grain is 21 sqrt(K), so k there is
#     a small fraction of k above; 1 % bounds it with a margin. Measured
#     6.2e-4;
#   - the log law above the bed (u from the horizontal means, fitted
#     between 1.5 d above the surface and 0.5 h, u* from the momentum
#     balance, the zero-plane displacement the best fit in [z_b - d, z_b]):
#     kappa within 10 % of 0.41 (measured 0.422) and the roughness
#     k_s = 30 z0 of the order of d, 1-5 d (Nikuradse's equivalent sand
#     roughness of gravel beds is 1-3 d; measured 2.9 d), fit R^2 > 0.995;
#   - the stress the grains carry (their fluid force along x per bed area,
#     mean of the last 5 s) within 5 % of rho g S h (measured 1.015).
# pimpleDemFoam (the same bed under one fluid with a rigid lid at 0.13 m,
# tests/cases/turbulentBedSinglePhase over it): k in the bed below 1 % of
# k above (measured 6.2e-4), the grains' stress within 5 % of rho g S h
# (1.018); its kappa is printed (0.44 with the lid, not checked).
# Reference: the log law of the wall with kappa = 0.41 over rough beds
# (Nikuradse 1933; Nezu & Nakagawa 1993), the channel's momentum balance.
# Negative control, in this test's own runs: the same channel with
# dragDamping no (the grains do not damp the turbulence) for 10 s must fail
# the bed check (measured in the test: k ratio 0.59 at 10 s, kappa 0.31;
# run on to 40 s: 0.61, kappa 0.55, k_s 9.9 d).
#------------------------------------------------------------------------------
. "${0%/*}/caseFunctions.sh"

caseDir="$testsDir/cases/turbulentBed"

# setupChannel <name> [singlePhase]: the case in tests/run/<name>, meshed
setupChannel()
{
    rm -rf "$runDir/$1"
    mkdir -p "$runDir"
    cp -r "$caseDir" "$runDir/$1"
    if [ "$2" = singlePhase ]
    then
        rm -f "$runDir/$1/0/alpha.water"
        cp -r "$testsDir/cases/turbulentBedSinglePhase/"* "$runDir/$1/"
    fi
    cd "$runDir/$1" || fail "cannot enter $runDir/$1"
    runApplication blockMesh || fail "$1: blockMesh"
    runApplication topoSet || fail "$1: topoSet"
    runApplication setFields || fail "$1: setFields"
}

# value <analysis file> <key>
value() { awk -v k="$2" '$1 == k { print $2 }' "$1"; }

# 1. interDemFoam, damped
setupChannel turbulentBed
runApplication interDemFoam || fail "interDemFoam failed (log.interDemFoam)"
grep -q "^End" log.interDemFoam || fail "interDemFoam did not end"
grep -q "Turbulence damped by the particles' drag" log.interDemFoam \
    || fail "the damping was not added"
/usr/bin/python3 analyse.py . 40 > analysis.txt || fail "analyse.py"
cat analysis.txt | grep -v "^#"
a=analysis.txt
check "k in the bed / k above it" "$(value $a kRatio)" 'v < 0.01' \
    "k one grain inside the bed is $(value $a kRatio) of k above it (at most 0.01)"
check "kappa" "$(value $a kappa)" 'v > 0.9*0.41 && v < 1.1*0.41' \
    "kappa $(value $a kappa), not within 10 % of 0.41"
check "k_s/d" "$(value $a ksOverD)" 'v >= 1 && v <= 5' \
    "the roughness k_s = $(value $a ksOverD) d, not 1-5 d"
check "log-law fit R2" "$(value $a fitR2)" 'v > 0.995' "log-law fit R2 $(value $a fitR2)"
check "grains' stress / rho g S h" "$(value $a tauRatio)" 'v > 0.95 && v < 1.05' \
    "the grains carry $(value $a tauRatio) of rho g S h (within 5 %)"
echo "ok: interDemFoam: k ratio $(value $a kRatio), kappa $(value $a kappa), k_s $(value $a ksOverD) d, tau $(value $a tauRatio)"

# 2. pimpleDemFoam, the same bed under one fluid with a lid
setupChannel turbulentBedSinglePhase singlePhase
runApplication pimpleDemFoam || fail "pimpleDemFoam failed (log.pimpleDemFoam)"
grep -q "^End" log.pimpleDemFoam || fail "pimpleDemFoam did not end"
/usr/bin/python3 analyse.py . 40 > analysis.txt || fail "analyse.py (single phase)"
check "k ratio (pimpleDemFoam)" "$(value $a kRatio)" 'v < 0.01' \
    "pimpleDemFoam: k in the bed is $(value $a kRatio) of k above it"
check "grains' stress (pimpleDemFoam)" "$(value $a tauRatio)" 'v > 0.95 && v < 1.05' \
    "pimpleDemFoam: the grains carry $(value $a tauRatio) of rho g S h"
echo "ok: pimpleDemFoam: k ratio $(value $a kRatio), tau $(value $a tauRatio) (kappa $(value $a kappa), not checked)"

# 3. negative control: without the damping (10 s) the bed check fails
setupChannel turbulentBedUndamped
echo "dragDamping no;" >> constant/couplingProperties
setEntry system/controlDict endTime 10
runApplication interDemFoam || fail "the undamped run failed"
grep -q "Turbulence not damped by the particles" log.interDemFoam \
    || fail "the undamped run was damped"
/usr/bin/python3 analyse.py . 10 > analysis.txt || fail "analyse.py (undamped)"
r=$(value analysis.txt kRatio)
requireNumber "k ratio (undamped)" "$r"
awk -v v="$r" 'BEGIN { exit !(v < 0.01) }' \
    && fail "negative control: without damping the k ratio $r passed the 1 % check"
echo "ok: negative control: without damping k in the bed is $r of k above it (kappa $(value analysis.txt kappa))"

pass "turbulence with eps: damped in the bed, log law and stress above it"
