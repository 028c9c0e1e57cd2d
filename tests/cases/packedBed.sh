#!/bin/bash
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
# Packed bed, short version of tutorials/interDemFoam/packedBed: 825 glass
# beads (d = 2 mm) poured into a 12 x 12 mm periodic column, held fixed,
# water at a superficial 15 mm/s (Re = 30). The pressure gradient between
# z = 10 and 30 mm must be within 10 % of Ergun's at the bed's own eps for
# the dense drag law given ($1, default GidaspowDrag), and dragSettling
# must give the seed's terminal velocity through the library's Di Felice law.
# With GidaspowDrag, a negative control: the same poured bed with
# SchillerNaumannDrag (no voidage correction) must miss Ergun by more than
# 50 % (it gives -81 %), so the 10 % check can fail.
#   packedBed.sh RongDrag pimpleDemFoam: the same bed also with the
#   single-phase solver (no VoF: water without alpha.water): its pressure
#   gradient within 10 % of Ergun and within 0.1 % of interDemFoam's on the
#   same bed (the two solve the same equations where alpha = 1), its
#   cumulative continuity error no larger than interDemFoam's (x 1.1; both
#   are set by the pressure solver's tolerance); both CPU times printed.
#   Negative control: pimpleDemFoam without the particles' drag (forces:
#   pressureGradient only) must miss Ergun by more than 50 %.
#   packedBed.sh fluidize: the bed released at 30 mm/s (above U_mf): water
#   fills the column, so alpha must stay 1 (to 1e-6) while eps changes every
#   step, and the water volume sum(eps alpha V) must not change.
#   packedBed.sh fluidizeSubCycled: the same with the phase fraction
#   semi-implicit (MULESCorr yes) and 3 sub-cycles per step.
#   packedBed.sh fluidizeEnvelopeCholesky: the same with the continuity
#   correction solved by PCG with the envelopeCholesky preconditioner
#   (system/fvSolution solvers.continuityPotential): the same alpha and
#   water-volume checks, and, the factor being the exact inverse of the
#   Laplacian on one processor (its cyclic faces included), every
#   continuityPotential solve meets 1e-13 in at most 2 iterations (DIC:
#   51-52 here; measured 1) and the factor is made once in the run (the
#   matrix is the same every step); the same column one cell across (every cell its own
#   cyclic neighbour in x and y), 0.01 s: at most 2 iterations too.
#   Negative controls, run by hand on builds made for them: a factor
#   without the cyclic faces' entries (48 iterations), one with only one
#   side of a self-coupled cell's faces (the one-cell column: 19).
# Reference: Ergun (1952) at the bed's eps; the seed's 0.1341 m/s. Measured:
# RongDrag -1.35 % (docs/sceneCheck.md); SchillerNaumannDrag -81 %;
# pimpleDemFoam -1.35 %, equal to interDemFoam to the 6 digits written,
# continuity error 1.209e-8 for both, without drag -99.96 %.
. "$(dirname "$0")/caseFunctions.sh"
law="${1:-GidaspowDrag}"
secondSolver="${2:-}"
case "$secondSolver" in
    ''|pimpleDemFoam) ;;
    *) fail "packedBed.sh: second argument: pimpleDemFoam or none, got '$secondSolver'" ;;
esac

copyTutorial packedBed "packedBed-$law${secondSolver:+-$secondSolver}"

sed -i 's/^width .*/width   0.012;/; s/^nCells .*/nCells  3;/' system/blockMeshDict
liggghts -in DEM/in.pour -var width 0.012 -var nBeads 825 -echo none \
    -log log.pour > /dev/null || fail "LIGGGHTS pour failed (log.pour)"

cp -r 0.orig 0

if [ "$law" = fluidizeSubCycled ]
then
    # the same check with the phase fraction semi-implicit, 3 sub-cycles
    semiImplicitAlpha 3
    law=fluidize
fi
envelopeCholesky=no
if [ "$law" = fluidizeEnvelopeCholesky ]
then
    foamDictionary -entry solvers/continuityPotential -set \
        "{ solver PCG; preconditioner envelopeCholesky; tolerance 1e-13; relTol 0; }" \
        system/fvSolution > /dev/null || fail "cannot set solvers/continuityPotential in system/fvSolution"
    envelopeCholesky=yes
    law=fluidize
fi
if [ "$law" = fluidize ]
then
    printf '(\n    (0 (0 0 0.03))\n    (1 (0 0 0.03))\n)\n' > constant/inletVelocity
    setEntry constant/couplingProperties demScript '"DEM/in.fluidize"'
    setEntry system/controlDict endTime 0.1
    setEntry system/controlDict writeInterval 0.1
    # with envelopeCholesky: a copy one cell across, every cell its own
    # cyclic neighbour in both directions (run below)
    oneCell="$runDir/packedBed-envelopeCholeskyOneCell"
    if [ "$envelopeCholesky" = yes ]
    then
        rm -rf "$oneCell" && cp -r . "$oneCell" || fail "cannot copy the case to $oneCell"
    fi
    runApplication blockMesh || fail "blockMesh"
    runApplication interDemFoam || fail "interDemFoam failed (log.interDemFoam)"
    # alpha extremes and water volume of every step
    # (every step's line must hold all three as numbers: a line without
    # them, or no line, fails)
    awk -v num='^[-+]?([0-9]+\\.?[0-9]*|\\.[0-9]+)([eE][-+]?[0-9]+)?$' '/water volume/ {
            na = nb = nw = 0
            for (i = 1; i <= NF; i++) {
                if ($i ~ /^Min\(alpha/) { v = $(i+2); na += (v ~ num); if (v < amin || !n) amin = v }
                if ($i ~ /^Max\(alpha/) { v = $(i+2); nb += (v ~ num); if (v > amax || !n) amax = v }
                if ($i == "V)") { w = $(i+2); nw += (w ~ num); if (!n) w0 = w; d = (w - w0)/w0; if (d < 0) d = -d; if (d > dmax) dmax = d }
            }
            if (na != 1 || nb != 1 || nw != 1 || w0 <= 0) { bad = 1; exit }
            n++
         }
         END { if (bad) { print "a water volume line without Min(alpha), Max(alpha) or the volume:"; print; exit 1 }
               printf "%d steps: alpha in [%.9g, %.9g], water volume drift %.3e\n", n, amin, amax, dmax
               exit !(n > 100 && amin > 1 - 1e-6 && amax < 1 + 1e-6 && dmax < 1e-9) }' \
        log.interDemFoam || fail "alpha left [1 - 1e-6, 1 + 1e-6] or water volume drifted (or not in the log)"
    if [ "$envelopeCholesky" = yes ]
    then
        solves=$(grep -c "envelopeCholeskyPCG:  Solving for continuityPotential" log.interDemFoam)
        check "continuityPotential solves with envelopeCholesky" "$solves" 'v > 100' \
            "only $solves continuityPotential solves with envelopeCholesky in log.interDemFoam"
        # mostIterations <log> <fewest solves>: the most PCG iterations of
        # a continuityPotential solve in <log>; nothing (a failed check)
        # when a count is not a number or there are fewer solves
        mostIterations()
        {
            awk -v fewest="$2" '/Solving for continuityPotential/ { n = $NF; if (n !~ /^[0-9]+$/) { bad = 1; exit } if (n > m) m = n; k++ }
                                END { if (!bad && k >= fewest) print m }' "$1"
        }
        most=$(mostIterations log.interDemFoam 1)
        check "most PCG iterations of a continuityPotential solve" "$most" 'v <= 2' \
            "a continuityPotential solve took $most iterations (an exact factor takes 1)"
        made=$(grep -c "envelopeCholesky: factorised the matrix of continuityPotential" log.interDemFoam)
        check "factorisations of continuityPotential's matrix" "$made" 'v == 1' \
            "continuityPotential's matrix was factorised $made times (once expected: it does not change)"
        echo "envelopeCholesky: $solves solves, at most $most iteration(s), $made factorisation"
        (
            cd "$oneCell" || exit 1
            sed -i 's/^nCells .*/nCells  1;/' system/blockMeshDict
            foamDictionary -entry endTime -set 0.01 system/controlDict > /dev/null &&
            runApplication blockMesh && runApplication interDemFoam
        ) || fail "the column one cell across did not run ($oneCell/log.interDemFoam)"
        grep -q "nCells:[[:space:]]*30 " "$oneCell/constant/polyMesh/owner" \
            || fail "the column one cell across does not have 30 cells"
        mostOne=$(mostIterations "$oneCell/log.interDemFoam" 10)
        check "most PCG iterations, the column one cell across (self-coupled cyclic cells)" "$mostOne" 'v <= 2' \
            "one cell across: a continuityPotential solve took $mostOne iterations, or fewer than 10 solves"
        echo "envelopeCholesky, one cell across: at most $mostOne iteration(s)"
    fi
    rise=$(awk '!/^#/ && NF >= 2 { if (!n++) z0 = $2; z = $2 } END { if (n >= 2) printf "%.3e", z - z0 }' DEM/bedHeight.dat)
    check "rise of the bed's centre of mass" "$rise" 'v > 1e-4' \
        "the bed did not move (centre of mass rose $rise m)"
    pass "fluidized bed: alpha stays 1, water volume conserved, bed rose $rise m"
fi

cat > constant/inletVelocity <<'TABLE'
(
    (0    (0 0 0.015))
    (1    (0 0 0.015))
)
TABLE
setEntry constant/couplingProperties forces "( $law pressureGradient )"
setEntry system/controlDict endTime 0.05
setEntry system/controlDict writeInterval 0.05

runApplication blockMesh || fail "blockMesh"
runApplication -s cells postProcess -func writeCellCentres -time 0 || fail "writeCellCentres"

# ergunError <case> <law>: relative error of the bed's pressure gradient
# against Ergun at the bed's eps (plotPackedBed.py's one row for <law>);
# fails unless that row is there with a number
ergunError()
{
    (
        cd "$1" && mkdir -p runs && ln -sfn .. "runs/fixedBed.$2" && cd runs &&
        /usr/bin/python3 ../plotPackedBed.py fixed "fixedBed.$2" --noPlot > log.plotPackedBed 2>&1
    ) || { cat "$1/runs/log.plotPackedBed" 1>&2; return 1; }
    cat "$1/runs/log.plotPackedBed" 1>&2
    awk -v law="$2" '!/^#/ && $1 == law { n++; e = $7 } END { if (n != 1) exit 1; print e }' \
        "$1/runs/pressureDrop.dat"
}

# Negative control (with the Gidaspow test only): the same bed with
# Schiller-Naumann drag, which has no voidage correction, must miss Ergun
# by far more than 10 % (it gives a fraction of the dense bed's drag)
control="$runDir/packedBed-SchillerNaumannControl"
if [ "$law" = GidaspowDrag ]
then
    rm -rf "$control" && cp -r . "$control"
fi

# The single-phase copy of the case (pimpleDemFoam): no alpha.water, one
# fluid in transportProperties
single="$runDir/packedBed-$law-single"
singleNoDrag="$runDir/packedBed-$law-singleNoDrag"
if [ -n "$secondSolver" ]
then
    rm -rf "$single" "$singleNoDrag" && cp -r . "$single"
    (
        cd "$single" || exit 1
        rm -f 0/alpha.water 0.orig/alpha.water
        cat > constant/transportProperties <<'PROPS'
FoamFile { version 2.0; format ascii; class dictionary; object transportProperties; }
transportModel  Newtonian;
nu              1e-06;
rho             1000;
PROPS
    ) || fail "could not make the single-phase case"
    cp -r "$single" "$singleNoDrag"
fi

runApplication interDemFoam || fail "interDemFoam failed (log.interDemFoam)"
err=$(ergunError . "$law") || fail "$law: no pressure gradient against Ergun (runs/log.plotPackedBed)"
check "$law: error against Ergun" "$err" 'v > -0.10 && v < 0.10' \
    "$law: pressure gradient off Ergun by $err (10 % allowed)"

if [ "$law" = GidaspowDrag ]
then
    (
        cd "$control" || exit 1
        setEntry constant/couplingProperties forces "( SchillerNaumannDrag pressureGradient )"
        runApplication interDemFoam
    ) || fail "Schiller-Naumann control run failed ($control/log.interDemFoam)"
    errSN=$(ergunError "$control" SchillerNaumannDrag) \
        || fail "Schiller-Naumann control: no pressure gradient against Ergun"
    check "SchillerNaumannDrag: error against Ergun" "$errSN" 'v < -0.5' \
        "negative control: Schiller-Naumann drag is off Ergun by only $errSN (below -50 % expected)"
    echo "negative control: Schiller-Naumann drag off Ergun by $errSN (fails the 10 % check)"
fi

if [ -n "$secondSolver" ]
then
    ( cd "$single" && runApplication pimpleDemFoam ) \
        || fail "pimpleDemFoam failed ($single/log.pimpleDemFoam)"
    grep -q "^End" "$single/log.pimpleDemFoam" || fail "pimpleDemFoam did not end"
    errSingle=$(ergunError "$single" "$law") \
        || fail "pimpleDemFoam: no pressure gradient against Ergun"
    check "pimpleDemFoam $law: error against Ergun" "$errSingle" 'v > -0.10 && v < 0.10' \
        "pimpleDemFoam: pressure gradient off Ergun by $errSingle (10 % allowed)"
    dpTwo=$(awk '!/^#/ { print $5; exit }' runs/pressureDrop.dat)
    dpOne=$(awk '!/^#/ { print $5; exit }' "$single/runs/pressureDrop.dat")
    rel=$(awk -v a="$dpOne" -v b="$dpTwo" 'BEGIN { d = (a - b)/b; printf "%.3e", d < 0 ? -d : d }')
    check "pimpleDemFoam against interDemFoam, relative difference of dp/dz" "$rel" 'v < 1e-3' \
        "pimpleDemFoam's pressure gradient $dpOne Pa/m differs from interDemFoam's $dpTwo Pa/m by $rel (0.1 % allowed)"
    cont=$(awk '/continuity errors/ { c = $NF } END { if (c != "") print (c < 0 ? -c : c) }' "$single/log.pimpleDemFoam")
    contTwo=$(awk '/continuity errors/ { c = $NF } END { if (c != "") print (c < 0 ? -c : c) }' log.interDemFoam)
    requireNumber "interDemFoam cumulative continuity error" "$contTwo"
    check "pimpleDemFoam cumulative continuity error" "$cont" "v <= 1.1*$contTwo + 1e-15" \
        "pimpleDemFoam: cumulative continuity error $cont, above interDemFoam's $contTwo on the same bed"
    wallTwo=$(awk '/^ExecutionTime/ { t = $3 } END { print t }' log.interDemFoam)
    wallOne=$(awk '/^ExecutionTime/ { t = $3 } END { print t }' "$single/log.pimpleDemFoam")
    (
        cd "$singleNoDrag" || exit 1
        setEntry constant/couplingProperties forces "( pressureGradient )"
        runApplication pimpleDemFoam
    ) || fail "pimpleDemFoam negative control failed ($singleNoDrag/log.pimpleDemFoam)"
    errNoDrag=$(ergunError "$singleNoDrag" "$law") \
        || fail "pimpleDemFoam negative control: no pressure gradient"
    check "pimpleDemFoam without drag: error against Ergun" "$errNoDrag" 'v < -0.5' \
        "negative control: without drag pimpleDemFoam is off Ergun by only $errNoDrag (below -50 % expected)"
    pass "$law bed: interDemFoam off Ergun by $err, pimpleDemFoam by $errSingle" \
         "(difference $rel, cumulative continuity error $cont vs $contTwo; CPU time" \
         "interDemFoam $wallTwo s, pimpleDemFoam $wallOne s);" \
         "negative control without drag: $errNoDrag"
fi

# The settling utility through the same library: seed Table 1, 0.1341 m/s
v=$(dragSettling -drag DiFeliceDrag -d 0.001 -rhoP 2500 | sed -n 's/.* vTerminal \([^ ]*\) .*/\1/p')
check "dragSettling terminal velocity" "$v" 'v > 0.1341*0.995 && v < 0.1341*1.005' \
    "dragSettling terminal velocity $v, expected 0.1341 m/s within 0.5 %"
pass "$law bed off Ergun by $err (10 % allowed)${errSN:+, Schiller-Naumann by $errSN};" \
     "dragSettling terminal velocity $v m/s"
