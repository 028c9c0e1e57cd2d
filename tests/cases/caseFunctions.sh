# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
# Shared helpers of the case tests (sourced). Each test runs in its own
# folder under tests/run/ and exits 0 (pass), 1 (fail) or 77 (skipped).

[ -n "$INTERDEMFOAM_DIR" ] || { echo "source etc/bashrc first" 1>&2; exit 1; }
. "$WM_PROJECT_DIR/bin/tools/RunFunctions"

testsDir="$INTERDEMFOAM_DIR/tests"
runDir="$testsDir/run"

fail() { echo "FAIL: $*" 1>&2; exit 1; }
pass() { echo "PASS: $*"; exit 0; }

# Numbers read from logs and tables. In awk an empty or non-numeric value
# compares as true ("" < 1), so a check on a missing line would pass: every
# value a check reads goes through these first.
#   isNumber <value>           true for a finite decimal number only
#                              (not empty, not text, not nan or inf)
#   requireNumber <what> <value>   fail unless it is one
#   check <what> <value> <condition on v> <message>
#                              fail with <message> unless <value> is a
#                              number and the awk condition holds, e.g.
#                              check "water balance" "$b" 'v > -1 && v < 1' "..."
isNumber()
{
    [[ "$1" =~ ^[-+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?$ ]]
}

requireNumber()
{
    isNumber "$2" || fail "$1: not a number ('$2'): missing or unreadable"
}

check()
{
    requireNumber "$1" "$2"
    awk -v v="$2" "BEGIN { exit !($3) }" || fail "$4"
}

# Fresh copy of a tutorial under tests/run/<name>
copyTutorial()
{
    local tutorial="$1" name="$2"
    rm -rf "$runDir/$name"
    mkdir -p "$runDir"
    cp -r "$INTERDEMFOAM_TUTORIALS/$tutorial" "$runDir/$name"
    "$runDir/$name/Allclean" > /dev/null 2>&1
    cd "$runDir/$name" || fail "cannot enter $runDir/$name"
}

# Run the solver in the current case: runSolver serial | parallel
# (parallel: decomposePar, mpirun -np 2 via runParallel, reconstructPar);
# fails unless the run reached its end
runSolver()
{
    if [ "$1" = parallel ]
    then
        runApplication decomposePar || return 1
        runParallel interDemFoam || return 1
        runApplication reconstructPar || return 1
    else
        runApplication interDemFoam || return 1
    fi
    grep -q "^End" log.interDemFoam
}

# Set a controlDict/fvSolution entry: setEntry <file> <key> <value>
setEntry()
{
    foamDictionary -entry "$2" -set "$3" "$1" > /dev/null \
        || fail "cannot set $2 in $1"
}

# Largest relative deviation from the first value in column 2 of a
# function-object table (comment lines skipped); prints nan and returns 1
# for a missing or empty table, a row without a number in column 2, or a
# first value of 0
maxRelativeDrift()
{
    [ -s "$1" ] || { echo "nan"; return 1; }
    awk '!/^#/ && NF >= 1 {
        if (NF < 2 || $2 !~ /^[-+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?$/) { bad = 1; exit }
        if (!n++) { v0 = $2; if (v0 == 0) { bad = 1; exit } }
        d = ($2 - v0)/v0; if (d < 0) d = -d; if (d > m) m = d
    } END { if (bad || !n) { print "nan"; exit 1 } printf "%.3e\n", m }' "$1"
}

# Semi-implicit MULES (an implicit upwind predictor, then the limited
# high-order correction) and sub-cycles for the phase fraction, as in
# OpenFOAM's own damBreak: semiImplicitAlpha <nAlphaSubCycles>
# fallingBed <endTime>: in a copy of tests/cases/particleBed (the current
# directory), let its 20 particles fall (gravity, integration), dump their
# DEM state at step 600 to post/bed.600.dump with 17 digits, and write the
# fields every 60 steps with 17 digits up to endTime
# (exchangeIdentical.sh, samplingParallel.sh)
fallingBed()
{
    cat >> DEM/in.liggghts <<'DEM'
fix             gravi all gravity 9.81 vector 0.0 0.0 -1.0
fix             integr all nve/sphere
dump            state all custom 600 post/bed.*.dump id x y z vx vy vz
dump_modify     state sort id format "%d %.17g %.17g %.17g %.17g %.17g %.17g"
DEM
    mkdir -p post
    setEntry system/controlDict endTime "$1"
    setEntry system/controlDict writeInterval 60
    setEntry system/controlDict writePrecision 17
}

semiImplicitAlpha()
{
    local key='solvers/"alpha.water.*"'
    setEntry system/fvSolution "$key/MULESCorr" yes
    setEntry system/fvSolution "$key/nAlphaSubCycles" "$1"
    setEntry system/fvSolution "$key/solver" smoothSolver
    setEntry system/fvSolution "$key/smoother" symGaussSeidel
    setEntry system/fvSolution "$key/tolerance" 1e-12
    setEntry system/fvSolution "$key/relTol" 0
    setEntry system/fvSolution "$key/nLimiterIter" 5
}

# The singleParticleSettling tutorial narrowed to one 20 mm column
# (5 x 5 x 50 cells of 4 mm), the particle on its axis: run in the case
narrowSettlingColumn()
{
    sed -i 's/^Lx .*/Lx  0.02;/; s/^Ly .*/Ly  0.02;/; s/^nx .*/nx  5;/; s/^ny .*/ny  5;/' \
        system/blockMeshDict
    sed -i 's/^region .*/region          box block 0 0.02 0 0.02 0 0.2 units box/;
            s/^create_atoms .*/create_atoms    1 single 0.01 0.01 0.15 units box/' \
        DEM/in.liggghts
}
