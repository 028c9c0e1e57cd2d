#!/bin/bash
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#------------------------------------------------------------------------------
# The two particle exchanges give the same results. The cell-sized particle
# bed of voidFractionParallel (20 particles, d = dx = 4 mm, virtual sphere of
# 4 d, so spheres cross the METIS processor boundaries), here released in
# water (setFields fills the box: alpha.water = 1 in all 250 cells) and
# falling under gravity for 60 coupling steps, on 2, 3 and 4 ranks with
#   exchange allReduce;    (every rank holds every particle)
#   exchange manyToMany;   (each rank holds the particles that reach it)
# Checked:
#   - 2 ranks: the same fields (U, p_rgh, voidfraction, Ksl, Us) and the
#     same particles (U, fluid force F, id; DEM positions and velocities)
#     to all 17 digits (files compared byte for byte): both exchanges add
#     the same terms in the same order, and a sum of two ranks' shares does
#     not depend on the order;
#   - 3 and 4 ranks: the same to 1e-12 of each quantity's largest magnitude.
#     A particle's cells may now lie on three or more ranks; allReduce sums
#     their shares in MPI_Allreduce's order, manyToMany on the owner in rank
#     order, so the last bit may differ (1 ulp, 1e-16) and is carried on
#     through 60 steps of pressure solves; 1e-12 leaves 10^3 or more above
#     what is measured (printed) and is still far below any physical effect;
#   - the held counts manyToMany prints at the end ("Particles held per rank
#     at the end: min, max"). A rank holds a particle when its virtual
#     sphere (radius 2 d = 8 mm) reaches the box of the rank's cell centres.
#     The particles sit at x, y = 6, 12 mm and z = 7.5, 13.5, ... 31.5 mm (4
#     a layer; they fall 0.1 mm); METIS's cells (decomposePar -cellDist) give
#       2 ranks: centre boxes z 2-18 | 22-38 mm: layers 7.5-25.5 (16) and
#                19.5-31.5 (12): min 12, max 16
#       3 ranks: one box z 2-26 mm reaches all 20; the top one (z 26-38) 12;
#                the third (x 10-18, z 2-22) 16: min 12, max 20
#       4 ranks: two boxes z 2-18 (16 each), two z 22-38 (12 each): 12, 16
#     (EXPECT_HELD below); with allReduce every rank holds all 20;
#   - water: alpha.water = 1 in all 250 cells at t = 0 and, at the end, to
#     1e-12 in the 225 cells below the top layer (the falling bed draws
#     air in through the open top, into the top layer only);
#   - the particles moved (else the forces were never exercised).
# Measured: 2 ranks identical; 3 and 4 ranks 0 and 1e-15 of the largest
# values; held 12/16, 12/20, 12/16 (allReduce 20). Negative controls: the
# comparison fails on an emptied or cut field and sees a single value
# changed by 1e-9.
#------------------------------------------------------------------------------
. "${0%/*}/caseFunctions.sh"

src="$testsDir/cases/particleBed"
name=exchangeIdentical
rm -rf "$runDir/$name"; mkdir -p "$runDir/$name"; cd "$runDir/$name" || fail "no run dir"

# manyToMany's held counts "min max" on n ranks (measured once, see above)
declare -A EXPECT_HELD=([2]="12 16" [3]="12 20" [4]="12 16")

endTime=0.006

# waterBelow <alpha.water file> <cells> <tolerance>: alpha.water is 1 to
# <tolerance> in the first <cells> cells (the mesh has 250, numbered layer
# by layer from the bottom, 25 a layer); a uniform field counts for all
waterBelow()
{
    /usr/bin/python3 - "$@" <<'PYEOF'
import re, sys
f, n, tol = sys.argv[1], int(sys.argv[2]), float(sys.argv[3])
s = open(f).read()
m = re.search(r'internalField\s+uniform\s+([^;]+);', s)
if m:
    vals = [float(m.group(1))]*250
else:
    m = re.search(r'internalField\s+nonuniform\s+List<scalar>\s*(\d+)\s*\((.*?)\)\s*;', s, re.S)
    if not m:
        sys.exit('no internalField in ' + f)
    vals = [float(x) for x in m.group(2).split()]
if len(vals) != 250:
    sys.exit('%d values in %s, 250 expected' % (len(vals), f))
d = max(abs(v - 1) for v in vals[:n])
print('%s: alpha.water in the lowest %d cells: largest |alpha - 1| = %.3e, in the top layer min %.6g'
      % (f, n, d, min(vals[225:])))
sys.exit(0 if d <= tol else 1)
PYEOF
}

# largest difference of two files' numbers, relative to the largest
# magnitude in the first; fails unless their words other than numbers are
# the same and they hold the same count (> 0) of numbers
relativeDifference()
{
    /usr/bin/python3 - "$1" "$2" <<'PYEOF'
import re, sys
num = re.compile(r'^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$')
def words(f):
    s = open(f).read()
    s = s[s.find('FoamFile'):] if 'FoamFile' in s else s
    return re.findall(r'[^\s()\[\]{};]+', s)
a, b = words(sys.argv[1]), words(sys.argv[2])
if len(a) != len(b):
    sys.exit('%s and %s differ in length' % tuple(sys.argv[1:3]))
xa, xb = [], []
for u, v in zip(a, b):
    if num.match(u) and num.match(v):
        xa.append(float(u)); xb.append(float(v))
    elif u != v:
        sys.exit('%s: "%s" vs "%s"' % (sys.argv[1], u, v))
if not xa:
    sys.exit('no numbers in ' + sys.argv[1])
scale = max(abs(x) for x in xa) or 1.0
print('%.3e' % (max(abs(x - y) for x, y in zip(xa, xb))/scale))
PYEOF
}

runCase()  # <exchange> <ranks>
{
    local d="$1-$2"
    cp -r "$src" "$d"
    (
        cd "$d" || exit 1
        sed -i "s/^voidFraction .*/voidFraction      virtualSphere;/" constant/couplingProperties
        echo "exchange          $1;" >> constant/couplingProperties
        fallingBed $endTime
        setEntry system/decomposeParDict numberOfSubdomains $2
        runApplication blockMesh || exit 1
        runApplication setFields || exit 1
        runApplication decomposePar || exit 1
        mpirun --oversubscribe -np $2 interDemFoam -parallel \
            > log.interDemFoam 2>&1 < /dev/null || exit 1
        runApplication reconstructPar -latestTime || exit 1
        grep -q "^End" log.interDemFoam
    ) || fail "$d did not run (see $runDir/$name/$d/log.*)"
    grep -q "Particle exchange between ranks: $1" "$d/log.interDemFoam" \
        || fail "$d: $1 was not selected"
    awk '/^ITEM: ATOMS/ { f = 1; next } f' "$d/post/bed.600.dump" > "$d.atoms"
    [ "$(wc -l < "$d.atoms")" -eq 20 ] || fail "$d: no DEM dump of 20 particles"
}

# heldCounts <case>: "min max total" from the solver's last report
heldCounts()
{
    sed -n 's/^Particles held per rank at the end: min \([0-9]*\), max \([0-9]*\) (of \([0-9]*\) in the DEM)/\1 \2 \3/p' \
        "$1/log.interDemFoam"
}

fields="U p_rgh voidfraction Ksl Us lagrangian/demParticles/U lagrangian/demParticles/F lagrangian/demParticles/id"
t=$endTime
summary=""
for n in 2 3 4
do
    runCase allReduce $n
    runCase manyToMany $n
    a=allReduce-$n; m=manyToMany-$n

    # water: in every cell at the start (setFields); at the end in every
    # cell below the top layer (the falling bed draws air in through the
    # open top, into the top layer only)
    waterBelow "$a/0/alpha.water" 250 0 \
        || fail "$a: alpha.water is not 1 in every cell at t = 0 (setFields)"
    for e in $a $m
    do
        waterBelow "$e/$t/alpha.water" 225 1e-12 \
            || fail "$e: alpha.water is not 1 (1e-12) below the top layer at t = $t"
    done

    worst=0
    for f in $fields
    do
        [ -f "$a/$t/$f" ] || fail "$a wrote no $t/$f"
        [ -f "$m/$t/$f" ] || fail "$m wrote no $t/$f"
        if [ $n -eq 2 ]
        then
            cmp -s <(sed 1,/^FoamFile/d "$a/$t/$f") <(sed 1,/^FoamFile/d "$m/$t/$f") \
                || fail "$f differs between allReduce and manyToMany on 2 ranks (diff $a/$t/$f $m/$t/$f)"
        else
            r=$(relativeDifference "$a/$t/$f" "$m/$t/$f") || fail "$n ranks: cannot compare $f"
            echo "$n ranks: $f: largest difference / largest value = $r"
            check "$n ranks: $f difference" "$r" 'v <= 1e-12' \
                "$f differs between allReduce and manyToMany on $n ranks by $r (> 1e-12)"
            worst=$(awk -v a="$worst" -v b="$r" 'BEGIN { print (b > a ? b : a) }')
        fi
    done
    if [ $n -eq 2 ]
    then
        cmp -s $a.atoms $m.atoms \
            || fail "DEM positions/velocities differ on 2 ranks (diff $runDir/$name/{$a,$m}.atoms)"
    else
        r=$(relativeDifference $a.atoms $m.atoms) || fail "$n ranks: cannot compare the DEM dumps"
        echo "$n ranks: DEM positions and velocities: largest difference / largest value = $r"
        check "$n ranks: DEM difference" "$r" 'v <= 1e-12' \
            "DEM positions/velocities differ on $n ranks by $r (> 1e-12)"
        worst=$(awk -v a="$worst" -v b="$r" 'BEGIN { print (b > a ? b : a) }')
    fi

    set -- $(heldCounts $m)
    [ $# -eq 3 ] || fail "no 'Particles held per rank' line in $m/log.interDemFoam"
    echo "$n ranks: manyToMany held min $1, max $2 of $3 particles per rank"
    [ "$3" -eq 20 ] || fail "$m: $3 particles in the DEM, 20 expected"
    [ "$1 $2" = "${EXPECT_HELD[$n]}" ] \
        || fail "$m: ranks held min $1, max $2 particles, expected ${EXPECT_HELD[$n]}"
    set -- $(heldCounts $a)
    [ "$1 $2 $3" = "20 20 20" ] || fail "$a: ranks held '$1 $2 $3', expected 20 20 20"

    if [ $n -eq 2 ]
    then
        summary="2 ranks identical to 17 digits, held ${EXPECT_HELD[2]}"
    else
        summary="$summary; $n ranks within $worst, held ${EXPECT_HELD[$n]}"
    fi
done

# negative controls: the tolerant comparison fails on a field emptied, cut
# short, or with one value changed in its 10th digit
f=allReduce-3/$t/p_rgh
: > empty.p_rgh
awk '/^internalField/ { f = 1 }
     f && !done && /^[-0-9]/ { printf "%.17g\n", $1*(1 + 1e-9); done = 1; next } { print }' \
    $f > changed.p_rgh
cmp -s $f changed.p_rgh && fail "negative control: p_rgh not changed"
awk '/^internalField/ { f = 1 } !(f && /^[-0-9]/ && n++ >= 100)' $f > cut.p_rgh
relativeDifference $f empty.p_rgh > /dev/null 2>&1 && fail "the comparison passes on an empty field"
relativeDifference $f cut.p_rgh > /dev/null 2>&1 && fail "the comparison passes on a field cut short"
r=$(relativeDifference $f changed.p_rgh)
check "changed p_rgh difference" "$r" 'v > 1e-12' "the comparison misses a change in the 10th digit ($r)"
echo "negative controls: the comparison fails on an empty and a cut p_rgh and sees a changed one ($r)"

# DEM dump columns: id x y z vx vy vz
dz=$(awk '{ z = $4; if (NR == 1 || z > m) m = z } END { print m }' allReduce-2.atoms)
check "highest particle centre" "$dz" 'v < 0.0315 - 1e-5' \
    "the particles did not fall (highest centre z = $dz m, started at 0.0315 m)"

pass "allReduce = manyToMany: $summary (of 20 particles, min max per rank); highest centre $dz m after 60 steps"
