#!/bin/bash
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
# bin/demGrid (the DEM's processor grid chosen from where the grains are,
# the flagship's -demGrid auto) against LIGGGHTS's own counts. 3000 grains
# of 10-40 mm at random in a dam-shaped trapezoid of the flagship's 0.1 m
# slice (periodic across, flume 7.2 m long, dam 3.0-4.4 m, 0.3 m high); the
# flagship's contact model and skin (DEM/in.common); LIGGGHTS `run 0` on 4
# ranks (oversubscribed) with the grids 1x4x1, 2x2x1 and 4x1x1 prints each
# rank's neighbour pairs (its "Neighs" histogram). Checks:
#   - for each grid demGrid's largest and mean pairs per rank equal
#     LIGGGHTS's within 0.5 % (the same positions and cut, newton off: a
#     pair across ranks on both; only pairs at the cut's last digit can
#     differ), and its count on one rank equals LIGGGHTS's serial one,
#   - demGrid --best names the grid whose busiest rank LIGGGHTS measures
#     lowest of the three.
# Negative control: a copy of demGrid that counts a pair across two ranks
# once (newton on) misses LIGGGHTS's counts and must fail the first check.
# Reference: LIGGGHTS 3.8.0's neighbour lists. Measured: demGrid's counts
# equal LIGGGHTS's exactly (benchmarks/demBalance: the F dam on 1-16 ranks).
. "$(dirname "$0")/caseFunctions.sh"

work="$runDir/demGrid"
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
cp "$INTERDEMFOAM_DIR/benchmarks/demBalance/in.balance" \
   "$INTERDEMFOAM_TUTORIALS/landslideDamBreach/DEM/in.common" . \
    || fail "cannot copy in.balance and the flagship's in.common"
skin=$(sed -n 's/^neighbor *\([0-9.eE+-]*\) .*/\1/p' in.common)
requireNumber "the flagship's neighbour skin" "$skin"

# the grains: a LIGGGHTS data file and the same grains as a dump
/usr/bin/python3 - <<'EOF' || fail "cannot write the grains"
import math
import numpy as np
rng = np.random.default_rng(7)
n, toe, crest0, crest1, heel, height = 3000, 3.0, 3.43, 3.73, 4.37, 0.3
def top(x):     # the dam's profile: 35 deg up, crest 0.3 m, 25 deg down
    return np.clip(np.minimum((x - toe)/(crest0 - toe),
                              (heel - x)/(heel - crest1)), 0, 1)*height
x = []
while len(x) < n:
    p = rng.uniform((toe, 0.0, 0.0), (heel, 0.1, height))
    if p[2] <= top(p[0]):
        x.append(p)
x = np.array(x)
r = rng.choice([0.005, 0.0075, 0.01, 0.015, 0.02], size=n)
z = np.maximum(x[:, 2], r)
with open('grains.data', 'w') as f:
    f.write('demGrid test\n\n%d atoms\n2 atom types\n\n-0.1 7.1 xlo xhi\n'
            '0 0.1 ylo yhi\n0 0.6 zlo zhi\n\nAtoms\n\n' % n)
    for i in range(n):
        f.write('%d 1 %.6g 2500 %.9g %.9g %.9g\n'
                % (i + 1, 2*r[i], x[i, 0], x[i, 1], z[i]))
with open('grains.dump', 'w') as f:
    f.write('ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n%d\n'
            'ITEM: BOX BOUNDS ff pp ff\n-0.1 7.1\n0 0.1\n0 0.6\n'
            'ITEM: ATOMS id radius x y z\n' % n)
    for i in range(n):
        f.write('%d %.6g %.9g %.9g %.9g\n' % (i + 1, r[i], x[i, 0], x[i, 1], z[i]))
EOF

# LIGGGHTS's counts: "<max> <ave>" of Neighs for a grid on its ranks
liggghtsPairs()
{
    local p=$1 grid=$2 log=log.liggghts.$1.${2// /x}
    mpirun --oversubscribe -np "$p" liggghts -in in.balance -var data grains.data \
        -var grid "$grid" -var demDt 5e-5 -var steps 0 -echo none -log "$log" \
        > "$log.screen" 2>&1 < /dev/null || { echo "LIGGGHTS failed: $work/$log.screen"; return 1; }
    sed -n 's/^Neighs: *\([0-9.e+]*\) ave \([0-9.e+]*\) max.*/\2 \1/p' "$log" | tail -1
}

# demGrid's counts: "<max> <mean>" for a grid, from its table
demGridPairs()
{
    sed -n "s/^${1// /\\ } \([0-9]*\) \([0-9.]*\) .*/\1 \2/p" "$2"
}

# countChecks <demGrid>: its counts against LIGGGHTS's for each grid
countChecks()
{
    local table=table.$(basename "$(dirname "$1")") g ours theirs
    "$1" grains.dump 4 --skin "$skin" > "$table" || fail "$1 failed"
    ours=$(sed -n 's/.* \([0-9]*\) neighbour pairs on one rank.*/\1/p' "$table")
    check "pairs on one rank: demGrid $ours, LIGGGHTS $serialPairs" "$ours" \
        "v >= 0.995*$serialPairs && v <= 1.005*$serialPairs" \
        "demGrid counts $ours pairs on one rank, LIGGGHTS $serialPairs"
    for g in "1 4 1" "2 2 1" "4 1 1"
    do
        theirs=${measured[$g]}
        ours=$(demGridPairs "$g" "$table")
        requireNumber "demGrid's largest count for $g" "${ours% *}"
        requireNumber "demGrid's mean count for $g" "${ours#* }"
        check "grid $g largest pairs: demGrid ${ours% *}, LIGGGHTS ${theirs% *}" "${ours% *}" \
            "v >= 0.995*${theirs% *} && v <= 1.005*${theirs% *}" \
            "grid $g: demGrid's busiest rank has ${ours% *} pairs, LIGGGHTS's ${theirs% *}"
        check "grid $g mean pairs: demGrid ${ours#* }, LIGGGHTS ${theirs#* }" "${ours#* }" \
            "v >= 0.995*${theirs#* } && v <= 1.005*${theirs#* }" \
            "grid $g: demGrid's mean is ${ours#* } pairs, LIGGGHTS's ${theirs#* }"
    done
}

serial=$(liggghtsPairs 1 "1 1 1") || fail "LIGGGHTS on one rank failed"
serialPairs=${serial% *}
requireNumber "LIGGGHTS's pairs on one rank" "$serialPairs"
declare -A measured
best="" bestMax=""
for g in "1 4 1" "2 2 1" "4 1 1"
do
    measured[$g]=$(liggghtsPairs 4 "$g") || fail "LIGGGHTS on grid $g failed"
    requireNumber "LIGGGHTS's busiest rank, grid $g" "${measured[$g]% *}"
    requireNumber "LIGGGHTS's mean, grid $g" "${measured[$g]#* }"
    echo "LIGGGHTS grid $g: busiest rank ${measured[$g]% *} pairs, mean ${measured[$g]#* }"
    if [ -z "$bestMax" ] || [ "${measured[$g]% *}" -lt "$bestMax" ]
    then
        best=$g bestMax=${measured[$g]% *}
    fi
done

# mustFail <check> <argument> <what is broken> <the failure it must give>
mustFail()
{
    local msg
    msg=$( ($1 "$2") 2>&1 ) && fail "$1 passes with $3"
    case "$msg" in
        *"FAIL: "*"$4"*) ;;
        *) echo "$msg" | tail -5; fail "$1 fails with $3, but not for '$4'" ;;
    esac
    echo "negative control, $3: ${msg##*FAIL: }"
}

# negative control: a pair across two ranks counted once
mkdir -p newtonOn/bin && cp "$INTERDEMFOAM_DIR/bin/demGrid" newtonOn/bin/ || fail "cannot copy demGrid"
sed -i '/^    count += np.bincount(rj\[~image & (ri != rj)\], minlength=nranks)$/d' newtonOn/bin/demGrid
! grep -q 'rj\[~image' newtonOn/bin/demGrid || fail "negative control: cannot remove the second count"
mustFail countChecks "$work/newtonOn/bin/demGrid" "a pair across ranks counted once" \
    "busiest rank has"

countChecks "$INTERDEMFOAM_DIR/bin/demGrid"
chosen=$(demGrid grains.dump 4 --skin "$skin" --best) || fail "demGrid --best failed"
[ "$chosen" = "$best" ] \
    || fail "demGrid --best chose '$chosen'; LIGGGHTS's least loaded busiest rank is grid '$best' ($bestMax pairs)"
pass "demGrid's counts equal LIGGGHTS's on 1 rank ($serialPairs pairs) and on grids" \
     "1x4x1, 2x2x1, 4x1x1; it chooses '$chosen' (busiest rank $bestMax pairs)"
