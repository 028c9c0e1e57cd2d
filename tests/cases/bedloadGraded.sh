#!/bin/bash
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#------------------------------------------------------------------------------
# A graded bed in the bedload channel (tutorials/interDemFoam/bedload,
# Allrun -grading; docs/erosion.md, Which grains move first): the small
# channel (0.08 x 0.06 m) with half its mass in 10 mm and half in 20 mm
# grains, the tutorial's default model, theta 0.3 on the bed's geometric
# mean diameter, 4 s. Asserts:
#   - bad -grading input stops Allrun with a message naming -grading and
#     what is allowed (shares summing to 1.1; a 50 mm diameter, where the
#     small channel allows 10-30 mm; "10-1")
#   - the bed poured: each class holds 0.5 +- 0.05 of its mass (the 20 mm
#     class is about 15 grains: one grain is 0.034 of the mass) and the
#     whole bed the default bed's 0.3247 kg (234 grains of 10 mm) within
#     one 20 mm grain (0.0111 kg)
#   - theta refers to the mass-weighted geometric mean diameter: dRef
#     0.0141421 m in caseSettings, and the forcing rho g S = theta (rho_s -
#     rho) g dRef / h within 1e-4
#   - bedloadAnalysis.py fractions: the classes' fluxes (sums of V u_x over
#     the dumps, every 0.1 s) add up to the flux LIGGGHTS writes to
#     DEM/flux.dat at the same times (compute reduce over the mobile grains)
#     within 1 %; a copy that takes the grains' volume from the radius as
#     if it were the diameter (1/8 of it) must fail that check (negative
#     control, run here)
#   - bedloadAnalysis.py fractions on made-up dumps (a 0.04 m square, 1 mm
#     grid: a 20 mm grain whose disk crosses x = 0.04 and covers, across
#     the periodic side, part of a 10 mm grain at x = 0.006; a 10 mm grain
#     hidden under the 20 mm one; a frozen 10 mm grain): the 10 mm class's
#     share of the surface seen from above is 0.1443 +- 0.015 (the exposed
#     part of its disk, pi r^2 less the lens of two circles 11 mm apart,
#     52.97 of 367.13 mm^2; the tolerance: the 1 mm grid counts 317 points
#     on the 20 mm disk's 314.16 mm^2 and 81 on the 10 mm disk's 78.54,
#     a few on each rim; measured 0.1365), its share of the mobile bed's mass 0.2 (the
#     frozen grain left out), its exposed grain moving (share 1), and the
#     resting 20 mm grain's fluid force 0.5 of its submerged weight; copies
#     without the periodic wrap (0.2) and counting the frozen grain
#     (0.273) must fail (negative controls, run here)
#   - Wilcock & Crowe (2003) as bedloadAnalysis.py codes it, against their
#     equations worked by hand: at the reference stress of the surface's
#     mean size W* = 0.002 (their Eq. 7 at phi = 1); for 10/20 mm in equal
#     shares at twice that stress the hiding function (Eq. 3-4) gives
#     tau_r 0.930 and 1.118 of tau_rm, phi 2.150 and 1.789, W* 0.2029 and
#     0.0976: the fine class moves 2.08 times more per share (+-0.01); a
#     copy without the hiding function (b = 0) gives 1 and must fail
#     (negative control, run here)
#   - bedloadAnalysis.py mobile (for beds of 10 mm grains) refuses the
#     graded run, naming it
#   - -fluidVelocity roughnessLayer (the flow between the crests): Allrun
#     refuses -roughnessLayer without it and troughs above the zero plane
#     ("0.25 0.2"); on the graded bed it writes its d84 by mass, 0.02 m,
#     as the roughness diameter, and a 1 s run names the model with it in
#     its log
# About 25 s on one core.
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseFunctions.sh"

copyTutorial bedload bedloadGraded

# 1. Bad input
badGrading()   # <grading> <text the message must hold>
{
    local out
    out=$(./Allrun -size small -grading "$1" -theta 0.3 2>&1) \
        && fail "Allrun -grading \"$1\" ran, expected an error"
    echo "$out" | grep -q -- "-grading" && echo "$out" | grep -qF -- "$2" \
        || fail "Allrun -grading \"$1\": message '$out', expected -grading and '$2'"
    echo "bad -grading \"$1\": $out"
}
badGrading "10:0.6 20:0.5" "sum to 1.1, not 1"
badGrading "10:0.5 50:0.5" "each diameter 10-30 mm"
badGrading "10-1" "<diameter mm>:<mass share> pairs"

# -roughnessLayer: only with its model, troughs at or below the zero plane
badLayer()   # <text the message must hold> <Allrun options...>
{
    local out text="$1"; shift
    out=$(./Allrun -size small "$@" -theta 0.3 2>&1) \
        && fail "Allrun $* ran, expected an error"
    echo "$out" | grep -qF -- "$text" \
        || fail "Allrun $*: message '$out', expected '$text'"
    echo "bad $*: $out"
}
badLayer "-roughnessLayer is for -fluidVelocity roughnessLayer" -roughnessLayer "0.25 1"
badLayer "must be a number at least the crests' height 0.25 (the troughs at or below the zero plane), got '0.2'" -fluidVelocity roughnessLayer -roughnessLayer "0.25 0.2"

# 2. The run
./Allrun -size small -tag graded -grading "10:0.5 20:0.5" -theta 0.3 -endTime 4 > log.Allrun 2>&1 \
    || { tail -20 log.Allrun; fail "Allrun -grading (log.Allrun)"; }
run=graded.theta.0.3
cat $run/log.bedloadAnalysis

# 3. The poured bed: the classes' mass shares and the bed's mass
read -r share10 share20 mass <<< "$(/usr/bin/python3 - $run/post/grains.0.txt <<'EOF'
import math, sys
lines = open(sys.argv[1]).read().splitlines()
i = [k for k, l in enumerate(lines) if l.startswith('ITEM: ATOMS')][0]
cols = lines[i].split()[2:]
ir = cols.index('radius')
m = {}
for l in lines[i + 1:]:
    r = float(l.split()[ir])
    m[round(2000*r)] = m.get(round(2000*r), 0.0) + 2650*math.pi/6*(2*r)**3
total = sum(m.values())
print(m.get(10, 0.0)/total, m.get(20, 0.0)/total, total)
EOF
)"
echo "poured: 10 mm share $share10, 20 mm share $share20, mass $mass kg"
check "10 mm share" "$share10" 'v > 0.45 && v < 0.55' "the 10 mm class holds $share10 of the bed's mass, expected 0.5 +- 0.05"
check "20 mm share" "$share20" 'v > 0.45 && v < 0.55' "the 20 mm class holds $share20 of the bed's mass, expected 0.5 +- 0.05"
check "bed mass" "$mass" 'v > 0.3247 - 0.0111 && v < 0.3247 + 0.0111' \
    "the graded bed's mass is $mass kg, expected the default bed's 0.3247 kg within one 20 mm grain (0.0111 kg)"

# 4. theta on the geometric mean diameter
dRef=$(awk '$1 == "dRef" { sub(";", "", $2); print $2 }' $run/system/caseSettings)
forcing=$(awk '$1 == "forcing" { sub(";", "", $2); print $2 }' $run/system/caseSettings)
check "dRef" "$dRef" 'v > 0.0141421 - 1e-6 && v < 0.0141421 + 1e-6' "dRef $dRef m in caseSettings, expected sqrt(10 x 20) mm = 0.0141421 m"
check "forcing" "$forcing" 'v > 1144.56*(1 - 1e-4) && v < 1144.56*(1 + 1e-4)' \
    "forcing $forcing N/m3, expected 0.3 x 1650 x 9.81 x 0.0141421 / 0.06 = 1144.56"

# 5. The classes' fluxes against LIGGGHTS's own total
fluxCheck()   # <bedloadAnalysis.py to use>; prints the relative difference
{
    /usr/bin/python3 - "$1" $run <<'EOF'
import importlib.util, sys
spec = importlib.util.spec_from_file_location('b', sys.argv[1])
b = importlib.util.module_from_spec(spec); spec.loader.exec_module(b)
run = sys.argv[2]
rows, M, MWC = b.fractions(run)
s, flux, T, t0, tHalf, win = b.fluxWindow(run)
# flux.dat's rows at the dumps' times (every 1000 DEM steps = 0.1 s)
atDumps = [r[1] for r in flux if r[0] >= t0 - 1e-9
           and abs(r[0]*10 - round(r[0]*10)) < 1e-6]
q = sum(r['q'] for r in rows)
ref = b.mean(atDumps)
print('SUM', (q - ref)/ref, len(atDumps), q, ref)
EOF
}
out=$(fluxCheck bedloadAnalysis.py) || { echo "$out"; fail "bedloadAnalysis.py fractions $run"; }
echo "$out"
read -r tag relDiff nRows q ref <<< "$(echo "$out" | grep '^SUM')"
echo "fractions: sum of the classes' q $q m2/s, DEM/flux.dat at the $nRows dump times $ref m2/s"
check "class fluxes against DEM/flux.dat" "$relDiff" 'v > -0.01 && v < 0.01' \
    "the classes' fluxes add up to $q m2/s, DEM/flux.dat says $ref m2/s (relative difference $relDiff, expected within 1 %)"
# negative control: the volume from the radius taken as the diameter
sed 's|vol = math.pi/6\*(2\*r)\*\*3|vol = math.pi/6*r**3|' bedloadAnalysis.py > brokenAnalysis.py
cmp -s bedloadAnalysis.py brokenAnalysis.py && fail "negative control: the sed found no volume to break"
control=$(fluxCheck brokenAnalysis.py | awk '$1 == "SUM" { print $2 }')
echo "negative control (volume from the radius as a diameter): relative difference $control"
requireNumber "negative control's relative difference" "$control"
awk -v v="$control" 'BEGIN { exit !(v > -0.01 && v < 0.01) }' \
    && fail "negative control: the broken volume passed the flux check ($control)"

# 5b. The surface seen from above, on made-up dumps
madeUp()   # <bedloadAnalysis.py to use>: F_10, f_10, moving 10, 20, Fx/W' 20
{
    rm -rf madeUp && mkdir -p madeUp/system madeUp/DEM madeUp/post
    printf 'theta 0.2;\nforcing 500;\ndepth 0.06;\nlx 0.04;\nly 0.04;\ndRef 0.0141421;\n' \
        > madeUp/system/caseSettings
    awk 'BEGIN { print "# t qs Fx FxMob nMoving"; for (i = 0; i <= 20; i++) print i/10, 0, 0, 0, 0 }' \
        > madeUp/DEM/flux.dat
    local W20=0.0678048     # (2650 - 1000) 9.81 pi/6 0.02^3, N
    for step in 0 10000 20000
    do
        {
            printf 'ITEM: TIMESTEP\n%s\nITEM: NUMBER OF ATOMS\n4\n' $step
            printf 'ITEM: BOX BOUNDS pp pp ff\n0 0.04\n0 0.04\n0 0.2\n'
            echo "ITEM: ATOMS id x y z vx vy vz radius v_fxFluid v_fzFluid"
            echo "1 0.02 0.02 0.005 0 0 0 0.005 0 0"              # frozen (z < 1.5 r)
            echo "2 0.035 0.02 0.03 0 0 0 0.01 $(awk -v w=$W20 'BEGIN { print 0.5*w }') 0"
            echo "3 0.006 0.02 0.02 0.1 0 0 0.005 0 0"            # exposed, moving
            echo "4 0.035 0.02 0.012 0 0 0 0.005 0 0"             # under grain 2
        } > madeUp/post/grains.$step.txt
    done
    /usr/bin/python3 - "$1" <<'EOF'
import importlib.util, sys
spec = importlib.util.spec_from_file_location('b', sys.argv[1])
b = importlib.util.module_from_spec(spec); spec.loader.exec_module(b)
rows, M, MWC = b.fractions('madeUp')
f, c = rows[0], rows[-1]
print('MADEUP', f['F'], f['f'], f['moving'], c['moving'], c['fxOverW'])
EOF
}
out=$(madeUp bedloadAnalysis.py) || { echo "$out"; fail "bedloadAnalysis.py fractions on made-up dumps"; }
echo "$out"
read -r tag F10 f10 mov10 mov20 fxW20 <<< "$(echo "$out" | grep '^MADEUP')"
check "made-up: 10 mm share of the surface" "$F10" 'v > 0.1443 - 0.015 && v < 0.1443 + 0.015' \
    "made-up dumps: the 10 mm class holds $F10 of the surface seen from above, expected 0.1443 +- 0.015 (52.97 of 367.13 mm^2)"
check "made-up: 10 mm share of the bed" "$f10" 'v > 0.2 - 1e-6 && v < 0.2 + 1e-6' \
    "made-up dumps: the 10 mm class holds $f10 of the mobile bed's mass, expected 0.2 (the frozen grain left out)"
check "made-up: exposed 10 mm moving" "$mov10" 'v == 1' "made-up dumps: share $mov10 of the exposed 10 mm grains moving, expected 1"
check "made-up: exposed 20 mm moving" "$mov20" 'v == 0' "made-up dumps: share $mov20 of the exposed 20 mm grains moving, expected 0"
check "made-up: 20 mm force over weight" "$fxW20" 'v > 0.499 && v < 0.501' \
    "made-up dumps: the resting 20 mm grain's fluid force is $fxW20 of its submerged weight, expected 0.5"
# negative controls: no periodic wrap; the frozen grain counted
sed 's|key = (i % nx, j % ny)|key = (i, j)|' bedloadAnalysis.py > noWrap.py
sed 's|                     if float(w\[iz\]) < 1.5\*float(w\[ir\]))|                     if False)|' bedloadAnalysis.py > withFrozen.py
cmp -s bedloadAnalysis.py noWrap.py && fail "negative control: the sed found no periodic wrap to remove"
cmp -s bedloadAnalysis.py withFrozen.py && fail "negative control: the sed found no frozen grains to count"
F10No=$(madeUp noWrap.py | awk '$1 == "MADEUP" { print $2 }')
f10No=$(madeUp withFrozen.py | awk '$1 == "MADEUP" { print $3 }')
echo "negative controls: without the periodic wrap F_10 $F10No; with the frozen grain f_10 $f10No"
requireNumber "negative control (no wrap)" "$F10No"
requireNumber "negative control (frozen counted)" "$f10No"
awk -v v="$F10No" 'BEGIN { exit !(v > 0.1443 - 0.015 && v < 0.1443 + 0.015) }' \
    && fail "negative control: without the periodic wrap the surface share passed ($F10No)"
awk -v v="$f10No" 'BEGIN { exit !(v > 0.2 - 1e-6 && v < 0.2 + 1e-6) }' \
    && fail "negative control: counting the frozen grain the bed share passed ($f10No)"

# 6. Wilcock & Crowe against their equations worked by hand
wilcockCrowe()   # <bedloadAnalysis.py to use>: W* at phi 1, W*_10/W*_20
{
    /usr/bin/python3 - "$1" <<'EOF'
import importlib.util, math, sys
spec = importlib.util.spec_from_file_location('b', sys.argv[1])
b = importlib.util.module_from_spec(spec); spec.loader.exec_module(b)
d = 0.01
taurm = 0.036*(b.RHOS - b.RHO)*b.G*d
print(b.wilcockCrowe(taurm, [(d, 1.0)])[0][1], end=' ')
dsm = math.sqrt(0.01*0.02)
w = b.wilcockCrowe(2*0.036*(b.RHOS - b.RHO)*b.G*dsm, [(0.01, 0.5), (0.02, 0.5)])
print(w[0][1]/w[1][1])
EOF
}
read -r wRef ratio <<< "$(wilcockCrowe bedloadAnalysis.py)"
echo "Wilcock-Crowe: W* at the reference stress $wRef (0.002), fine over coarse at twice it $ratio (2.08)"
check "Wilcock-Crowe W* at phi 1" "$wRef" 'v > 0.002*(1 - 1e-9) && v < 0.002*(1 + 1e-9)' "W* $wRef at the reference stress, expected 0.002"
check "Wilcock-Crowe mobility 10/20 mm" "$ratio" 'v > 2.07 && v < 2.09' "W*_10/W*_20 $ratio at twice the reference stress, expected 2.08"
# negative control: no hiding function
sed 's|b = 0.67/(1.0 + math.exp(1.5 - d/dsm))|b = 0.0|' bedloadAnalysis.py > noHiding.py
cmp -s bedloadAnalysis.py noHiding.py && fail "negative control: the sed found no hiding function to remove"
read -r wRefNo ratioNo <<< "$(wilcockCrowe noHiding.py)"
echo "negative control (no hiding function): fine over coarse $ratioNo"
requireNumber "negative control's mobility ratio" "$ratioNo"
awk -v v="$ratioNo" 'BEGIN { exit !(v > 2.07 && v < 2.09) }' \
    && fail "negative control: without the hiding function the mobility check passed ($ratioNo)"

# 7. The monodisperse commands refuse a graded run
out=$(/usr/bin/python3 bedloadAnalysis.py mobile $run 2>&1) && fail "bedloadAnalysis.py mobile ran on the graded run"
echo "$out" | grep -q "$run: a graded bed" || fail "bedloadAnalysis.py mobile on the graded run: '$out', expected it to name the run and the graded bed"
echo "mobile on the graded run: $out"

# 8. The flow between the crests on the graded bed: D its d84 by mass
./Allrun -size small -tag layer -grading "10:0.5 20:0.5" -fluidVelocity roughnessLayer -theta 0.3 -endTime 1 > log.layer 2>&1 \
    || { tail -20 log.layer; fail "Allrun -fluidVelocity roughnessLayer (log.layer)"; }
layerD=$(foamDictionary -entry roughnessLayerCoeffs/roughnessDiameter -value layer.theta.0.3/constant/couplingProperties)
echo "roughnessLayer: roughness diameter $layerD m (the d84 by mass, 0.02)"
check "roughness diameter" "$layerD" 'v == 0.02' "roughnessLayerCoeffs/roughnessDiameter $layerD, expected 0.02 (the 20 mm class)"
grep -q "D 0.02 m) over the bed's zero plane" layer.theta.0.3/log.interDemFoam \
    || fail "the roughnessLayer run's log does not name its model with D 0.02 m"

pass "graded bed: poured shares $share10 / $share20, $mass kg; dRef $dRef; class fluxes within $relDiff of DEM/flux.dat (control $control); made-up surface F_10 $F10 (controls $F10No, $f10No); Wilcock-Crowe $wRef, $ratio (control $ratioNo)"
