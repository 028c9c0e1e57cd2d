#!/bin/bash
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
# The landslide dam's run-length rule (tutorials/interDemFoam/
# landslideDamBreach/damBreachAnalysis.py ended, the rule in its package's
# damBreach/ended.py, which Allrun calls after each piece of a run): a run
# goes on while, over the last 20 s, the dam height changed by 5 mm or
# more or the total energy [E] by 0.02 or more (grains still leave the
# dam), and stops at the longest run (Allrun
# -maxTime, default 300 s at small scale) saying NOT ENDED. Seconds, no
# solver: the rule is applied to synthetic LIGGGHTS dumps (every 0.5 s, g
# straight down) of one light crest grain (1 g) whose top is the dam height
# H(t), a straight line, above 100 resting grains of 10 g centred at 0.1 m,
# of which one leaves every P s; so the changes over 20 s are known exactly:
# H lowers 0.5 mm/s -> 10 mm, 0.15 mm/s -> 3 mm (and [E] by under 0.001);
# a grain every 4 s -> [E] 0.850 -> 0.800 (0.050), every 20 s -> 0.010.
# Checks (exit status, the printed height change to 0.1 mm and the printed
# [E] change to 0.001):
#   - 10 mm over 20 s at 80 s, longest run 100 s: still changing (go on);
#   - 3 mm over 20 s at 80 s: the breach has ended (stop);
#   - height steady, [E] 0.050 over 20 s at 80 s: still changing (go on);
#   - height steady, [E] 0.010 over 20 s at 80 s: the breach has ended;
#   - 10 mm over 20 s at 100 s, longest run 100 s: stop, NOT ENDED;
#   - the same at 100 s with -maxTime 200: still changing (go on);
#   - the same with a DEM step of 9e-5 s, dumped as the solver dumps,
#     every round(0.5/9e-5) = 5556 steps (0.50004 s), so that the last
#     dump is at 99.508 s, 0.49 s short of the piece's end (as a
#     matrix's sample b, whose last dump before 200 s is at 199.516 s):
#     with the piece's end given as Allrun gives it (--pieceEnd 100), stop,
#     NOT ENDED; by hand, without it (the piece taken to end within a dump
#     interval after the last dump), the same;
#   - the run to 80 s with the piece's end given as 100 s and the longest
#     run 100 s: stop, NOT ENDED (the piece's end is what counts: the last
#     dump plus an interval is 80.5 s);
#   - a 10 s run (shorter than the 20 s window): goes on with -maxTime
#     200, stops NOT ENDED with -maxTime 10;
#   - every grain gone: the dumps from 78 s on hold no grain (height 0: 250
#     mm lost over 20 s) and 78/liggghts.restart.emptied is there (the
#     solver's mark): the breach has ended, naming that file;
#   - the same on 2 ranks (processor0/98 and processor0/100 marked, dumps
#     empty from 98 s, end 100 s): ended, naming the earliest, 98 (not the
#     first in text order, 100).
# Negative controls: the checks fail on copies of the analysis whose rule
# (damBreach/ended.py) is changed: with both
# tolerances ignored (every run "ended"), with the [E] tolerance ignored
# (grains leaving do not count), with the longest run ignored (a run
# never stops; for a run shorter than the window too), with the longest
# run judged by the last dump's time (the run with the DEM step of 9e-5
# s goes on past it, as the matrix's sample b did to 220 s), with the
# piece's end ignored (the run to 80 s given the end 100 s goes on), with the emptied
# mark ignored (an empty flume judged by its height) and with
# the marks sorted as text.
# And the dumps the deposit and budget tables take every 20 s
# (damBreach/deposit.py): on the run with the DEM step of 9e-5 s, the dump
# nearest each multiple (0, 20.0, 40.0, 60.0, 80.0 s) and the last (99.5
# s); negative control: a copy matching the multiples within 1e-6 s (the
# rule until December 2026) finds only 0 s and the last.
# Reference: the height and [E] changes built into the synthetic dumps
# (exact). Measured: every verdict as constructed; no other number.
. "$(dirname "$0")/caseFunctions.sh"

analysis="$INTERDEMFOAM_TUTORIALS/landslideDamBreach/damBreachAnalysis.py"
ruleModule="$INTERDEMFOAM_TUTORIALS/landslideDamBreach/damBreach/ended.py"
[ -f "$analysis" ] && [ -f "$ruleModule" ] || fail "no $analysis or $ruleModule"
rm -rf "$runDir/breachEnded"
mkdir -p "$runDir/breachEnded"
cd "$runDir/breachEnded" || fail "cannot enter $runDir/breachEnded"

# synthCase <name> <end time s> <lowering rate m/s> <period s (0: none)>
#           [<time s from which the dumps are empty> [<DEM step s>]]:
# the crest grain's top H(t) = 0.25 - rate t above 100 - floor(t/period)
# resting grains; a dump every round(0.5/demDt) steps (demDt 1e-4 s unless
# given: every 0.5 s) up to the end's step, as the solver dumps
synthCase()
{
    mkdir -p "$1/DEM" "$1/post" "$1/constant"
    echo "variable demDt index ${6:-1e-4}" > "$1/DEM/in.case"
    echo "value ( 0 0 -9.81 );" > "$1/constant/g"
    /usr/bin/python3 - "$@" <<'EOF' || fail "cannot write the dumps of $1"
import sys
case = sys.argv[1]
t_end, rate, period = (float(v) for v in sys.argv[2:5])
t_gone = float(sys.argv[5]) if len(sys.argv) > 5 else 1e9
dt = float(sys.argv[6]) if len(sys.argv) > 6 else 1e-4
r = 0.01
every = int(round(0.5/dt))
for step in range(0, int(round(t_end/dt)) + 1, every):
    t = step*dt
    top = 0.25 - rate*t
    n = 100 - (int(t/period + 1e-9) if period > 0 else 0)
    rows = ['1 %g 0.001 3.5 0.05 %.9f 0 0 0' % (r, top - r)]
    rows += ['%d %g 0.01 3.5 0.05 0.1 0 0 0' % (2 + i, r) for i in range(n)]
    if t >= t_gone - 1e-9:
        rows = []
    with open('%s/post/particles.%d.txt' % (case, step), 'w') as f:
        f.write('ITEM: TIMESTEP\n%d\nITEM: NUMBER OF ATOMS\n%d\n'
                'ITEM: BOX BOUNDS ff pp ff\n-0.1 7.1\n0 0.1\n0 0.6\n'
                'ITEM: ATOMS id radius mass x y z vx vy vz\n%s\n'
                % (step, len(rows), '\n'.join(rows)))
EOF
}
synthCase changing80 80 0.0005 0
synthCase slowing80 80 0.00015 0
synthCase losing80 80 0 4
synthCase shedding80 80 0 20
synthCase changing100 100 0.0005 0
synthCase changing100drift 100 0.0005 0 1e9 9e-5
synthCase short10 10 0.0005 0
synthCase emptied80 80 0 0 78
mkdir -p emptied80/78 && touch emptied80/78/liggghts.restart.emptied
synthCase emptiedRanks100 100 0 0 98
for t in 98 100
do
    mkdir -p emptiedRanks100/processor0/$t
    touch emptiedRanks100/processor0/$t/liggghts.restart.emptied
done

# ruleChecks <analysis script>: the cases of the header
ruleChecks()
{
    local py="$1" out rc change
    # expect <case> <maxTime> <exit status> <printed height change mm>
    #        <printed [E] change> <text> [<the piece's end s>]
    expect()
    {
        out=$(/usr/bin/python3 "$py" ended "$1" --window 20 --tolerance 0.005 \
              --maxTime "$2" ${7:+--pieceEnd $7} 2>&1)
        rc=$?
        echo "  $1, longest run $2 s: exit $rc: $out"
        [ "$rc" = "$3" ] || fail "$1 (longest run $2 s): exit $rc, expected $3"
        change=$(echo "$out" | sed -n 's/.*: change \([0-9.]*\) mm.*/\1/p' | head -1)
        check "height change of $1" "$change" "v >= $4 - 0.1 && v <= $4 + 0.1" \
            "$1: printed height change '$change' mm, expected $4 mm"
        change=$(echo "$out" | sed -n 's/.*\[E\] [0-9.]* -> [0-9.]*: change \([0-9.]*\) .*/\1/p' | head -1)
        check "[E] change of $1" "$change" "v >= $5 - 0.001 && v <= $5 + 0.001" \
            "$1: printed [E] change '$change', expected $5"
        echo "$out" | grep -q "$6" || fail "$1 (longest run $2 s): no '$6' in: $out"
    }
    expect changing80 100 1 10.0 0.000 'still changing'
    expect slowing80 100 0 3.0 0.000 'the breach has ended'
    expect losing80 100 1 0.0 0.050 'still changing'
    expect shedding80 100 0 0.0 0.010 'the breach has ended'
    expect changing100 100 0 10.0 0.000 'NOT ENDED'
    expect changing100 200 1 10.0 0.000 'still changing'
    expect changing100drift 100 0 10.0 0.000 'NOT ENDED' 100
    expect changing100drift 100 0 10.0 0.000 'NOT ENDED'
    expect changing100drift 200 1 10.0 0.000 'still changing' 100
    expect changing80 100 0 10.0 0.000 'NOT ENDED' 100
    # gone <case> <the mark it must name>
    gone()
    {
        out=$(/usr/bin/python3 "$py" ended "$1" --window 20 --tolerance 0.005 \
              --maxTime 200 2>&1)
        rc=$?
        echo "  $1: exit $rc: $out"
        [ "$rc" = 0 ] || fail "$1 (every grain gone): exit $rc, expected 0"
        echo "$out" | grep -q "every grain has left the flume ($2)" \
            || fail "$1: no 'every grain has left the flume ($2)' in: $out"
    }
    gone emptied80 78/liggghts.restart.emptied
    gone emptiedRanks100 processor0/98/liggghts.restart.emptied
    # short <maxTime> <exit status> <text>: a 10 s run, shorter than the
    # window
    short()
    {
        out=$(/usr/bin/python3 "$py" ended short10 --window 20 --tolerance 0.005 \
              --maxTime "$1" 2>&1)
        rc=$?
        echo "  short10, longest run $1 s: exit $rc: $out"
        [ "$rc" = "$2" ] || fail "short10 (longest run $1 s): exit $rc, expected $2"
        echo "$out" | grep -q "$3" || fail "short10 (longest run $1 s): no '$3' in: $out"
    }
    short 200 1 'shorter than the 20 s window: not ended'
    short 10 0 'NOT ENDED'
}

# mutant <name> <sed expression>: a copy of the analysis (damBreachAnalysis.py
# and its package damBreach/) in <name>/, its rule damBreach/ended.py
# changed by the expression
mutant()
{
    rm -rf "$1" && mkdir -p "$1/damBreach" && cp "$analysis" "$1"/ \
        && cp "$(dirname "$ruleModule")"/*.py "$1"/damBreach/ \
        || fail "negative control $1: cannot copy the analysis"
    sed -i "$2" "$1"/damBreach/ended.py
    cmp -s "$ruleModule" "$1"/damBreach/ended.py \
        && fail "negative control $1: the rule's line was not found"
}

# negative controls: the rule broken in seven ways must fail the checks
rule="level = state\['height_change'\] < tolerance and state\['energy_change'\] < energy_tolerance"
mutant noTolerance "s/$rule/level = True/"
mutant noEnergy "s/$rule/level = state['height_change'] < tolerance/"
mutant noLongestRun "s/if not done and reached(case, state\['t_end'\], max_time, piece_end):/if False:/"
mutant lastDumpLongestRun "s/    end = piece_end$/    end = t_end/; s/end = t_end + (dumps/end = t_end + 0*(dumps/"
mutant ignorePieceEnd "s/    end = piece_end$/    end = None/"
mutant noEmptied "s/state\['gone'\] is not None or (not state\['short'\] and level)/not state['short'] and level/; s/    if state\['gone'\]:/    if False:/"
mutant textOrder 's/key=time_of)/)/'
for broken in noTolerance noEnergy noLongestRun lastDumpLongestRun ignorePieceEnd noEmptied textOrder
do
    msg=$( (ruleChecks $broken/damBreachAnalysis.py) 2>&1 ) \
        && fail "the checks pass with the rule broken ($broken)"
    echo "negative control $broken: ${msg##*FAIL: }"
done

# everyChecks <analysis script>: `deposit --every 20` on the run with the
# DEM step of 9e-5 s (dumps 0.50004 s apart) takes the dump nearest each
# multiple of 20 s, and the last: 0, 20.0, 40.0, 60.0, 80.0 and 99.5 s
everyChecks()
{
    local times
    times=$(/usr/bin/python3 "$1" deposit changing100drift --every 20 2>&1 \
            | awk '$1 == "changing100drift" {printf "%s ", $2}')
    echo "  deposit --every 20, changing100drift: $times"
    [ "$times" = "0.0 20.0 40.0 60.0 80.0 99.5 " ] \
        || fail "deposit --every 20 on changing100drift: times '$times', expected '0.0 20.0 40.0 60.0 80.0 99.5 '"
}
rm -rf exactEvery && mkdir -p exactEvery/damBreach && cp "$analysis" exactEvery/ \
    && cp "$(dirname "$ruleModule")"/*.py exactEvery/damBreach/ \
    || fail "negative control exactEvery: cannot copy the analysis"
sed -i 's/<= 0.5\*interval + 1e-9 and i not in chosen/<= 1e-6 and i not in chosen/' exactEvery/damBreach/deposit.py
cmp -s "$(dirname "$ruleModule")"/deposit.py exactEvery/damBreach/deposit.py \
    && fail "negative control exactEvery: the line was not found"
msg=$( (everyChecks exactEvery/damBreachAnalysis.py) 2>&1 ) \
    && fail "the deposit check passes with dumps matched to the multiples of 20 s within 1e-6 s"
echo "negative control exactEvery: ${msg##*FAIL: }"

ruleChecks "$analysis"
everyChecks "$analysis"
pass "the run goes on at 10 mm or [E] 0.050 over 20 s, stops at 3 mm and [E] 0.010 over 20 s, stops NOT ENDED at the longest run (100 s, also when its last dump falls 0.49 s short of it; not at -maxTime 200), and stops when every grain has gone, naming the earliest mark; deposit --every 20 takes the dump nearest each 20 s"
