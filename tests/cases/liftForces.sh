#!/bin/bash
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#------------------------------------------------------------------------------
# Lift forces sampled on a mesh, coupled to LIGGGHTS (case tests/cases/
# liftForces: water in a 12 x 12 x 20 mm box periodic in x and y, cells of
# 4 mm, one 1 mm particle held at the centre of a cell, (6, 6, 10) mm, no
# gravity, voidFraction centre, only the lift model under test). The fluid
# force F on the particle is read from the Lagrangian field
# <time>/lagrangian/demParticles/F after 20 coupling steps.
#
#   liftForces.sh saffman   plane Couette flow, bottom wall at rest, top wall
#       at U_w = 20 mm/s: u = G z x, G = U_w/H = 1 1/s, vorticity curl u =
#       G y; the particle at rest lags the fluid by u = G z_p = 10 mm/s.
#       Seed eq. 15 in Saffman's form (SaffmanLift.H):
#         F = 1.61 d^2 (mu rho)^(1/2) |w|^(-1/2) (u - v) x w
#           = +1.61 d^2 (mu rho)^(1/2) G^(1/2) (G z_p) z = 1.61e-8 N z
#       toward the faster fluid (+z).
#       The top wall moving the other way (-20 mm/s): u and curl u both flip,
#       F stays +z (the particle still lags the flow).
#       Control: the same particle leading the flow (v = 2 u(z_p) = 20 mm/s
#       along x, held in place): u - v flips, so F must point to -z (the
#       slower fluid) with the same magnitude; the +z check fails on it.
#   liftForces.sh magnus    uniform flow u = 10 mm/s x (slip walls), the
#       particle held in place and spun at omega_p = 100 rad/s about +z
#       (LIGGGHTS fix move rotate about its own centre). Seed eq. 16 with
#       d^3 and the cross product (MagnusLift.H, Rubinow & Keller 1961):
#         F = pi/8 d^3 rho (curl u/2 - omega_p) x (u - v)
#           = -pi/8 d^3 rho omega_p U y = -3.93e-7 N y
#       Control: spin reversed (-100 rad/s): F must point to +y; the -y check
#       fails on it.
#   liftForces.sh sampling  the fluid velocity a particle sees, taken at its
#       centre (couplingProperties: fluidVelocity cellPoint; fluidSampler.H).
#       The Saffman case above with the particle off its cell's centre, at
#       z_p = 9 mm and 11.5 mm in the cell 8-12 mm (centre 10 mm): the
#       cell-point interpolation of the linear profile is exact, so u =
#       G z_p and F_z = 1.61 d^2 (mu rho)^(1/2) G^(1/2) G z_p (F is linear
#       in u - v). Control: the default, voidFractionAverage (here the
#       centre model's host-cell value, G 10 mm): F_z 11 % above the
#       9 mm value, so the 9 mm check fails on it; it must match the 10 mm
#       value instead.
#   liftForces.sh wibergSmith   bed lift from the flow over a grain's top and
#       under its bottom (WibergSmithLift.H, Wiberg & Smith 1985): the
#       Couette flow of the Saffman case with gravity (0 0 -9.81), C_L 0.2,
#       the particle at rest at z_p = 10 mm. Its top and bottom, z_p +- d/2,
#       lie in its cell, where the reconstruction of the linear profile is
#       exact: u_T,B = G (z_p +- d/2), and
#         F = 1/2 C_L rho (pi d^2/4) (u_T^2 - u_B^2) z
#           = C_L rho (pi d^2/4) G^2 z_p d z = 1.5708e-9 N z.
#       The same particle leading the flow (v = 2 G z_p along x): the
#       relative velocities swap sizes and F must point to -z with the same
#       magnitude; the +z check fails on it. Moving with the flow at its
#       centre (v = G z_p): the top and the bottom see the same relative
#       speed and F must vanish (below 1 % of the lagging value). At rest
#       in the uniform stream (10 mm/s) with fixed eddies (intensity 0.75,
#       eddyTime 1e-4 s: u' of order 7.5 mm/s): the same eddy passes over
#       the top and the bottom, so F must vanish (below 0.1 % of the
#       lagging value, 1.6e-12 N); a grain whose eddy were added to its
#       top alone would feel 1/2 C_L rho A (2 U u'_x + |u'_h|^2), of order
#       1e-8 N. Build controls, run by hand: a library that samples the
#       bottom at the top (height +d/2 for both) gives F = 0 and fails; one
#       that adds the eddy to the top alone fails the uniform stream.
#
# Tolerance 2 % on the magnitude, and the other two components below 1 % of
# it. The imposed flows are exact solutions that the mesh represents
# exactly (a linear profile has an exact cell-centre value and Gauss-linear
# curl; a uniform flow has none to get wrong), and the particle sits at
# the cell centre, where the centre model samples. What remains is the
# particle's own volume in its cell (eps = 1 - V_p/V_cell = 0.992: the flow
# is slightly displaced around that cell, under 0.8 % of u) and the
# 12-digit output.
# Measured: saffman +0.10 % of 1.61e-8 N, magnus +0.10 % of 3.93e-7 N,
# sampling +0.06 % (z_p = 9 mm) and +0.03 % (11.5 mm); the default average
# within 0.1 % of the 10 mm value.
#------------------------------------------------------------------------------
. "$(dirname "$0")/caseFunctions.sh"
mode="${1:-saffman}"
tolerance=0.02
fluctuation=""   # velocityFluctuation entry of the next run (none: "")

# run <name> <force model> <flow: couette | couetteReversed | uniform>
# <DEM motion> [<particle's z> [<fluidVelocity>]]: the case
# in tests/run/liftForces-<name>; sets force to the particle's "Fx Fy Fz"
# (WibergSmithLift: with gravity, C_L 0.2)
run()
{
    local name=$1 model=$2 ubody=$3 motion=$4 zp=${5:-0.01} sampling=${6:-}
    local dir="$runDir/liftForces-$name"
    rm -rf "$dir" && mkdir -p "$runDir" && cp -r "$testsDir/cases/liftForces" "$dir" \
        && cd "$dir" || fail "cannot set up $dir"
    setEntry constant/couplingProperties forces "( $model )"
    if [ "$model" = WibergSmithLift ]
    then
        foamDictionary -entry WibergSmithLiftCoeffs -add "{ liftCoefficient 0.2; }" \
            constant/couplingProperties > /dev/null || fail "$name: cannot set C_L"
        foamDictionary -entry value -set "(0 0 -9.81)" constant/g > /dev/null \
            || fail "$name: cannot set gravity"
    fi
    printf '%s\n' "$motion" > DEM/in.motion
    sed -i "s/^create_atoms    1 single 0.006 0.006 0.01 units box$/create_atoms    1 single 0.006 0.006 $zp units box/" \
        DEM/in.liggghts
    grep -q "^create_atoms    1 single 0.006 0.006 $zp units box$" DEM/in.liggghts \
        || fail "$name: cannot place the particle at z = $zp"
    if [ -n "$sampling" ]
    then
        foamDictionary -entry fluidVelocity -add "$sampling" constant/couplingProperties > /dev/null \
            || fail "$name: cannot set fluidVelocity $sampling"
    fi
    if [ -n "$fluctuation" ]
    then
        foamDictionary -entry velocityFluctuation -add "$fluctuation" constant/couplingProperties > /dev/null \
            || fail "$name: cannot set velocityFluctuation"
    fi
    runApplication blockMesh > /dev/null || fail "$name: blockMesh"
    # 0/U: the imposed flow, cells in blockMesh order (x fastest, then y, z)
    /usr/bin/python3 - "$ubody" > 0/U <<'PY' || fail "$name: cannot write 0/U"
import sys
kind, H = sys.argv[1], 0.02
Uw = -0.02 if kind == 'couetteReversed' else 0.02
print('FoamFile { version 2.0; format ascii; class volVectorField; location "0"; object U; }')
print('dimensions [0 1 -1 0 0 0 0];')
if kind.startswith('couette'):
    rows = ['(%.12g 0 0)' % (Uw*(k + 0.5)*0.004/H) for k in range(5) for j in range(3) for i in range(3)]
    print('internalField nonuniform List<vector> %d (\n%s\n);' % (len(rows), '\n'.join(rows)))
    print('boundaryField { bottom { type noSlip; } top { type fixedValue; value uniform (%g 0 0); }' % Uw)
else:
    print('internalField uniform (0.01 0 0);')
    print('boundaryField { "(bottom|top)" { type slip; }')
print('"(left|right|front|back)" { type cyclic; } }')
PY
    runApplication interDemFoam > /dev/null || fail "$name: interDemFoam failed (see $dir/log.interDemFoam)"
    grep -q "^End" log.interDemFoam || fail "$name: run did not reach the end"
    ! grep -q "outside the fluid mesh" log.interDemFoam || fail "$name: the particle is outside the mesh"
    [ -f 0.002/lagrangian/demParticles/F ] || fail "$name: no 0.002/lagrangian/demParticles/F"
    # the one particle's force vector
    # (a list of one vector, "1((fx fy fz))" or over several lines)
    force=$(/usr/bin/python3 - 0.002/lagrangian/demParticles/F <<'PY'
import re, sys
s = open(sys.argv[1]).read()
s = s[s.index('FoamFile'):]
s = s[s.index('}') + 1:]
m = re.search(r'(\d+)\s*\((.*)\)', s, re.S)
vecs = re.findall(r'\(([^()]*)\)', m.group(2)) if m else []
if m and int(m.group(1)) == 1 and len(vecs) == 1:
    print(' '.join(vecs[0].split()))
PY
)
}

# checkForce <name> "Fx Fy Fz" <component 1..3> <expected signed value>:
# the component within the tolerance of the expected value, the other two
# below 1 % of it
checkForce()
{
    local name=$1 f=$2 c=$3 expected=$4
    set -- $f
    requireNumber "$name: Fx" "$1"; requireNumber "$name: Fy" "$2"; requireNumber "$name: Fz" "$3"
    local comp=${!c} rel
    rel=$(awk -v f="$comp" -v e="$expected" 'BEGIN { printf "%.5f", f/e - 1 }')
    echo "$name: F = ($1 $2 $3) N, component $c = $comp N, eq.: $expected N, relative error $rel"
    check "$name: direction" "$comp" "v*($expected) > 0" \
        "$name: force component $c = $comp N points the wrong way (expected $expected N)"
    check "$name: magnitude" "$rel" "v > -$tolerance && v < $tolerance" \
        "$name: force component $c = $comp N, expected $expected N within $tolerance"
    local i
    for i in 1 2 3
    do
        [ "$i" = "$c" ] && continue
        check "$name: component $i" "${!i}" "v < 0.01*sqrt(($expected)^2) && -v < 0.01*sqrt(($expected)^2)" \
            "$name: component $i = ${!i} N, not small against $expected N"
    done
}

# the check must fail on the control: run it in a subshell, expect failure
mustFail()
{
    local what=$1; shift
    local out
    if out=$("$@" 2>&1)
    then
        fail "negative control ($what): the check passed: $out"
    fi
    echo "negative control ($what) fails the check as it must: ${out##*FAIL: }"
}

d=0.001; rho=1000; mu=1e-3
case "$mode" in
saffman)
    G=1; zp=0.01
    Fz=$(awk -v d=$d -v r=$rho -v m=$mu -v G=$G -v z=$zp \
        'BEGIN { printf "%.6e", 1.61*d*d*sqrt(m*r)*sqrt(G)*G*z }')
    run saffman SaffmanLift couette "# held at rest (no integration)"; f=$force
    checkForce "Saffman, lagging particle" "$f" 3 "$Fz"
    run saffmanLeading SaffmanLift couette "velocity all set 0.02 0 0 units box"; fc=$force
    mustFail "Saffman, particle leading the flow, against the lagging particle's +z" \
        checkForce "Saffman, leading particle" "$fc" 3 "$Fz"
    checkForce "Saffman, leading particle (-z)" "$fc" 3 "-$Fz"
    # the top wall moving the other way: u and curl u both change sign, the
    # particle still lags the (now -x) flow and is still pushed to +z
    run saffmanWallReversed SaffmanLift couetteReversed "# held at rest"; fr=$force
    checkForce "Saffman, top wall reversed (+z)" "$fr" 3 "$Fz"
    pass "Saffman lift toward the faster fluid, $f N against (0 0 $Fz) N of eq. 15;" \
         "leading the flow: $fc N (toward the slower fluid); top wall reversed: $fr N"
    ;;
magnus)
    W=100; U=0.01
    Fy=$(awk -v d=$d -v r=$rho -v w=$W -v u=$U \
        'BEGIN { printf "%.6e", -atan2(0, -1)/8*d*d*d*r*w*u }')
    # rotation about the particle's own centre: it stays in place, spinning
    period=$(awk -v w=$W 'BEGIN { printf "%.12g", 2*atan2(0, -1)/w }')
    spin="fix spin all move rotate 0.006 0.006 0.01"
    run magnus MagnusLift uniform "$spin 0 0 1 $period"; f=$force
    checkForce "Magnus, spin +z" "$f" 2 "$Fy"
    run magnusReversed MagnusLift uniform "$spin 0 0 -1 $period"; fc=$force
    mustFail "Magnus, spin reversed, against the +z spin's -y" \
        checkForce "Magnus, spin -z" "$fc" 2 "$Fy"
    checkForce "Magnus, spin -z (+y)" "$fc" 2 "${Fy#-}"
    pass "Magnus lift $f N against (0 $Fy 0) N of eq. 16; spin reversed: $fc N"
    ;;
sampling)
    G=1
    saffmanAt() # <z_p>: eq. 15's F_z for the particle at rest at z_p
    {
        awk -v d=$d -v r=$rho -v m=$mu -v G=$G -v z=$1 \
            'BEGIN { printf "%.6e", 1.61*d*d*sqrt(m*r)*sqrt(G)*G*z }'
    }
    F9=$(saffmanAt 0.009); F115=$(saffmanAt 0.0115); F10=$(saffmanAt 0.01)
    run cellPoint9 SaffmanLift couette "# held at rest" 0.009 cellPoint; f9=$force
    grep -q "fluidVelocity cellPoint" "$runDir/liftForces-cellPoint9/log.interDemFoam" \
        || fail "the solver did not report fluidVelocity cellPoint"
    checkForce "cellPoint, z_p = 9 mm" "$f9" 3 "$F9"
    run cellPoint115 SaffmanLift couette "# held at rest" 0.0115 cellPoint; f115=$force
    checkForce "cellPoint, z_p = 11.5 mm" "$f115" 3 "$F115"
    run average9 SaffmanLift couette "# held at rest" 0.009; fc=$force
    mustFail "the default voidFractionAverage, against the 9 mm value" \
        checkForce "voidFractionAverage, z_p = 9 mm" "$fc" 3 "$F9"
    checkForce "voidFractionAverage, z_p = 9 mm (the host cell's 10 mm value)" "$fc" 3 "$F10"
    pass "fluid velocity at the particle's centre: F_z $f9 N at 9 mm (eq. 15 with u = G z_p: $F9 N)," \
         "$f115 N at 11.5 mm ($F115 N); the cell average gives $fc N at 9 mm (the centre's $F10 N)"
    ;;
wibergSmith)
    G=1; zp=0.01
    Fz=$(awk -v d=$d -v r=$rho -v G=$G -v z=$zp \
        'BEGIN { printf "%.6e", 0.2*r*atan2(0, -1)/4*d*d*G*G*z*d }')
    run wibergSmith WibergSmithLift couette "# held at rest (no integration)"; f=$force
    checkForce "Wiberg-Smith, grain at rest" "$f" 3 "$Fz"
    run wibergSmithLeading WibergSmithLift couette "velocity all set 0.02 0 0 units box"; fc=$force
    mustFail "Wiberg-Smith, grain leading the flow, against the resting grain's +z" \
        checkForce "Wiberg-Smith, leading grain" "$fc" 3 "$Fz"
    checkForce "Wiberg-Smith, leading grain (-z)" "$fc" 3 "-$Fz"
    run wibergSmithWithFlow WibergSmithLift couette "velocity all set 0.01 0 0 units box"; f0=$force
    set -- $f0
    requireNumber "Wiberg-Smith, with the flow: Fz" "$3"
    check "Wiberg-Smith, grain moving with the flow at its centre" "$3" \
        "v < 0.01*$Fz && -v < 0.01*$Fz" \
        "grain moving with the flow at its centre: F_z = $3 N, not below 1 % of $Fz N"
    # the same eddy over the top and the bottom: in a uniform stream the
    # lift vanishes whatever the fluctuation (top-only: 1/2 C_L rho A
    # (2 U u'_x + |u'_h|^2), of order 1e-8 N here)
    fluctuation="{ intensity 0.75; eddyTime 1e-4; seed 3; }"
    run wibergSmithEddies WibergSmithLift uniform "# held at rest (no integration)"; fe=$force
    fluctuation=""
    grep -q "velocity fluctuations seen by the particles" log.interDemFoam \
        || fail "Wiberg-Smith in a uniform stream: the fluctuations are not on"
    set -- $fe
    requireNumber "Wiberg-Smith, uniform stream with eddies: Fz" "$3"
    check "Wiberg-Smith, grain at rest in a uniform stream with eddies" "$3" \
        "v < 0.001*$Fz && -v < 0.001*$Fz" \
        "grain at rest in a uniform stream with eddies: F_z = $3 N, not below 0.1 % of $Fz N (the same eddy must pass over its top and bottom)"
    pass "Wiberg-Smith lift $f N against (0 0 $Fz) N;" \
         "leading the flow: $fc N; moving with it: $f0 N;" \
         "uniform stream with eddies: $fe N"
    ;;
*)
    fail "unknown mode '$mode' (saffman | magnus | sampling | wibergSmith)"
    ;;
esac
