#!/bin/bash
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
# Landslide dam breach, tiny version of tutorials/interDemFoam/landslideDamBreach
# (the whole pipeline, a few minutes): the dam poured by LIGGGHTS, scenario
# C4 in the 0.1 m slice with the lake started 3 cm below the crest so that it
# overtops at once, 8 s of breach, then the analysis. Checks:
#   - the poured dam is the seed's: crest 0.3 m high (the carving plane;
#     grain tops may stand up to a radius above it or settle below),
#   - grains move: one at least by more than the largest diameter (40 mm),
#   - the lake overtops the crest (freeboard < 0), and the crest loses more
#     than the smallest grain diameter (20 mm) after it does,
#   - water volume balance in - out - storage closes to 1 % of the inflow,
#   - tables, plots and the ParaView files are written,
#   - the matrix analysis on this one run of eight reports no finding as
#     holding: its count reads 0 of 12 and names the seven missing runs,
#   - the rankings of the findings fail on a list with a value missing,
#   - P12's rate peaks (rate_peaks) on synthetic dH/dt series (single
#     spikes of -dH/dt, overtopping at 0 s, 100 s long): 20, 15, 10 mm/s
#     at 10, 20, 30 s and 3 mm/s at 70 s fade (holds for a rebalanced run,
#     not for a complete failure); 10, 10 mm/s at 10, 20 s and 50, 40 mm/s
#     at 80, 90 s rise at the end (holds for a complete failure, the seed's
#     F4, not for a rebalanced run); in each case exactly 4 peaks are
#     found (their count, not their times, is checked),
#   - -demStep 0.3 sets the case's DEM step to 0.3 of the 20 mm grains'
#     Rayleigh time (1.68e-4 s) where the default run has 1e-4 s, and
#     -demStep 0.7 stops with the option named;
#   - -sample b (the matrix's second sample) sets maxCo 0.45 and the DEM
#     step 0.9 x 1e-4 = 9e-5 s in the case C4.small.b, and -tag x.b is
#     refused;
#     the two-sample findings hold only where both samples hold (verdict()
#     on the six pairs of words; two made-up samples of four findings count
#     1 held in both, negative control a count of sample a only), and the matrix with --second writes both
#     samples' matrix and phases and holds nothing with seven runs missing;
#     the findings-against-cost chart reads made-up matrices right (each
#     sample's count held and the CPU time of its eight runs; a matrix with
#     a run missing skipped; negative control: sample a's count given to b);
#   - -fluidVelocity roughnessLayer writes fluidVelocity roughnessLayer
#     and roughnessLayerCoeffs with the C dam's d84 by mass, 0.04 m (the
#     default run has none: the negative control of the read);
#   - -parallel 2 writes the DEM grid bin/demGrid chooses from the dam's
#     grains (-demGrid auto), the serial run LIGGGHTS's "* * *";
#   - the mass budget (damBreachAnalysis.py budget) starts from the poured
#     dam: its first row puts 36.38 kg on the dam's footprint, the mass
#     results/grading.small.dat gives the C dam (measured from the grains
#     the build wrote, not from the dumps), within 0.01 kg, and none in the
#     deposit; negative control: the F dam's 37.68 kg from the same file is
#     not matched;
#   - equalTime on two made-up runs (A: H = 0.3 - 0.001 t m over 100 s; B
#     ends at 50 s) gives A's mean height over [45, 50] s, 0.2525 m, and its
#     own residual over [90, 100] s, 0.205 m; negative control: a copy that
#     takes each run at its own end fails;
#   - -eddyLifetime turnover (with -turbulence kOmegaSST -fluctuation
#     turbulence) writes velocityFluctuation { source turbulence;
#     eddyLifetime turnover; } into the case (the default run has no
#     eddyLifetime), and without -fluctuation turbulence stops with the
#     option named.
# Each value is read from damBreach.summary and must be a number (a missing
# line fails); negative controls: the checks fail on the summary without any
# one of these lines, and on an empty one; the matrix check fails on a copy
# of the analysis that ignores the missing runs and on one that writes plain
# "holds", the ranking check on one that drops missing values (the old
# decreasing()), the rate-peak check on one that judges a complete failure
# by fading too; each must fail for the reason it guards.
# Reference: the seed's dam (0.3 m high) and the water balance. Measured:
# the whole test 101 s in the fresh-clone CI of an earlier version, 114 s here
# with the budget and equalTime checks.
. "$(dirname "$0")/caseFunctions.sh"

copyTutorial landslideDamBreach damBreach
rm -f DEM/dam.*.restart                        # pour the dam too

./Allrun -scenario C4 -lakeLevel 0.27 -endTime 8 > log.Allrun 2>&1 \
    || { tail -20 log.Allrun; fail "Allrun failed (log.Allrun)"; }
case=C4.small
for f in damBreach.dat profiles.dat damBreach.png profiles.png damBreach.summary \
         post/particles_0.vtk post/forceChain_0.vtk
do
    [ -s "$case/$f" ] || fail "$case/$f not written"
done
cat "$case"/damBreach.summary

# summaryChecks <summary file>: every quantity present, a number, in range
summaryChecks()
{
    local s="$1"
    value() { awk -v k="$1" 'index($0, k) == 1 { print $NF }' "$s"; }
    H0=$(value 'initial dam height')
    moved=$(value 'largest grain displacement')
    over=$(value 'overtopping from t')
    lost=$(value 'height lost after overtopping')
    balance=$(value 'water balance error')
    check "initial dam height" "$H0" 'v >= 0.26 && v <= 0.32' \
        "the poured dam is $H0 m high, not 0.3 m (0.26-0.32)"
    check "largest grain displacement" "$moved" 'v > 0.04' \
        "no grain moved more than 40 mm (largest displacement $moved m)"
    check "overtopping time" "$over" 'v >= 0' \
        "the lake never overtopped the crest"
    check "height lost after overtopping" "$lost" 'v > 0.02' \
        "the crest lost only $lost m after overtopping (> 0.02 m expected)"
    check "water balance error" "$balance" 'v > -1 && v < 1' \
        "water balance off by $balance % of the inflow (1 % allowed)"
}

# mustFail <check function> <its argument: a broken summary or analysis>
# <what was broken> <expected failure text>: a negative control; the check
# fails on the broken input, and for the reason it guards (not by a crash)
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

# negative controls: the checks must fail on the summary without any one of
# its checked lines, and on an empty one (a missing value is no pass)
for key in 'initial dam height' 'largest grain displacement' 'overtopping from t' \
           'height lost after overtopping' 'water balance error' ''
do
    if [ -n "$key" ]
    then
        grep -v "^$key" "$case"/damBreach.summary > summary.broken
    else
        : > summary.broken
    fi
    [ "$(wc -l < summary.broken)" -lt "$(wc -l < "$case"/damBreach.summary)" ] \
        || fail "negative control: no '$key' line to remove"
    mustFail summaryChecks summary.broken "summary without '${key:-any line}'" \
        "not a number"
done
rm -f summary.broken

summaryChecks "$case"/damBreach.summary

# matrixChecks <dir of damBreachAnalysis.py>: the findings of the matrix
# analysis run on this one scenario. With seven of the eight runs missing no
# finding may be reported as holding (a check that passes on missing data):
# the count line says 0 of 12 and names the missing runs, and no finding
# reads plain "holds" (at most "holds on the runs present").
matrixChecks()
{
    local out="matrix.$(basename "$1")" count
    rm -rf "$out"
    /usr/bin/python3 "$1"/damBreachAnalysis.py matrix "$out" small "$case" \
        > "$out.log" 2>&1 || { tail -5 "$out.log"; fail "the matrix analysis failed ($out.log)"; }
    [ -s "$out/findings.small.txt" ] || fail "no $out/findings.small.txt"
    [ "$(grep -c '^P[0-9]* ' "$out/findings.small.txt")" = 12 ] \
        || fail "$out/findings.small.txt does not list the 12 findings"
    count=$(grep '^# [0-9]* of 12 hold' "$out/findings.small.txt")
    case "$count" in
        "# 0 of 12 hold: 7 of the eight runs missing (C1 C2 C3 F1 F2 F3 F4);"*) ;;
        *) fail "with seven runs missing the findings count reads '$count'" ;;
    esac
    ! grep -E '^P[0-9]+ holds:' "$out/findings.small.txt" \
        || fail "a finding holds on one run of eight"
    echo "matrix on one run: $count"
}

analysisDir="$INTERDEMFOAM_TUTORIALS/landslideDamBreach"

# breakAnalysis <dir> <module> <sed expression> <the line it leaves>: a copy
# of the analysis (damBreachAnalysis.py and its package damBreach/) in <dir>
# with one guard of damBreach/<module>.py removed
breakAnalysis()
{
    rm -rf "$1" && mkdir -p "$1/damBreach" && cp "$analysisDir"/damBreachAnalysis.py "$1"/ \
        && cp "$analysisDir"/damBreach/*.py "$1"/damBreach/ \
        || fail "negative control: cannot copy the analysis to $1"
    sed -i "$3" "$1"/damBreach/$2.py
    grep -Fqx -- "$4" "$1"/damBreach/$2.py \
        || fail "negative control: cannot remove the guard in $1"
}

# rankingCheck <dir>: the rankings of P6, P7, P9 and P11 (damBreach/
# findings.py's decreasing()) fail when a value is missing or NaN, and hold
# on a complete decreasing list
rankingCheck()
{
    local wrong
    wrong=$(/usr/bin/python3 - "$1" <<'EOF'
import math, sys
sys.path.insert(0, sys.argv[1])
from damBreach import findings as m
cases = [([0.2, 0.15, 0.1], True), ([0.2, 0.25], False), ([0.2], False),
         ([0.2, math.nan, 0.1], False), ([math.nan, 0.2, 0.1], False),
         ([0.2, None, 0.1], False)]
for values, expected in cases:
    try:
        got = m.decreasing(values)
    except Exception as e:
        got = 'error %s' % type(e).__name__
    if got != expected:
        print('%s -> %s' % (values, got))
EOF
) || fail "the ranking check could not run: $wrong"
    [ -z "$wrong" ] || fail "decreasing() ranks wrongly: $(echo $wrong)"
}

# rateShapeCheck <dir>: P12's shape of the rate peaks (rate_peaks) on the
# synthetic series of the header
rateShapeCheck()
{
    local wrong
    wrong=$(/usr/bin/python3 - "$1" <<'EOF'
import sys
import numpy as np
sys.path.insert(0, sys.argv[1])
from damBreach import findings as m
t = np.arange(0.0, 100.25, 0.5)
def series(spikes):
    rate = np.zeros_like(t)
    for at, mm_s in spikes:
        rate[int(round(at/0.5))] = -mm_s/1000.0     # dH/dt < 0: lowering
    return rate
fading = series([(10, 20), (20, 15), (30, 10), (70, 3)])
rising = series([(10, 10), (20, 10), (80, 50), (90, 40)])
for name, rate, failed, expected in (('fading', fading, False, True),
                                     ('fading', fading, True, False),
                                     ('rising', rising, True, True),
                                     ('rising', rising, False, False)):
    thr, first, second, shape, kind = m.rate_peaks(t, rate, 0.0, failed)
    if len(first) + len(second) != 4 or shape != expected:
        print('%s (failed %s): %d + %d peaks, %s %s, expected %s'
              % (name, failed, len(first), len(second), kind, shape,
                 expected))
EOF
) || fail "the rate-peak check could not run: $wrong"
    [ -z "$wrong" ] || fail "rate_peaks judges wrongly: $(echo $wrong)"
}

# verdictCheck <dir>: two samples (matrix --second): a finding "holds" only
# where it holds in both; in one only it says which; the one-sample words
# stay as they were; the count of two made-up samples' findings is of
# those that hold in both
verdictCheck()
{
    local wrong
    wrong=$(/usr/bin/python3 - "$1" <<'EOF'
import sys
sys.path.insert(0, sys.argv[1])
from damBreach import matrix as m
cases = [((True, True), 'holds'), ((True, False), 'holds in one sample only (a)'),
         ((False, True), 'holds in one sample only (b)'),
         ((False, False), 'does not hold'), ((True, None), 'holds'),
         ((False, None), 'does not hold')]
for (a, b), expected in cases:
    got = m.verdict(a, b, 'holds')
    if got != expected:
        print('%s %s -> %s' % (a, b, got))
# the count of two made-up samples: P1 holds in both, P2 in a only, P3 in
# neither, P4 in b only
import os, tempfile
res_a = [('P1', 'c', [], True), ('P2', 'c', [], True), ('P3', 'c', [], False),
         ('P4', 'c', [], False)]
res_b = [('P1', 'c', [], True), ('P2', 'c', [], False), ('P3', 'c', [], False),
         ('P4', 'c', [], True)]
with tempfile.TemporaryDirectory() as scratch:
    path = os.path.join(scratch, 'findings.txt')
    m.write_findings(path, 'small', res_a, [], res_b)
    text = open(path).read()
for line in ('# 1 of 4 hold in both samples', '# in sample a 2 of 4 hold, in sample b 2',
             'P2 holds in one sample only (a): c', 'P4 holds in one sample only (b): c'):
    if line not in text.split('\n'):
        print('no line %r in the findings of two made-up samples' % line)
EOF
) || fail "the verdict check could not run: $wrong"
    [ -z "$wrong" ] || fail "two samples judged wrongly: $(echo $wrong)"
}

# findingsCostCheck <dir>: the findings-against-cost chart (coarseness.py
# findings_cost) reads each sample's count of findings held and sums the
# CPU time of its eight runs: made-up matrices, two samples (a 5 of 12,
# b 7, CPU 8 x 100 s and 8 x 200 s) and one (4 of 12, 8 x 50 s); a matrix
# with runs missing is skipped
findingsCostCheck()
{
    local wrong
    wrong=$(/usr/bin/python3 - "$1" <<'EOF'
import os, sys, tempfile
sys.path.insert(0, sys.argv[1])
from damBreach import coarseness as m
head = "# The seed's findings, checked on the small-scale runs\n"
def matrix(d, suffix, cpu):
    with open(os.path.join(d, 'matrix.small%s.dat' % suffix), 'w') as f:
        f.write('# scenario ... cpu_s\n')
        for sc in ('C1', 'C2', 'C3', 'C4', 'F1', 'F2', 'F3', 'F4'):
            f.write('%s 0.01 C 0.3 0.2 20.0 0.8 10 %g %g\n' % (sc, cpu, cpu))
with tempfile.TemporaryDirectory() as scratch:
    two, one, part = (os.path.join(scratch, n) for n in ('two', 'one', 'part'))
    for d in (two, one, part):
        os.mkdir(d)
    open(os.path.join(two, 'findings.small.txt'), 'w').write(
        head + 'P1 holds: c\n# in sample a 5 of 12 hold, in sample b 7\n'
        '# 4 of 12 hold in both samples\n')
    matrix(two, '', 100)
    matrix(two, '.b', 200)
    open(os.path.join(one, 'findings.small.txt'), 'w').write(
        head + 'P1 holds: c\n# 4 of 12 hold\n')
    matrix(one, '', 50)
    open(os.path.join(part, 'findings.small.txt'), 'w').write(
        head.rstrip('\n') + '; missing runs: F1\n# 0 of 12 hold: 1 of the '
        'eight runs missing (F1); 3 hold on the runs present\n')
    got = {d: m.matrix_findings(d, 'small') for d in (two, one, part)}
    expected = {two: [('a', 5, 12, 800.0), ('b', 7, 12, 1600.0)],
                one: [('a', 4, 12, 400.0)], part: None}
    for d in (two, one, part):
        if got[d] != expected[d]:
            print('%s: %s, expected %s' % (os.path.basename(d), got[d],
                                           expected[d]))
EOF
) || fail "the findings-cost check could not run: $wrong"
    [ -z "$wrong" ] || fail "findings against cost read wrongly: $(echo $wrong)"
}

# twoSampleChecks: the matrix with a second sample (this run again) writes
# both samples' matrix and phases, and with seven runs missing still holds
# no finding
twoSampleChecks()
{
    local out=matrix.twoSamples count
    rm -rf "$out"
    /usr/bin/python3 "$PWD"/damBreachAnalysis.py matrix "$out" small "$case" \
        --second "$case" > "$out.log" 2>&1 \
        || { tail -5 "$out.log"; fail "the two-sample matrix analysis failed ($out.log)"; }
    for f in matrix.small.dat matrix.small.b.dat phases.small.dat phases.small.b.dat
    do
        [ "$(grep -c '^C4 ' "$out/$f")" = 1 ] || fail "no C4 row in $out/$f"
    done
    count=$(grep '^# [0-9]* of 12 hold' "$out/findings.small.txt")
    case "$count" in
        "# 0 of 12 hold: 7 of the eight runs missing"*) ;;
        *) fail "two samples, seven runs missing: the count reads '$count'" ;;
    esac
}

breakAnalysis countOneSample matrix 's/held = sum(ok and (res_b is None or res_b\[i\]\[3\])/held = sum(ok and True/' \
    '        held = sum(ok and True'
mustFail verdictCheck "$PWD/countOneSample" "the count of sample a only" \
    "hold in both samples"
breakAnalysis bothSamples matrix 's/^    if ok_b is None or ok_a == ok_b:$/    if True:/' '    if True:'
mustFail verdictCheck "$PWD/bothSamples" "one sample enough to hold" \
    "two samples judged wrongly"
breakAnalysis costSampleA coarseness "s/^            held = {'a': int(w\[4\]), 'b': int(w\[-1\])}\$/            held = {'a': int(w[4]), 'b': int(w[4])}/" \
    "            held = {'a': int(w[4]), 'b': int(w[4])}"
mustFail findingsCostCheck "$PWD/costSampleA" "sample a's count given to b" \
    "findings against cost read wrongly"
breakAnalysis ignoreMissing matrix 's/^\(    missing = \).*/\1[]/' '    missing = []'
mustFail matrixChecks "$PWD/ignoreMissing" "the missing runs ignored" \
    "findings count reads"
breakAnalysis plainHolds matrix "s/^\(        holds = \).*/\1'holds'/" \
    "        holds = 'holds'"
mustFail matrixChecks "$PWD/plainHolds" "plain holds on one run" \
    "a finding holds on one run of eight"
dropped='    v = [x for x in values if x is not None and not np.isnan(x)]'
breakAnalysis dropMissing findings "s/^    v = list(values)\$/$dropped/" "$dropped"
mustFail rankingCheck "$PWD/dropMissing" "missing values dropped" \
    "decreasing() ranks wrongly"
breakAnalysis failureFades findings 's/^    if failed:$/    if False:/' '    if False:'
mustFail rateShapeCheck "$PWD/failureFades" "a complete failure judged by fading" \
    "rate_peaks judges wrongly"
matrixChecks "$PWD"
verdictCheck "$PWD"
findingsCostCheck "$PWD"
twoSampleChecks
rankingCheck "$PWD"
rateShapeCheck "$PWD"

# -demStep: the case's DEM step is the fraction given of the 20 mm grains'
# Rayleigh time (5.6e-4 s: 0.3 -> 1.68e-4 s), the run above kept the
# tutorial's 1e-4 s (the negative control: the same read on it), and a
# fraction above 0.5 stops with the option named
demDtOf() { sed -n 's/^variable *demDt *index *//p' "$1/DEM/in.case"; }
./Allrun -scenario C4 -demStep 0.3 -tag step30 -endTime 1 -setupOnly \
    > log.Allrun.step30 2>&1 || { tail -5 log.Allrun.step30; fail "Allrun -demStep 0.3 -setupOnly failed"; }
step30=$(demDtOf C4.small.step30)
stepDefault=$(demDtOf "$case")
requireNumber "DEM step with -demStep 0.3" "$step30"
requireNumber "DEM step of the default run" "$stepDefault"
check "DEM step with -demStep 0.3" "$step30" 'v > 1.679e-4 && v < 1.681e-4' \
    "-demStep 0.3 gave a DEM step of $step30 s, not 0.3 x 5.6e-4 = 1.68e-4 s"
check "DEM step of the default run (negative control)" "$stepDefault" \
    '!(v > 1.679e-4 && v < 1.681e-4) && v == 1e-4' \
    "the default run's DEM step is $stepDefault s, not 1e-4 s"
# -sample b: the matrix's second sample, every step 10 % shorter, in its
# own case C4.small.b: maxCo 0.45 (the default run's 0.5 is the negative
# control) and the DEM step 0.9 x the default run's 1e-4 s = 9e-5 s; a tag
# ending in .b is refused (it would name a second sample's cases)
./Allrun -scenario C4 -sample b -endTime 1 -setupOnly > log.Allrun.sampleB 2>&1 \
    || { tail -5 log.Allrun.sampleB; fail "Allrun -sample b -setupOnly failed"; }
coOf() { foamDictionary -entry maxCo -value "$1/system/controlDict"; }
requireNumber "maxCo of -sample b" "$(coOf C4.small.b)"
check "maxCo of -sample b" "$(coOf C4.small.b)" 'v == 0.45' \
    "-sample b gave maxCo $(coOf C4.small.b), not 0.45"
check "maxCo of the default run (negative control)" "$(coOf "$case")" '!(v == 0.45)' \
    "the default run's maxCo is $(coOf "$case")"
check "DEM step of -sample b" "$(demDtOf C4.small.b)" 'v > 8.99e-5 && v < 9.01e-5' \
    "-sample b gave a DEM step of $(demDtOf C4.small.b) s, not 0.9 x 1e-4 = 9e-5 s"
./Allrun -scenario C4 -tag x.b -setupOnly > log.Allrun.tagB 2>&1 \
    && fail "-tag x.b ran (log.Allrun.tagB)"
grep -q "^Allrun: -tag x.b: a tag b or ending in .b" log.Allrun.tagB \
    || fail "-tag x.b did not stop with the option named (log.Allrun.tagB)"
# -parallel 2 (-demGrid auto): the case's DEM grid is bin/demGrid's best
# for the dam's grains on 2 ranks, not LIGGGHTS's "* * *"
./Allrun -scenario C4 -parallel 2 -tag np2 -endTime 1 -setupOnly > log.Allrun.np2 2>&1 \
    || { tail -5 log.Allrun.np2; fail "Allrun -parallel 2 -setupOnly failed"; }
gridOf() { sed -n 's/^variable *demGrid *index *"\(.*\)"$/\1/p' "$1/DEM/in.case"; }
expected=$(demGrid DEM/dam.C.small.grains 2 --best) || fail "demGrid on DEM/dam.C.small.grains failed"
[ -n "$expected" ] && [ "$(gridOf C4.small.np2)" = "$expected" ] \
    || fail "-parallel 2 wrote the DEM grid '$(gridOf C4.small.np2)', demGrid chooses '$expected'"
[ "$(gridOf "$case")" = "* * *" ] \
    || fail "the serial run's DEM grid is '$(gridOf "$case")', not LIGGGHTS's \"* * *\""
echo "-parallel 2: DEM grid $expected"
./Allrun -scenario C4 -demStep 0.7 -tag step70 -setupOnly > log.Allrun.step70 2>&1 \
    && fail "-demStep 0.7 ran (log.Allrun.step70)"
grep -q "^Allrun: -demStep needs" log.Allrun.step70 \
    || fail "-demStep 0.7 did not stop with the option named (log.Allrun.step70)"
# -eddyLifetime turnover (with -turbulence kOmegaSST -fluctuation
# turbulence) writes velocityFluctuation { source turbulence; eddyLifetime
# turnover; } into the case's constant/couplingProperties (the default run
# has no eddyLifetime there: the negative control of the read); without
# -fluctuation turbulence it stops with the option named
./Allrun -scenario C4 -turbulence kOmegaSST -fluctuation turbulence -eddyLifetime turnover \
    -tag turnover -endTime 1 -setupOnly > log.Allrun.turnover 2>&1 \
    || { tail -5 log.Allrun.turnover; fail "Allrun -eddyLifetime turnover -setupOnly failed"; }
fluctuationOf() { foamDictionary -entry "velocityFluctuation/$2" -value "$1/constant/couplingProperties" 2>/dev/null; }
[ "$(fluctuationOf C4.small.turnover source)" = turbulence ] \
    && [ "$(fluctuationOf C4.small.turnover eddyLifetime)" = turnover ] \
    || fail "-eddyLifetime turnover wrote velocityFluctuation { source '$(fluctuationOf C4.small.turnover source)'; eddyLifetime '$(fluctuationOf C4.small.turnover eddyLifetime)'; }, not turbulence and turnover"
[ -z "$(fluctuationOf "$case" eddyLifetime)" ] \
    || fail "the default run's couplingProperties has an eddyLifetime (negative control of the read)"
./Allrun -scenario C4 -eddyLifetime turnover -tag turnoverLam -setupOnly > log.Allrun.turnoverLam 2>&1 \
    && fail "-eddyLifetime turnover without -fluctuation turbulence ran (log.Allrun.turnoverLam)"
grep -q "^Allrun: -eddyLifetime is how long a grain keeps an eddy" log.Allrun.turnoverLam \
    || fail "-eddyLifetime without -fluctuation turbulence did not stop with the option named (log.Allrun.turnoverLam)"

# -fluidVelocity roughnessLayer (the flow between the crests) writes the
# model and its coefficients with the dam's d84 by mass (C: 40 mm); the
# default run has no roughnessLayerCoeffs (the negative control of the read)
./Allrun -scenario C4 -fluidVelocity roughnessLayer -tag layer -endTime 1 -setupOnly > log.Allrun.layer 2>&1 \
    || { tail -5 log.Allrun.layer; fail "Allrun -fluidVelocity roughnessLayer -setupOnly failed"; }
layerOf() { foamDictionary -entry "$2" -value "$1/constant/couplingProperties" 2>/dev/null; }
layerD=$(layerOf C4.small.layer roughnessLayerCoeffs/roughnessDiameter)
echo "-fluidVelocity roughnessLayer: fluidVelocity $(layerOf C4.small.layer fluidVelocity), roughnessDiameter $layerD m (the C dam's d84, 0.04)"
[ "$(layerOf C4.small.layer fluidVelocity)" = roughnessLayer ] \
    || fail "-fluidVelocity roughnessLayer wrote fluidVelocity '$(layerOf C4.small.layer fluidVelocity)'"
check "roughnessLayer's roughness diameter" "$layerD" 'v == 0.04' \
    "-fluidVelocity roughnessLayer wrote roughnessDiameter $layerD, not the C dam's d84 0.04 m"
[ -z "$(layerOf "$case" roughnessLayerCoeffs/roughnessDiameter)" ] \
    || fail "the default run's couplingProperties has roughnessLayerCoeffs (negative control of the read)"

# the mass budget's first row against the dam's mass in the grading file
damMassOf() { sed -n "s/^# $1: [0-9]* grains, \([0-9.]*\) kg.*/\1/p" results/grading.small.dat; }
/usr/bin/python3 damBreachAnalysis.py budget "$case" > log.budget 2>&1 \
    || { cat log.budget; fail "damBreachAnalysis.py budget failed (log.budget)"; }
cat log.budget
firstRow=$(awk -v c="$case" '$1 == c && $2 + 0 == 0 { print $3, $4; exit }' log.budget)
read -r footprint0 deposit0 <<< "$firstRow"
requireNumber "budget: footprint mass at t = 0" "$footprint0"
requireNumber "budget: deposit mass at t = 0" "$deposit0"
for m in C F
do
    requireNumber "the $m dam's mass in results/grading.small.dat" "$(damMassOf $m)"
done
budgetMatches() { /usr/bin/python3 -c "import sys; sys.exit(0 if abs($footprint0 - $1) <= 0.01 and $deposit0 == 0 else 1)"; }
budgetMatches "$(damMassOf C)" \
    || fail "budget: $footprint0 kg on the footprint and $deposit0 kg in the deposit at t = 0, the C dam is $(damMassOf C) kg"
budgetMatches "$(damMassOf F)" \
    && fail "budget: the footprint's $footprint0 kg also matches the F dam's $(damMassOf F) kg (negative control)"
echo "budget: $footprint0 kg on the footprint at t = 0 (the C dam $(damMassOf C) kg)"

# equalTime on two made-up runs: A's H falls linearly, 0.3 - 0.001 t m over
# 0-100 s, B's stays 0.2 m and ends at 50 s; at T = 50 s A's mean height
# over [45, 50] s is 0.2525 m, its own residual (over [90, 100] s) 0.205 m
mkdir -p equalTime/A equalTime/B
/usr/bin/python3 -c "
import numpy as np
t = np.arange(0, 100.01, 0.5)
np.savetxt('equalTime/A/damBreach.dat', np.column_stack([t, 0.3 - 0.001*t, 0*t, 1 + 0*t]))
t = np.arange(0, 50.01, 0.5)
np.savetxt('equalTime/B/damBreach.dat', np.column_stack([t, 0.2 + 0*t, 0*t, 1 + 0*t]))"
equalTimeOf() { /usr/bin/python3 "$1"/damBreachAnalysis.py equalTime equalTime/A equalTime/B 2>&1 \
    | awk '$1 == "equalTime/A" { print $3, $4 }'; }
equalTimeChecks()
{
    local hT residual
    read -r hT residual <<< "$(equalTimeOf "$1")"
    check "equalTime: A at T = 50 s" "$hT" 'v > 0.2524 && v < 0.2526' \
        "equalTime gave A $hT m at T = 50 s, not 0.2525 m"
    check "equalTime: A's own residual" "$residual" 'v > 0.2049 && v < 0.2051' \
        "equalTime gave A's residual $residual m, not 0.205 m"
}
equalTimeChecks "$PWD"
mkdir -p ownEnd/damBreach && cp damBreachAnalysis.py ownEnd/ && cp damBreach/*.py ownEnd/damBreach/
sed -i 's|window, tail = last_tenth(t, end), last_tenth(t)|window, tail = last_tenth(t), last_tenth(t)|' ownEnd/damBreach/compare.py
grep -q 'window, tail = last_tenth(t), last_tenth(t)' ownEnd/damBreach/compare.py || fail "negative control: the equalTime window not broken"
mustFail equalTimeChecks "$PWD/ownEnd" "each run at its own end" "not 0.2525 m"
echo "equalTime: A 0.2525 m at T = 50 s, 0.205 m at its own end"

pass "dam ${H0} m, overtopped at ${over} s, crest lowered ${lost} m after," \
     "largest displacement ${moved} m, water balance ${balance} %"
