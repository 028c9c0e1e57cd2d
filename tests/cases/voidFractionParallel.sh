#!/bin/bash
#------------------------------------------------------------------------------
# A bed of cell-sized particles (d = dx = 4 mm, 20 of them, held still)
# that METIS splits across 2 subdomains: for centre, divided and
# virtualSphere, the voidfraction field on 2 ranks (reconstructPar) equals
# the serial one to 1e-12, and sum(eps V) = V_box - sum(V_p) to 1e-9
# relative (no volume lost at the processor boundary).
#------------------------------------------------------------------------------
. "${0%/*}/caseFunctions.sh"

src="$testsDir/cases/particleBed"
name=voidFractionParallel
rm -rf "$runDir/$name"; mkdir -p "$runDir/$name"; cd "$runDir/$name" || fail "no run dir"

# field values of internalField (ascii) of a volScalarField, one per line
internalValues()
{
    awk '/^internalField/ { f = 1; next } f && /^\(/ { g = 1; next }
         g && /^\)/ { exit } g { print }' "$1"
}

Vbox=1.6e-05
Vp=$(awk 'BEGIN { printf "%.15g\n", 20*3.14159265358979*0.004^3/6 }')

for model in centre divided virtualSphere diffusion
do
    for mode in serial parallel
    do
        d="$model-$mode"
        cp -r "$src" "$d"
        (
            cd "$d" || exit 1
            sed -i "s/^voidFraction .*/voidFraction      $model;/" constant/couplingProperties
            runApplication blockMesh || exit 1
            if [ "$mode" = parallel ]
            then
                runApplication decomposePar || exit 1
                runParallel interDemFoam || exit 1
                runApplication reconstructPar || exit 1
            else
                runApplication interDemFoam || exit 1
            fi
            grep -q "^End" log.interDemFoam
        ) || fail "$d did not run (see $runDir/$name/$d/log.*)"
    done

    internalValues "$model-serial/0.0003/voidfraction" > "$model.serial"
    internalValues "$model-parallel/0.0003/voidfraction" > "$model.parallel"
    n=$(wc -l < "$model.serial")
    [ "$n" -eq 250 ] || fail "$model: expected 250 cell values, found $n"
    diff=$(paste "$model.serial" "$model.parallel" \
        | awk '{ d = $1 - $2; if (d < 0) d = -d; if (d > m) m = d } END { printf "%.3e\n", m }')
    minEps=$(sort -g "$model.serial" | head -n 1)

    table="$model-parallel/postProcessing/fluidVolume/0/volFieldValue.dat"
    err=$(awk -v vb="$Vbox" -v vp="$Vp" '!/^#/ && NF >= 2 {
            e = ($2 - (vb - vp))/vp; if (e < 0) e = -e; if (e > m) m = e
          } END { printf "%.3e\n", m }' "$table")
    echo "$model: max |eps serial - eps 2 ranks| = $diff, min eps $minEps," \
         "particle volume error on 2 ranks $err (relative)"
    awk -v d="$diff" 'BEGIN { exit !(d < 1e-12) }' \
        || fail "$model: eps on 2 ranks differs from serial by $diff"
    awk -v e="$err" 'BEGIN { exit !(e < 1e-9) }' \
        || fail "$model: particle volume not conserved on 2 ranks ($err)"
    awk -v m="$minEps" 'BEGIN { exit !(m < 0.999) }' \
        || fail "$model: no particle volume in the field (min eps $minEps)"
done

pass "voidfraction on 2 ranks = serial, particle volume conserved"
