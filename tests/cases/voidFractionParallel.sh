#!/bin/bash
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#------------------------------------------------------------------------------
# A bed of cell-sized particles (d = dx = 4 mm, 20 of them, held still)
# that METIS splits across 2 subdomains: for centre, divided, virtualSphere
# and diffusion, the voidfraction field on 2 ranks (reconstructPar) equals
# the serial one to 1e-12, and sum(eps V) = V_box - sum(V_p) to 1e-9
# relative (no volume lost at the processor boundary). The same for
# centreSpill: the centre model with a floor of 0.6 (each particle's cell,
# 0.52 solid, is over the cap of 0.4) and voidFractionFloor spill, which
# moves the excess to the neighbouring cells across the processor boundary
# too: the serial log must report spilled cells and neither log a floor hit.
# A missing, empty or non-numeric field or table fails; negative controls at
# the end check that. Reference: the serial run and the particles' volume.
# Measured: 1e-15 (eps) and 4e-14 (volume) (docs/voidFraction.md).
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

# largest |a - b| of two columns of numbers, line by line; fails on a
# non-numeric or missing value or on lists of different length
largestDifference()
{
    paste "$1" "$2" | awk -v num='^[-+]?([0-9]+\\.?[0-9]*|\\.[0-9]+)([eE][-+]?[0-9]+)?$' '
        NF != 2 || $1 !~ num || $2 !~ num { bad = 1; exit }
        { n++; d = $1 - $2; if (d < 0) d = -d; if (d > m) m = d }
        END { if (bad || !n) exit 1; printf "%.3e\n", m }'
}

# largest relative error of sum(eps V) against V_box - sum(V_p) over the rows
# of the fluidVolume table; fails on a missing or empty table or a
# non-numeric row
volumeError()
{
    [ -s "$1" ] || return 1
    awk -v vb="$Vbox" -v vp="$Vp" -v num='^[-+]?([0-9]+\\.?[0-9]*|\\.[0-9]+)([eE][-+]?[0-9]+)?$' '
        /^#/ || NF == 0 { next }
        NF < 2 || $2 !~ num { bad = 1; exit }
        { n++; e = ($2 - (vb - vp))/vp; if (e < 0) e = -e; if (e > m) m = e }
        END { if (bad || !n) exit 1; printf "%.3e\n", m }' "$1"
}

Vbox=1.6e-05
Vp=$(awk 'BEGIN { printf "%.15g\n", 20*3.14159265358979*0.004^3/6 }')

for model in centre divided virtualSphere diffusion centreSpill
do
    for mode in serial parallel
    do
        d="$model-$mode"
        cp -r "$src" "$d"
        (
            cd "$d" || exit 1
            if [ "$model" = centreSpill ]
            then
                sed -i "s/^voidFraction .*/voidFraction      centre;/; s/^minVoidFraction .*/minVoidFraction   0.6;\nvoidFractionFloor spill;/" constant/couplingProperties
            else
                sed -i "s/^voidFraction .*/voidFraction      $model;/" constant/couplingProperties
            fi
            runApplication blockMesh || exit 1
            runSolver "$mode"
        ) || fail "$d did not run (see $runDir/$name/$d/log.*)"
    done

    internalValues "$model-serial/0.0003/voidfraction" > "$model.serial"
    internalValues "$model-parallel/0.0003/voidfraction" > "$model.parallel"
    for mode in serial parallel
    do
        n=$(wc -l < "$model.$mode")
        [ "$n" -eq 250 ] || fail "$model: expected 250 $mode cell values, found $n"
    done
    diff=$(largestDifference "$model.serial" "$model.parallel") \
        || fail "$model: non-numeric voidfraction values ($model.serial, $model.parallel)"
    minEps=$(sort -g "$model.serial" | head -n 1)

    table="$model-parallel/postProcessing/fluidVolume/0/volFieldValue.dat"
    err=$(volumeError "$table") || fail "$model: no particle volume table $table (or no number in it)"
    echo "$model: max |eps serial - eps 2 ranks| = $diff, min eps $minEps," \
         "particle volume error on 2 ranks $err (relative)"
    check "$model: eps difference" "$diff" 'v < 1e-12' \
        "$model: eps on 2 ranks differs from serial by $diff"
    check "$model: particle volume error" "$err" 'v < 1e-9' \
        "$model: particle volume not conserved on 2 ranks ($err)"
    check "$model: min eps" "$minEps" 'v < 0.999' \
        "$model: no particle volume in the field (min eps $minEps)"
    if [ "$model" = centreSpill ]
    then
        spilled=$(grep -c "^Voidfraction spill" "$model-serial/log.interDemFoam")
        hits=$(cat "$model-serial/log.interDemFoam" "$model-parallel/log.interDemFoam" \
            | grep -c "^Warning: voidfraction floor")
        echo "$model: $spilled step(s) with spilled cells (serial), $hits floor hit line(s)"
        check "$model: steps that spilled" "$spilled" 'v >= 1' \
            "$model: the serial run spilled nothing: the case does not test the spill"
        check "$model: floor hit lines" "$hits" 'v == 0' \
            "$model: the spill left cells at the floor"
        check "$model: min eps at the floor" "$minEps" 'v > 0.6 - 1e-9 && v < 0.6 + 1e-9' \
            "$model: min eps $minEps, not the floor 0.6 the spill fills cells to"
    fi
done

# negative controls: the volume check fails on a missing table, an empty
# one and one with its header only; the eps comparison on a field cut short
# or with a non-numeric value
grep '^#' "$table" > header.dat; : > empty.dat
for t in missing.dat empty.dat header.dat
do
    volumeError "$t" > /dev/null && fail "the volume check passes on $t"
done
head -n 100 centre.parallel > cut.dat
largestDifference centre.serial cut.dat > /dev/null \
    && fail "the eps comparison passes on a field cut short"
sed '7s/.*/nan/' centre.parallel > nan.dat
largestDifference centre.serial nan.dat > /dev/null \
    && fail "the eps comparison passes on a field with nan"
echo "negative controls: the checks fail on a missing, empty or header-only volume table and on a cut or nan eps field"

pass "voidfraction on 2 ranks = serial, particle volume conserved"
