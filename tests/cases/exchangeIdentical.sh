#!/bin/bash
#------------------------------------------------------------------------------
# The two particle exchanges give the same results. The cell-sized particle
# bed of voidFractionParallel (20 particles, d = dx = 4 mm, virtual sphere of
# 4 d, so spheres cross the METIS processor boundary), now falling in water
# under gravity for 60 coupling steps, on 2 ranks with
#   exchange allReduce;    (every rank holds every particle)
#   exchange manyToMany;   (each rank holds the particles that reach it)
# must write the same fields (U, p_rgh, voidfraction, Ksl, Us) and the same
# particles (position, U, fluid force F) to all 17 digits: both exchanges
# add the same terms in the same order, and on 2 ranks a sum of two terms
# does not depend on the order. With manyToMany a rank must hold fewer
# particles than the DEM has (else nothing was tested), and the particles
# must have moved (else the forces were never exercised).
#------------------------------------------------------------------------------
. "${0%/*}/caseFunctions.sh"

src="$testsDir/cases/particleBed"
name=exchangeIdentical
rm -rf "$runDir/$name"; mkdir -p "$runDir/$name"; cd "$runDir/$name" || fail "no run dir"

endTime=0.006
for exchange in allReduce manyToMany
do
    cp -r "$src" "$exchange"
    (
        cd "$exchange" || exit 1
        sed -i "s/^voidFraction .*/voidFraction      virtualSphere;/" constant/couplingProperties
        echo "exchange          $exchange;" >> constant/couplingProperties
        cat >> DEM/in.liggghts <<'DEM'
fix             gravi all gravity 9.81 vector 0.0 0.0 -1.0
fix             integr all nve/sphere
dump            state all custom 600 post/bed.*.dump id x y z vx vy vz
dump_modify     state sort id format "%d %.17g %.17g %.17g %.17g %.17g %.17g"
DEM
        mkdir -p post
        setEntry system/controlDict endTime $endTime
        setEntry system/controlDict writeInterval 60
        setEntry system/controlDict writePrecision 17
        runApplication blockMesh || exit 1
        runApplication decomposePar || exit 1
        runParallel interDemFoam || exit 1
        runApplication reconstructPar -latestTime || exit 1
        grep -q "^End" log.interDemFoam
    ) || fail "$exchange did not run (see $runDir/$name/$exchange/log.*)"
done

grep -q "Particle exchange between ranks: allReduce" allReduce/log.interDemFoam \
    || fail "allReduce was not selected"
grep -q "Particle exchange between ranks: manyToMany" manyToMany/log.interDemFoam \
    || fail "manyToMany was not selected"

t=$endTime
for f in U p_rgh voidfraction Ksl Us lagrangian/demParticles/U lagrangian/demParticles/F \
         lagrangian/demParticles/id
do
    [ -f "allReduce/$t/$f" ] || fail "allReduce wrote no $t/$f"
    cmp -s <(sed 1,/^FoamFile/d "allReduce/$t/$f") <(sed 1,/^FoamFile/d "manyToMany/$t/$f") \
        || fail "$f differs between allReduce and manyToMany (diff allReduce/$t/$f manyToMany/$t/$f)"
done
# positions: barycentric in v1912, whose tet may differ with the cell's
# decomposition; compare the particles' DEM positions from the DEM dump
for e in allReduce manyToMany
do
    awk '/^ITEM: ATOMS/ { f = 1; next } f' "$e/post/bed.600.dump" > "$e.atoms"
done
[ -s allReduce.atoms ] || fail "no DEM dump"
cmp -s allReduce.atoms manyToMany.atoms || fail "DEM positions/velocities differ (diff $runDir/$name/{allReduce,manyToMany}.atoms)"

held=$(sed -n 's/^Particles held per rank at the end: min \([0-9]*\), max \([0-9]*\) (of \([0-9]*\) in the DEM)/\1 \2 \3/p' manyToMany/log.interDemFoam)
set -- $held
[ $# -eq 3 ] || fail "no 'Particles held per rank' line in manyToMany/log.interDemFoam"
[ "$2" -lt "$3" ] || fail "manyToMany: a rank held $2 of $3 particles (all of them)"
heldAll=$(sed -n 's/^Particles held per rank at the end: min \([0-9]*\), .*/\1/p' allReduce/log.interDemFoam)
[ "$heldAll" = "$3" ] || fail "allReduce: a rank held $heldAll of $3 particles"

dz=$(awk '{ z = $3; if (NR == 1 || z > m) m = z } END { print m }' allReduce.atoms)
awk -v z="$dz" 'BEGIN { exit !(z < 0.0315 - 1e-5) }' \
    || fail "the particles did not fall (highest centre z = $dz m, started at 0.0315 m)"

pass "allReduce = manyToMany on 2 ranks to 17 digits (fields, particle U and F, DEM state after 60 steps); manyToMany ranks held $1..$2 of $3 particles, allReduce $heldAll"
