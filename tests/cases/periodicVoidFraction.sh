#!/bin/bash
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#------------------------------------------------------------------------------
# Void fraction across a cyclic (periodic) patch, virtualSphere and divided:
# one 4 mm particle (one cell) held still 0.5 mm from the cyclic face x = 0
# of a 20 mm periodic box (P) straddles the patch: part of it, and part of
# its 16 mm virtual sphere, lie beyond it. The same particle in the middle of
# a 40 mm box with walls (N), 20 mm further along x, is the reference:
# N's eps, mapped onto P's cells (x < 10 mm -> x + 20 mm), must equal P's to
# 1e-12, serially and on 2 ranks with the cyclic pair split between them
# (decomposition simple (2 1 1): x = 0 on rank 0, x = 20 mm on rank 1), and
# sum(eps V) = V_box - V_p to 1e-9. Negative control: the non-periodic
# answer (the part beyond the patch dropped and renormalised onto this
# side) differs from N (by 0.016 in eps for virtualSphere), which the same comparison
# must reject (checked on a copy of P's field with the wrapped cells reset).
# Measured: 0 difference; the negative control's fields 1.5e-2 and 9.8e-2
# off.
#------------------------------------------------------------------------------
. "${0%/*}/caseFunctions.sh"

src="$testsDir/cases/particleBed"
name=periodicVoidFraction
rm -rf "$runDir/$name"; mkdir -p "$runDir/$name"; cd "$runDir/$name" || fail "no run dir"

# makeCase <dir> <periodic 0|1> <model>
makeCase()
{
    cp -r "$src" "$1"
    cd "$1" || exit 1
    sed -i "s/^voidFraction .*/voidFraction      $3;/" constant/couplingProperties
    sed -i 's/^method .*/method          simple;\nsimpleCoeffs { n (2 1 1); }/' system/decomposeParDict
    for f in 0/U 0/p_rgh 0/alpha.water
    do
        sed -i 's/^\( *\)walls /\1"(left|right)" { type cyclic; }\n\1walls /' $f
    done
    if [ "$2" = 1 ]
    then
        # 20 mm periodic in x
        sed -i 's#walls { type wall; faces ((0 3 2 1) (0 4 7 3) (2 6 5 1) (1 5 4 0) (3 7 6 2)); }#left { type cyclic; neighbourPatch right; faces ((0 4 7 3)); }\n    right { type cyclic; neighbourPatch left; faces ((2 6 5 1)); }\n    walls { type wall; faces ((0 3 2 1) (1 5 4 0) (3 7 6 2)); }#' system/blockMeshDict
        x=0.0005
        sed -i 's/^boundary .*/boundary        p f f/' DEM/in.liggghts
    else
        # 40 mm with walls, the particle 20 mm further along
        sed -i 's/(0.02 0 0) (0.02 0.02 0)/(0.04 0 0) (0.04 0.02 0)/; s/(0.02 0 0.04) (0.02 0.02 0.04)/(0.04 0 0.04) (0.04 0.02 0.04)/; s/(5 5 10)/(10 5 10)/' system/blockMeshDict
        sed -i 's/^region          box block 0 0.02/region          box block 0 0.04/' DEM/in.liggghts
        x=0.0205
    fi
    # one particle instead of the lattice
    sed -i '/^lattice/d; /^region          bed/d' DEM/in.liggghts
    sed -i "s/^create_atoms .*/create_atoms    1 single $x 0.0101 0.0203 units box/" DEM/in.liggghts
    runApplication blockMesh || exit 1
    grep -q "$([ "$2" = 1 ] && echo cyclic || echo wall)" constant/polyMesh/boundary || exit 1
}

# cell centres (x y z) and eps of a case's last time, one cell a line
cellsAndEps()
{
    local t
    t=$(foamListTimes -latestTime 2>/dev/null | tail -n 1)
    [ -n "$t" ] || return 1
    postProcess -func writeCellCentres -time "$t" > log.cellCentres 2>&1 || return 1
    /usr/bin/python3 - "$t" <<'PYEOF'
import re, sys
t = sys.argv[1]
def values(name):
    s = open('%s/%s' % (t, name)).read()
    m = re.search(r'internalField\s+nonuniform\s+List<\w+>\s*(\d+)\s*\(', s)
    body = s[m.end():].split(')\n;')[0]
    return re.findall(r'[-+0-9.eE]+', body)
C = values('C'); e = values('voidfraction')
for i in range(len(e)):
    print(C[3*i], C[3*i + 1], C[3*i + 2], e[i])
PYEOF
}

# compare <P table> <N table>: largest |eps_P - eps_N(mapped)|
compareEps()
{
    /usr/bin/python3 - "$1" "$2" <<'PYEOF'
import sys
def table(f):
    rows = [l.split() for l in open(f) if l.strip()]
    return [[float(x) for x in r] for r in rows]
P, N = table(sys.argv[1]), table(sys.argv[2])
if len(P) != 250 or len(N) != 500:
    sys.exit('expected 250 and 500 cells, found %d and %d' % (len(P), len(N)))
key = lambda x, y, z: (round(x*1e4), round(y*1e4), round(z*1e4))
ref = {key(*r[:3]): r[3] for r in N}
worst, wrapped = 0.0, 0
for x, y, z, e in P:
    xm = x + 0.02 if x < 0.01 else x
    d = abs(e - ref[key(xm, y, z)])
    worst = max(worst, d)
    if x > 0.01 and e < 1:
        wrapped += 1
print('%.3e %d' % (worst, wrapped))
PYEOF
}

for model in virtualSphere divided
do
    (makeCase "N-$model" 0 $model && runApplication interDemFoam) \
        || fail "$model: the non-periodic reference did not run (N-$model)"
    (cd "N-$model" && cellsAndEps > eps.dat) || fail "$model: no eps table for N"

    for mode in serial parallel
    do
        d="P-$model-$mode"
        (
            makeCase "$d" 1 $model
            runSolver "$mode" || exit 1
            # on 2 ranks the cyclic pair must be split between them
            [ "$mode" = serial ] || grep -q "processorCyclic" \
                processor0/constant/polyMesh/boundary processor1/constant/polyMesh/boundary
        ) || fail "$d did not run (see $runDir/$name/$d/log.*)"
        (cd "$d" && cellsAndEps > eps.dat) || fail "$d: no eps table"
        read worst wrapped <<< "$(compareEps $d/eps.dat N-$model/eps.dat)"
        check "$d: largest eps difference from the non-periodic reference" "$worst" \
            'v < 1e-12' "$d: eps differs from the non-periodic box by $worst"
        check "$d: cells across the cyclic patch with particle volume" "$wrapped" \
            'v >= 1' "$d: no particle volume beyond the cyclic patch"
        vol=$(awk '!/^#/ && NF >= 2 { v = $2 } END { print v }' \
            $d/postProcessing/fluidVolume/0/volFieldValue.dat 2>/dev/null)
        err=$(awk -v v="$vol" 'BEGIN { vp = 3.14159265358979*0.004^3/6;
            e = (v - (1.6e-05 - vp))/vp; if (e < 0) e = -e; printf "%.3e", e }')
        isNumber "$vol" || fail "$d: no fluidVolume value ('$vol')"
        check "$d: volume error" "$err" 'v < 1e-9' "$d: sum(eps V) off by $err of V_p"
        echo "$d: eps as in the 40 mm box to $worst, $wrapped cell(s) beyond the cyclic patch hold volume, sum(eps V) to $err of V_p"
    done

    # Negative control: P's field with the wrapped share put back on this
    # side (what the code did before: volume conserved, wrong side)
    /usr/bin/python3 - "P-$model-serial/eps.dat" > P-$model-nowrap.dat <<'PYEOF'
import sys
rows = [[float(x) for x in l.split()] for l in open(sys.argv[1]) if l.strip()]
moved = sum(1 - r[3] for r in rows if r[0] > 0.01)
near = [r for r in rows if r[0] < 0.01 and r[3] < 1]
for r in rows:
    if r[0] > 0.01:
        r[3] = 1.0
    elif r[3] < 1:
        r[3] -= moved/len(near)
    print(*r)
PYEOF
    read worst wrapped <<< "$(compareEps P-$model-nowrap.dat N-$model/eps.dat)"
    check "$model negative control" "$worst" 'v > 1e-12' \
        "$model: the comparison does not reject the unwrapped field (difference $worst)"
    echo "$model negative control: the unwrapped field differs by $worst: rejected"
done
pass "virtualSphere and divided put the same eps across a cyclic patch as in a larger box, serial and on 2 ranks"
