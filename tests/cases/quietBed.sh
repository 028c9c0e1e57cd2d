#!/bin/bash
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#------------------------------------------------------------------------------
# Quiet dense beds: the pressure at the plate under 825 glass beads (d = 2 mm)
# poured into the 12 mm periodic column of the packedBed tutorial (cells 2 d,
# virtual sphere, RongDrag + pressureGradient, CFD step 5e-4 s = 10 DEM
# steps), one value per CFD step, over the second half of the run
# (benchmarks/quietBed/Allrun):
#   at rest, U = 8 mm/s (below U_mf = 21.7 mm/s), 0.5 s: standard deviation
#     at most 1 % of the bed's buoyant weight per area W (353 Pa);
#   fluidized, U = 30 mm/s, 1.5 s: at most 5 % of W, mean within 10 % of W.
# Negative control: the former scheme (d(eps)/dt as the difference of two
# eps snapshots, drag held over the coupling interval) must fail the rest
# criterion (it rang at 60 % of W).
# Reference: the bed's buoyant weight per area W. Measured: 5e-5 W at rest,
# 6.6e-3 W fluidized with mean 0.955 W; the former scheme 0.53 W at rest.
#------------------------------------------------------------------------------
. "${0%/*}/caseFunctions.sh"
bench="$INTERDEMFOAM_DIR/benchmarks/quietBed/Allrun"
runs="$runDir/quietBed"
rm -rf "$runs"

value() { awk -v k="$1" '$1 == k { n++; v = $2 } END { if (n == 1) print v }' "$runs/$2/noise.summary"; }

"$bench" -runDir "$runs" -name rest -U 0.008 -endTime 0.5 > "$runDir/quietBed.rest.log" 2>&1 \
    || fail "the bed at rest did not run ($runDir/quietBed.rest.log)"
s=$(value std_over_W rest)
check "pressure standard deviation / W, bed at rest" "$s" 'v <= 0.01' \
    "bed at rest: pressure standard deviation $s of the bed weight (limit 0.01)"
echo "bed at rest (8 mm/s): pressure standard deviation $s of W"

"$bench" -runDir "$runs" -name fluidized -U 0.03 -endTime 1.5 > "$runDir/quietBed.fluidized.log" 2>&1 \
    || fail "the fluidized bed did not run ($runDir/quietBed.fluidized.log)"
s=$(value std_over_W fluidized)
m=$(value mean_over_W fluidized)
check "pressure standard deviation / W, fluidized" "$s" 'v <= 0.05' \
    "fluidized bed: pressure standard deviation $s of the bed weight (limit 0.05)"
check "mean pressure / W, fluidized" "$m" 'v > 0.9 && v < 1.1' \
    "fluidized bed: mean plate pressure $m of the bed weight (expected 0.9-1.1)"
echo "fluidized bed (30 mm/s): mean $m of W, standard deviation $s of W"

# negative control: the former scheme rings
"$bench" -runDir "$runs" -name formerScheme -U 0.008 -endTime 0.5 -rate snapshot \
    -demDrag explicit > "$runDir/quietBed.former.log" 2>&1 \
    || fail "the former-scheme control did not run ($runDir/quietBed.former.log)"
s=$(value std_over_W formerScheme)
check "negative control (former scheme) standard deviation / W" "$s" 'v > 0.01' \
    "negative control: the former scheme is quiet too ($s of W): the test proves nothing"
echo "negative control: snapshot d(eps)/dt, drag held over the interval: standard deviation $s of W (fails the 1 % limit)"
pass "dense bed quiet: at rest and fluidized"
