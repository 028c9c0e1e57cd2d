#!/bin/bash
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
# The landslide dam's run-length rule (tutorials/interDemFoam/
# landslideDamBreach/damBreachAnalysis.py ended, which Allrun calls after
# each piece of a run): a run goes on while the dam height changed by 5 mm or
# more over the last 20 s, and stops at the longest run (Allrun -maxTime,
# default 200 s at small scale) saying NOT ENDED. Seconds, no solver: the
# rule is applied to synthetic LIGGGHTS dumps (every 0.5 s) of one resting
# grain whose top is the dam height H(t), a straight line, so that the height
# change over 20 s is known exactly: 0.5 mm/s -> 10 mm, 0.15 mm/s -> 3 mm.
# Checks (exit status and the printed change, to 0.1 mm):
#   - 10 mm over 20 s at 80 s, longest run 100 s: still changing (go on);
#   - 3 mm over 20 s at 80 s: the breach has ended (stop);
#   - 10 mm over 20 s at 100 s, longest run 100 s: stop, NOT ENDED;
#   - the same at 100 s with -maxTime 200: still changing (go on).
# Negative controls: the checks fail on copies of the rule with the
# tolerance ignored (every run "ended") and with the longest run ignored
# (a run never stops).
. "$(dirname "$0")/caseFunctions.sh"

analysis="$INTERDEMFOAM_TUTORIALS/landslideDamBreach/damBreachAnalysis.py"
[ -f "$analysis" ] || fail "no $analysis"
rm -rf "$runDir/breachEnded"
mkdir -p "$runDir/breachEnded"
cd "$runDir/breachEnded" || fail "cannot enter $runDir/breachEnded"

# synthCase <name> <end time s> <lowering rate m/s>: H(t) = 0.25 - rate t
synthCase()
{
    mkdir -p "$1/DEM" "$1/post"
    echo "variable demDt index 1e-4" > "$1/DEM/in.case"
    /usr/bin/python3 - "$1" "$2" "$3" <<'EOF' || fail "cannot write the dumps of $1"
import sys
case, t_end, rate = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
r = 0.01
for k in range(int(round(t_end/0.5)) + 1):
    t = 0.5*k
    step = int(round(t/1e-4))
    top = 0.25 - rate*t
    with open('%s/post/particles.%d.txt' % (case, step), 'w') as f:
        f.write('ITEM: TIMESTEP\n%d\nITEM: NUMBER OF ATOMS\n1\n'
                'ITEM: BOX BOUNDS ff pp ff\n-0.1 7.1\n0 0.1\n0 0.6\n'
                'ITEM: ATOMS id radius mass x y z vx vy vz\n'
                '1 %g 0.01 3.5 0.05 %.9f 0 0 0\n' % (step, r, top - r))
EOF
}
synthCase changing80 80 0.0005
synthCase slowing80 80 0.00015
synthCase changing100 100 0.0005

# ruleChecks <analysis script>: the four cases of the header
ruleChecks()
{
    local py="$1" out rc change
    # expect <case> <maxTime> <exit status> <printed change mm> <text>
    expect()
    {
        out=$(/usr/bin/python3 "$py" ended "$1" --window 20 --tolerance 0.005 \
              --maxTime "$2" 2>&1)
        rc=$?
        echo "  $1, longest run $2 s: exit $rc: $out"
        [ "$rc" = "$3" ] || fail "$1 (longest run $2 s): exit $rc, expected $3"
        change=$(echo "$out" | sed -n 's/.*: change \([0-9.]*\) mm.*/\1/p' | head -1)
        check "height change of $1" "$change" "v >= $4 - 0.1 && v <= $4 + 0.1" \
            "$1: printed change '$change' mm, expected $4 mm"
        echo "$out" | grep -q "$5" || fail "$1 (longest run $2 s): no '$5' in: $out"
    }
    expect changing80 100 1 10.0 'still changing'
    expect slowing80 100 0 3.0 'the breach has ended'
    expect changing100 100 0 10.0 'NOT ENDED'
    expect changing100 200 1 10.0 'still changing'
}

# negative controls: the rule broken in two ways must fail the checks
sed 's/done = change < tolerance/done = True/' "$analysis" > noTolerance.py
sed 's/t_end >= max_time - 1e-6/False/' "$analysis" > noLongestRun.py
for broken in noTolerance noLongestRun
do
    cmp -s "$analysis" $broken.py && fail "negative control $broken: the rule's line was not found"
    msg=$( (ruleChecks $broken.py) 2>&1 ) \
        && fail "the checks pass with the rule broken ($broken)"
    echo "negative control $broken: ${msg##*FAIL: }"
done

ruleChecks "$analysis"
pass "the run goes on at 10 mm / 20 s, stops at 3 mm / 20 s, and stops NOT ENDED at the longest run (100 s; not at -maxTime 200)"
