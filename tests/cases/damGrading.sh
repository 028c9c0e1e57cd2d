#!/bin/bash
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
# The landslide dam built with its grading (tutorials/interDemFoam/
# landslideDamBreach, LIGGGHTS alone, about a minute on one core): both small
# dams poured by ./Allrun -buildDam "C F", then checked here independently of
# the tutorial's checker:
#   - results/grading.small.dat holds every class of C (20, 30, 40 mm) and F
#     (10, 15, 20, 30, 40 mm), each within 3 points of its target mass share;
#   - its counts are the grains in the dump of the built dam (counted here by
#     radius), and the measured shares follow from those counts;
#   - F is finer than C (its smallest class at most half of C's), the DEM
#     step is at most 20 % of the Rayleigh time of the smallest grains, and
#     the dam is denser than the old pour's 0.49 (solid fraction > 0.52).
# Negative controls:
#   - the old pour (largest grains first, fix insert/pack at 0.62 into the
#     trapezoid every 0.2 s: no 20 mm grains in C) makes ./Allrun fail with
#     the grading message, and its dam is not kept;
#   - the checker on C's dam with 20 mm grains removed to 3.5 points under
#     their share fails; at 2.5 points under it passes (the 3-point bound).
# Reference: the gradings' target mass shares (docs/damBreach.md, The
# scene). Measured (results/grading.small.dat): C 0.313/0.399/0.288 of
# 0.3/0.4/0.3; F 0.158/0.203/0.247/0.188/0.205 of
# 0.15/0.20/0.25/0.20/0.20; solid fraction 0.547 (C) and 0.567 (F).
. "$(dirname "$0")/caseFunctions.sh"

copyTutorial landslideDamBreach damGrading
rm -f DEM/dam.* results/grading.small.dat

./Allrun -buildDam "C F" > log.Allrun 2>&1 \
    || { tail -30 log.Allrun; fail "Allrun -buildDam \"C F\" failed (log.Allrun)"; }
cat log.Allrun
dat=results/grading.small.dat
[ -s "$dat" ] || fail "$dat not written"
for m in C F
do
    [ -f DEM/dam.$m.small.restart ] || fail "DEM/dam.$m.small.restart not written"
    [ -s build.$m.small/dam.grains ] || fail "build.$m.small/dam.grains not written"
done

# the rows: class diameters, shares within 3 points, counts > 0
expectC="0.0200 0.0300 0.0400"
expectF="0.0100 0.0150 0.0200 0.0300 0.0400"
for m in C F
do
    expect=expectC; [ $m = F ] && expect=expectF
    got=$(awk -v m=$m '$1 == m { printf "%s ", $2 }' "$dat")
    [ "$got" = "${!expect} " ] || fail "$dat: material $m classes '$got', expected '${!expect}'"
    while read -r mat d target measured count
    do
        check "$m d $d target" "$target" 'v > 0 && v < 1' "$m d = $d: target $target"
        check "$m d $d measured" "$measured" 'v >= 0 && v <= 1' "$m d = $d: measured $measured"
        check "$m d $d count" "$count" 'v > 0' "$m d = $d: no grains"
        off=$(awk -v a="$measured" -v b="$target" 'BEGIN { printf "%.4f", a - b }')
        check "$m d $d share" "$off" 'v >= -0.03 && v <= 0.03' \
            "material $m, d = $d m: mass share $measured, target $target (3 points allowed)"
        echo "$m d = $d m: target $target, measured $measured ($off), $count grains"
    done < <(awk -v m=$m '$1 == m' "$dat")

    # the counts and shares from the grains themselves (dump: id type radius
    # mass x y z ...)
    awk -v m=$m 'NR == FNR { if (/^ITEM: ATOMS/) { on = 1; next } if (on && NF) {
            d = sprintf("%.4f", 2*$3); n[d]++; mass[d] += $4; M += $4 } next }
        $1 == m { d = $2; if (n[d] != $5) { print m " d " d ": " n[d] " grains in the dump, " $5 " in the table"; bad = 1 }
                  s = mass[d]/M; if (s - $4 > 5e-4 || $4 - s > 5e-4) { print m " d " d ": share " s " from the dump, " $4 " in the table"; bad = 1 }
                }
        END { exit bad }' \
        build.$m.small/dam.grains "$dat" > check.$m 2>&1 || { cat check.$m; fail "$dat disagrees with build.$m.small/dam.grains"; }
    total=$(awk '/^ITEM: NUMBER OF ATOMS/ { getline; print; exit }' build.$m.small/dam.grains)
    inTable=$(awk -v m=$m '$1 == m { s += $5 } END { print s + 0 }' "$dat")
    [ "$total" = "$inTable" ] || fail "material $m: $total grains in the dump, $inTable in the classes"

    # solid fraction and Rayleigh time from the summary line
    summary=$(grep "^# $m:" "$dat")
    solid=$(echo "$summary" | sed -n 's/.*solid fraction \([0-9.]*\) .*/\1/p')
    rayleigh=$(echo "$summary" | sed -n 's/.* = \([0-9.]*\) % of the Rayleigh time.*/\1/p')
    check "$m solid fraction" "$solid" 'v > 0.52 && v < 0.74' \
        "material $m: solid fraction $solid (the old pour: 0.49)"
    check "$m Rayleigh" "$rayleigh" 'v > 0 && v <= 20' \
        "material $m: DEM step $rayleigh % of the Rayleigh time (20 % at most)"
done
dC=$(awk '$1 == "C" { print $2; exit }' "$dat")
dF=$(awk '$1 == "F" { print $2; exit }' "$dat")
check "F finer than C" "$dF" "v <= 0.5*$dC" "F's smallest class $dF m is not at most half of C's ($dC m)"

# negative control 1: the old pour, largest first, into the trapezoid
mkdir -p old/DEM
cp -r DEM/in.* old/DEM/
sed -i 's/^fix             ins all insert\/pack .*/fix ins all insert\/pack seed 49979687 distributiontemplate pdd insert_every 2000 overlapcheck yes all_in yes volumefraction_region 0.62 region dam/;
        s/^run             1$/run 30000/' old/DEM/in.buildDam
grep -q 'volumefraction_region 0.62 region dam' old/DEM/in.buildDam || fail "negative control: old pour not set"
cp -r Allrun scripts damBreachAnalysis.py damBreach old/
(cd old && mkdir -p results && ./Allrun -buildDam C > log.Allrun 2>&1) \
    && { cat old/log.Allrun; fail "negative control: Allrun accepts the old largest-first pour"; }
grep -q "GRADING CHECK FAILED" old/log.Allrun || { cat old/log.Allrun; fail "negative control: no grading message"; }
grep -q "d = 20 mm: 0.000 of the mass" old/log.Allrun || { cat old/log.Allrun; fail "negative control: the missing 20 mm class is not named"; }
[ -f old/DEM/dam.C.small.restart ] && fail "negative control: the rejected dam is kept for the runs"
[ -f old/DEM/dam.C.small.restart.rejected ] || fail "negative control: the rejected dam not set aside"
echo "negative control, the old pour:"
sed -n '/^Grading of the dam/,$p' old/log.Allrun

# negative control 2: C's dam with 20 mm grains removed down to 3.5 points
# under their share (must fail) and 2.5 points under it (must pass)
for under in 0.035 0.025
do
    /usr/bin/python3 - build.C.small/dam.grains $under > grains.under$under <<'EOF'
import sys
lines = open(sys.argv[1]).read().splitlines()
i = next(k for k, l in enumerate(lines) if l.startswith('ITEM: ATOMS')) + 1
rows = [l.split() for l in lines[i:] if l.strip()]
M = sum(float(r[3]) for r in rows)
small = [r for r in rows if abs(2*float(r[2]) - 0.02) < 1e-9]
M20 = sum(float(r[3]) for r in small)
m1 = float(small[0][3])
share = 0.3 - float(sys.argv[2])            # C's 20 mm target: 0.3
k = int((M20 - share*M)/(m1*(1 - share))) + 1
drop = set(r[0] for r in small[:k])
keep = [r for r in rows if r[0] not in drop]
head = lines[:i]
head[head.index('ITEM: NUMBER OF ATOMS') + 1] = str(len(keep))
print('\n'.join(head + [' '.join(r) for r in keep]))
EOF
    /usr/bin/python3 damBreachAnalysis.py grading build.C.small --grains grains.under$under > log.under$under 2>&1
    rc=$?
    measured=$(awk '$1 == "C" && $2 == 20 { print $4 }' log.under$under)
    if [ $under = 0.035 ]
    then
        [ $rc -ne 0 ] && grep -q "GRADING CHECK FAILED" log.under$under \
            || { cat log.under$under; fail "negative control: 20 mm share $measured (3.5 points under) passes"; }
        echo "negative control, 20 mm share $measured (target 0.3): fails"
    else
        [ $rc -eq 0 ] || { cat log.under$under; fail "20 mm share $measured (2.5 points under) fails"; }
        echo "bound, 20 mm share $measured (target 0.3): passes"
    fi
done

pass "C and F small dams poured with their gradings (results/grading.small.dat); the old pour and a 3.5-point miss fail"
