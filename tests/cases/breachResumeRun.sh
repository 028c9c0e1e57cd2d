#!/bin/bash
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
# `Allrun -resume` on real dam-breach runs (tutorials/interDemFoam/
# landslideDamBreach; case.damBreach's small run: C4, lake 3 cm below the
# crest), shortened in this copy of the tutorial so that a run is a chain
# of pieces within seconds: the first piece to 2 s instead of 60, then
# pieces of 2 s instead of 20, writes every 1 s, the longest run 6 s (the
# run-length rule, with its 20 s window, goes on to 6 s and stops there,
# NOT ENDED). The dam is poured first. Checks:
#   - the run without a stop has three pieces (log.interDemFoam, .to4, .to6);
#   - a run killed (SIGKILL to its process group) in its first piece, past
#     1.5 s (write of 1 s on disk), then resumed: "start", and a
#     damBreach.summary identical (diff) to the run without a stop;
#   - a run killed in its second piece, past 3.5 s (writes of 1, 2, 3 s),
#     then resumed: "from 2 -" (the first piece's end), the stopped log in
#     interrupted/log.interDemFoam.to4, the pieces .to4 and .to6 run again,
#     and the summary identical to the run without a stop;
#   - resuming that finished case again prints "finished", runs no solver
#     and leaves its solver log (md5) and summary unchanged.
# Negative control: with the resume module (damBreach/resume.py) changed to
# go on from the latest write (3 s) instead of the last complete piece's
# end, a run killed the same way and resumed must give a different summary.
# (Stopped pieces, cleaning, 2 ranks and bad settings are checked on
# synthetic case folders by case.breachResume.)
# Reference: the same run without a stop. Measured: the resumed runs'
# damBreach.summary identical to it (diff).
. "$(dirname "$0")/caseFunctions.sh"

copyTutorial landslideDamBreach breachResumeRun
rm -f DEM/dam.*.restart                        # pour the dam too
# pieces of seconds: first piece 2 s, then 2 s each, writes every 1 s (the
# run's lengths per scale: Allrun's scripts/options.py)
sed -i "s/defaultLake='0.15', defaultEnd='60', maxEnd='300'/defaultLake='0.15', defaultEnd='2', maxEnd='300'/; s/^PIECE_LENGTH = '20' /PIECE_LENGTH = '2' /" scripts/options.py
grep -q "defaultEnd='2', maxEnd='300'" scripts/options.py && grep -q "^PIECE_LENGTH = '2' " scripts/options.py \
    || fail "could not shorten the pieces in scripts/options.py (the lines to change were not found)"
foamDictionary -entry writeInterval -set 1 system/controlDict > /dev/null \
    || fail "could not set writeInterval in system/controlDict"
options="-scenario C4 -lakeLevel 0.27 -maxTime 6"

./Allrun $options -tag whole > log.Allrun.whole 2>&1 \
    || { tail -20 log.Allrun.whole; fail "Allrun failed (log.Allrun.whole)"; }
whole=C4.small.whole/damBreach.summary
[ -s "$whole" ] || fail "$whole not written"
for log in log.interDemFoam log.interDemFoam.to4 log.interDemFoam.to6
do
    grep -q "^End" C4.small.whole/$log || fail "the run without a stop has no complete $log"
done
grep -q "^end time \[s\] *6$" "$whole" || fail "$whole: the run did not end at 6 s"

# runStopped <tag> <time s>: the run in case C4.small.<tag>, killed once
# its solver has passed <time>
runStopped()
{
    local case=C4.small.$1 t="" k log
    # a process group of its own (job control), so that one kill stops
    # Allrun, the solver and LIGGGHTS together
    set -m
    ./Allrun $options -tag "$1" > log.Allrun.$1 2>&1 &
    local pid=$!
    set +m
    for k in $(seq 1 2400)
    do
        log=$(ls -t $case/log.interDemFoam* 2> /dev/null | head -1)
        t=$(grep "^Time = " "$log" 2> /dev/null | tail -1 | awk '{print $3}')
        [ -n "$t" ] && awk -v t="$t" -v s="$2" 'BEGIN { exit !(t > s) }' && break
        kill -0 "$pid" 2> /dev/null || fail "the run $1 ended before it could be stopped (log.Allrun.$1)"
        sleep 0.25
    done
    kill -9 -- -"$pid" 2> /dev/null
    wait "$pid" 2> /dev/null
    for k in $(seq 1 40)                       # killed processes take a moment
    do
        pgrep -g "$pid" > /dev/null || break
        sleep 0.25
    done
    pgrep -g "$pid" > /dev/null && fail "the run $1 is still running 10 s after the kill"
    echo "  $1 stopped at t = $t s in $(basename "$log") (writes: $(cd $case && ls -d [0-9]* | grep -v orig | sort -n | tr '\n' ' '))"
    grep -q "^End" "$log" && fail "$1: $log had ended before the run was stopped"
    return 0
}

# resumeCheck <tag> <state Allrun must report>: resume the stopped case;
# its summary must equal the run's without a stop
resumeCheck()
{
    ./Allrun $options -tag "$1" -resume > log.Allrun.$1.resume 2>&1 \
        || { tail -20 log.Allrun.$1.resume; fail "Allrun -resume failed (log.Allrun.$1.resume)"; }
    grep "^Allrun: -resume" log.Allrun.$1.resume
    grep -q "^Allrun: -resume C4.small.$1: $2\$" log.Allrun.$1.resume \
        || fail "$1: Allrun -resume did not go on '$2' (log.Allrun.$1.resume)"
    local s=C4.small.$1/damBreach.summary
    [ -s "$s" ] || fail "$1: $s not written"
    diff "$whole" "$s" > diff.$1 \
        || { cat diff.$1; fail "$1: the resumed run's summary differs from the run's without a stop"; }
    return 0
}

# negative control: going on from the latest write (3 s)
runStopped latestWrite 3.5
[ -d C4.small.latestWrite/3 ] || fail "latestWrite: stopped before its write of 3 s"
cp damBreach/resume.py damBreach/resume.py.orig
sed -i 's/    return "from", done\[1\], done\[0\], settings/    return "from", max(time_folders(case)), done[0], settings/' damBreach/resume.py
cmp -s damBreach/resume.py damBreach/resume.py.orig \
    && fail "negative control latestWrite: the line to break was not found"
msg=$( (resumeCheck latestWrite "from 3 -") 2>&1 ) \
    && fail "the resumed summary equals the run's without a stop with the module broken (latestWrite)"
echo "negative control latestWrite: ${msg##*FAIL: }"
case "$msg" in
    *"summary differs"*) ;;
    *) fail "negative control latestWrite fails, but not for the summary: $msg" ;;
esac
mv damBreach/resume.py.orig damBreach/resume.py

runStopped first 1.5
resumeCheck first start
echo "  first: resumed from the start, summary identical to the run's without a stop"

runStopped later 3.5
[ -d C4.small.later/3 ] || fail "later: stopped before its write of 3 s"
resumeCheck later "from 2 -"
[ -f C4.small.later/interrupted/log.interDemFoam.to4 ] \
    || fail "the stopped log is not in C4.small.later/interrupted/"
for log in log.interDemFoam.to4 log.interDemFoam.to6
do
    grep -q "^End" C4.small.later/$log || fail "later: no complete $log after the resume"
done
echo "  later: resumed from 2 s, summary identical to the run's without a stop"

# resuming the finished case: analysed, not rerun
before=$(cat C4.small.later/log.interDemFoam* | md5sum)
./Allrun $options -tag later -resume > log.Allrun.again 2>&1 \
    || { tail -20 log.Allrun.again; fail "Allrun -resume of the finished case failed"; }
grep -q "^Allrun: -resume C4.small.later: finished$" log.Allrun.again \
    || fail "the finished case was not recognised as finished (log.Allrun.again)"
grep -q "^Running interDemFoam" log.Allrun.again \
    && fail "the finished case was run again"
[ "$(cat C4.small.later/log.interDemFoam* | md5sum)" = "$before" ] \
    || fail "the finished case's solver logs changed"
diff "$whole" C4.small.later/damBreach.summary > /dev/null \
    || fail "the finished case's summary changed when resumed again"

pass "runs of three 2 s pieces killed in the first piece (past 1.5 s) and in the second (past 3.5 s) and resumed (from the start; from 2 s, the stopped log in interrupted/) give the same damBreach.summary as the run without a stop; resuming the finished case only analyses it; going on from the latest write instead gives another summary"
