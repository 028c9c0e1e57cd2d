#!/bin/bash
# Packed bed, short version of tutorials/interDemFoam/packedBed: 825 glass
# beads (d = 2 mm) poured into a 12 x 12 mm periodic column, held fixed,
# water at a superficial 15 mm/s (Re = 30). The pressure gradient between
# z = 10 and 30 mm must be within 10 % of Ergun's at the bed's own eps for
# the dense drag law given ($1, default GidaspowDrag), and dragSettling
# must give the seed's terminal velocity through the library's Di Felice law.
#   packedBed.sh fluidize: the bed released at 30 mm/s (above U_mf): water
#   fills the column, so alpha must stay 1 (to 1e-6) while eps changes every
#   step, and the water volume sum(eps alpha V) must not change.
. "$(dirname "$0")/caseFunctions.sh"
law="${1:-GidaspowDrag}"

copyTutorial packedBed "packedBed-$law"

sed -i 's/^width .*/width   0.012;/; s/^nCells .*/nCells  3;/' system/blockMeshDict
liggghts -in DEM/in.pour -var width 0.012 -var nBeads 825 -echo none \
    -log log.pour > /dev/null || fail "LIGGGHTS pour failed (log.pour)"

cp -r 0.orig 0

if [ "$law" = fluidize ]
then
    printf '(\n    (0 (0 0 0.03))\n    (1 (0 0 0.03))\n)\n' > constant/inletVelocity
    setEntry constant/couplingProperties demScript '"DEM/in.fluidize"'
    setEntry system/controlDict endTime 0.1
    setEntry system/controlDict writeInterval 0.1
    runApplication blockMesh || fail "blockMesh"
    runApplication interDemFoam || fail "interDemFoam failed (log.interDemFoam)"
    # alpha extremes and water volume of every step
    awk '/water volume/ {
            for (i = 1; i <= NF; i++) {
                if ($i ~ /^Min\(alpha/) { v = $(i+2); if (v < amin || !n) amin = v }
                if ($i ~ /^Max\(alpha/) { v = $(i+2); if (v > amax || !n) amax = v }
                if ($i == "V)") { w = $(i+2); if (!n) w0 = w; d = (w - w0)/w0; if (d < 0) d = -d; if (d > dmax) dmax = d }
            }
            n++
         }
         END { printf "%d steps: alpha in [%.9g, %.9g], water volume drift %.3e\n", n, amin, amax, dmax
               exit !(n > 100 && amin > 1 - 1e-6 && amax < 1 + 1e-6 && dmax < 1e-9) }' \
        log.interDemFoam || fail "alpha left [1 - 1e-6, 1 + 1e-6] or water volume drifted"
    rise=$(awk '!/^#/ { if (!n++) z0 = $2; z = $2 } END { printf "%.3e", z - z0 }' DEM/bedHeight.dat)
    awk -v r="$rise" 'BEGIN { exit !(r > 1e-4) }' \
        || fail "the bed did not move (centre of mass rose $rise m)"
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
runApplication interDemFoam || fail "interDemFoam failed (log.interDemFoam)"

mkdir -p runs && ln -s .. "runs/fixedBed.$law"
(cd runs && /usr/bin/python3 "$runDir/packedBed-$law/plotPackedBed.py" fixed \
    "fixedBed.$law" --noPlot --check 0.10) || fail "pressure gradient vs Ergun"

# The settling utility through the same library: seed Table 1, 0.1341 m/s
v=$(dragSettling -drag DiFeliceDrag -d 0.001 -rhoP 2500 | sed -n 's/.* vTerminal \([^ ]*\) .*/\1/p')
awk -v v="$v" 'BEGIN { e = v/0.1341 - 1; if (e < 0) e = -e; exit !(e < 0.005) }' \
    || fail "dragSettling terminal velocity $v, expected 0.1341 m/s within 0.5 %"
pass "$law bed within 10 % of Ergun; dragSettling terminal velocity $v m/s"
