#!/bin/bash
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#------------------------------------------------------------------------------
# An interFoam case runs unchanged: OpenFOAM's own damBreak tutorial (from
# the OpenFOAM source the build unpacks; semi-implicit MULES, interFoam's
# scheme names, no couplingProperties) run as its Allrun does, once with
# interFoam and once with interDemFoam, no file edited. Asserted:
#   - interDemFoam reaches the end and no case file differs from OpenFOAM's;
#   - the surge front (water length of the bottom cell row left of the
#     obstacle, sum(alpha dx)) at t = 0.05, 0.1 and 0.15 s: the two solvers
#     within 3 mm (a quarter of a 12.7 mm cell) of each other. With eps = 1
#     they solve the same equations; their time-step sequences differ (501
#     and 495 steps): measured 0.4, 1.5 and 0.1 mm. Negative control: upwind
#     alpha schemes in interDemFoam move the front by 3.7, 7.8 and 4.4 mm;
#   - the water volume: conserved to 1e-6 by both until the splash reaches
#     the open top (t <= 0.25 s; printed to 6 digits), and at t = 1 s the two within 1 % of each
#     other (water leaves through the top: 2.2 % with interFoam; the splash
#     depends on each solver's time steps);
#   - interDemFoam keeps alpha within [-1e-4, 1 + 1e-4] (MULES's limiter,
#     5 iterations, bounds to about that: interFoam itself reaches
#     -8.8e-5 on this case).
# Reference: interFoam (OpenFOAM v1912) on the same, unedited case. Measured:
# fronts 0.4, 1.5 and 0.1 mm apart, final water 0.42 % apart, interFoam's
# own alpha down to -8.8e-5.
#------------------------------------------------------------------------------
. "${0%/*}/caseFunctions.sh"

source="$WM_PROJECT_DIR/tutorials/multiphase/interFoam/laminar/damBreak/damBreak"
[ -d "$source" ] || fail "no $source (./Allwmake unpacks OpenFOAM's source, tutorials included)"

for solver in interFoam interDemFoam
do
    rm -rf "$runDir/damBreak.$solver"
    mkdir -p "$runDir"
    cp -r "$source" "$runDir/damBreak.$solver"
    cd "$runDir/damBreak.$solver" || fail "cannot enter $runDir/damBreak.$solver"
    # as the tutorial's Allrun does
    runApplication blockMesh || fail "$solver: blockMesh"
    cp 0/alpha.water.orig 0/alpha.water
    runApplication setFields || fail "$solver: setFields"
    runApplication "$solver" || fail "$solver failed (see damBreak.$solver/log.$solver)"
    grep -q "^End" "log.$solver" || fail "$solver did not reach the end"
    diff -r "$source/system" system > /dev/null || fail "$solver: system/ differs from OpenFOAM's"
    diff -r -x polyMesh "$source/constant" constant > /dev/null \
        || fail "$solver: constant/ differs from OpenFOAM's"
    echo "$solver: $(grep -c '^Time = ' "log.$solver") steps, $(grep '^ExecutionTime' "log.$solver" | tail -1)"
done
cd "$runDir" || fail "cannot enter $runDir"

# front <case> <time>: sum(alpha dx) over the 23 bottom cells of block 0
front()
{
    foamDictionary -entry internalField -value "$1/$2/alpha.water" 2>/dev/null \
        | awk '/^\(/{f=1; next} /^\)/{f=0} f { print }' \
        | awk -v num='^[-+]?([0-9]+\\.?[0-9]*|\\.[0-9]+)([eE][-+]?[0-9]+)?$' '
              NR <= 23 { if ($1 !~ num) exit; n++; s += $1*2*0.146/23 }
              END { if (n == 23) printf "%.5f\n", s }'
}
for t in 0.05 0.1 0.15
do
    a=$(front damBreak.interFoam $t)
    b=$(front damBreak.interDemFoam $t)
    requireNumber "front of interFoam at $t s" "$a"
    requireNumber "front of interDemFoam at $t s" "$b"
    d=$(awk -v a="$a" -v b="$b" 'BEGIN { d = a - b; if (d < 0) d = -d; printf "%.5f", d }')
    echo "front at t = $t s: interFoam $a m, interDemFoam $b m, difference $d m"
    check "front difference at $t s" "$d" 'v < 0.003' \
        "fronts at t = $t s differ by $d m, more than 3 mm"
done

# volume <log> <tmax>: largest relative change of the phase-1 volume
# fraction up to tmax; volumeEnd <log>: its last value
volumeDrift()
{
    awk -v tmax="$2" '/^Time = / { t = $3 }
        /^Phase-1 volume fraction/ && t <= tmax { v = $5; if (!n++) v0 = v
            d = (v - v0)/v0; if (d < 0) d = -d; if (d > m) m = d }
        END { if (n > 10 && v0 > 0) printf "%.3e\n", m }' "$1"
}
volumeEnd()
{
    awk '/^Phase-1 volume fraction/ { v = $5 } END { print v }' "$1"
}
for solver in interFoam interDemFoam
do
    drift=$(volumeDrift damBreak.$solver/log.$solver 0.25)
    echo "$solver: water volume drift up to 0.25 s: ${drift:-none}"
    check "$solver water volume drift to 0.25 s" "$drift" 'v < 1e-6' \
        "$solver: water volume changed by $drift before the splash"
done
va=$(volumeEnd damBreak.interFoam/log.interFoam)
vb=$(volumeEnd damBreak.interDemFoam/log.interDemFoam)
requireNumber "interFoam's final phase-1 fraction" "$va"
requireNumber "interDemFoam's final phase-1 fraction" "$vb"
rel=$(awk -v a="$va" -v b="$vb" 'BEGIN { d = (b - a)/a; if (d < 0) d = -d; printf "%.4f", d }')
echo "water at t = 1 s: interFoam $va, interDemFoam $vb of the domain: relative difference $rel"
check "final water volume difference" "$rel" 'v < 0.01' \
    "final water volumes differ by $rel (> 1 %)"

bounds=$(awk '/^Phase-1 volume fraction/ { for (i = 1; i <= NF; i++) {
        if ($i ~ /^Min\(alpha/) { v = $(i+2); if (!n || v < lo) lo = v }
        if ($i ~ /^Max\(alpha/) { v = $(i+2); if (!n || v > hi) hi = v } } n++ }
    END { if (n) printf "%.3e %.9f\n", lo, hi }' damBreak.interDemFoam/log.interDemFoam)
lo=${bounds% *}; hi=${bounds#* }
check "interDemFoam min(alpha)" "$lo" 'v > -1e-4' "alpha fell to $lo"
check "interDemFoam max(alpha)" "$hi" 'v < 1 + 1e-4' "alpha rose to $hi"

pass "OpenFOAM's damBreak runs unchanged: fronts within 3 mm, water within $rel at 1 s, alpha in [$lo, $hi]"
