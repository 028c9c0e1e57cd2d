#!/bin/bash
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
# `Allrun -resume` on a real dam-breach run (tutorials/interDemFoam/
# landslideDamBreach; case.damBreach's small run: C4, lake 3 cm below the
# crest, a fixed end of 8 s, writes every 2 s). A run killed (SIGKILL to
# Allrun, the solver and LIGGGHTS) once the solver has passed 5 s, with the
# writes of 2 and 4 s on disk, and then resumed must give a
# damBreach.summary identical, line by line, to the same run made without
# a stop (the stopped piece is run again from its start, the state an
# uninterrupted run has there); the resumed case keeps the stopped log in
# interrupted/. Resuming the finished case again analyses it without
# rerunning (no new solver log) and leaves the summary unchanged.
# Negative control: with the resume module changed to go on from the
# latest write (4 s) instead of the last complete piece, the resumed run's
# summary differs (it ends at 4 s), and the check must fail.
# (The pieces of a run "until the breach has ended" are checked on
# synthetic case folders by case.breachResume.)
. "$(dirname "$0")/caseFunctions.sh"

copyTutorial landslideDamBreach breachResumeRun
rm -f DEM/dam.*.restart                        # pour the dam too
options="-scenario C4 -lakeLevel 0.27 -endTime 8"

./Allrun $options > log.Allrun.whole 2>&1 \
    || { tail -20 log.Allrun.whole; fail "Allrun failed (log.Allrun.whole)"; }
whole=C4.small/damBreach.summary
[ -s "$whole" ] || fail "$whole not written"
grep -q "^end time \[s\] *8$" "$whole" || fail "$whole: the run did not end at 8 s"

# runStopped <tag>: the run in case C4.small.<tag>, killed once the
# solver's log has passed 5 s
runStopped()
{
    local log=C4.small.$1/log.interDemFoam t=0 k
    # a process group of its own (job control), so that one kill stops
    # Allrun, the solver and LIGGGHTS together
    set -m
    ./Allrun $options -tag "$1" > log.Allrun.$1 2>&1 &
    local pid=$!
    set +m
    for k in $(seq 1 1200)
    do
        t=$(grep "^Time = " "$log" 2>/dev/null | tail -1 | awk '{print $3}')
        [ -n "$t" ] && awk -v t="$t" 'BEGIN { exit !(t > 5) }' && break
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
    echo "  $1 stopped at t = $t s (writes: $(cd C4.small.$1 && ls -d [0-9]* | grep -v orig | sort -n | tr '\n' ' '))"
    [ -d C4.small.$1/4 ] || fail "$1: stopped before its write of 4 s"
    grep -q "^End" "$log" && fail "$1: the run had ended before it was stopped"
    return 0
}

# resumeCheck <tag>: resume the stopped case; its summary must equal the
# uninterrupted run's
resumeCheck()
{
    ./Allrun $options -tag "$1" -resume > log.Allrun.$1.resume 2>&1 \
        || { tail -20 log.Allrun.$1.resume; fail "Allrun -resume failed (log.Allrun.$1.resume)"; }
    grep "^Allrun: -resume" log.Allrun.$1.resume
    local s=C4.small.$1/damBreach.summary
    [ -s "$s" ] || fail "$1: $s not written"
    diff "$whole" "$s" > diff.$1 \
        || { cat diff.$1; fail "$1: the resumed run's summary differs from the uninterrupted run's"; }
    return 0
}

# negative control: resuming from the latest write
runStopped latestWrite
sed -i 's/        return "start", 0.0, None, settings/        return "from", max(time_folders(case)), "", settings/' damBreachResume.py
grep -q 'return "from", max(time_folders(case))' damBreachResume.py \
    || fail "negative control latestWrite: the line to break was not found"
msg=$( (resumeCheck latestWrite) 2>&1 ) \
    && fail "the resumed summary equals the uninterrupted one with the module broken (latestWrite)"
echo "negative control latestWrite: ${msg##*FAIL: }"
case "$msg" in
    *"summary differs"*) ;;
    *) fail "negative control latestWrite fails, but not for the summary: $msg" ;;
esac
cp "$INTERDEMFOAM_TUTORIALS/landslideDamBreach/damBreachResume.py" .

runStopped resumed
resumeCheck resumed
[ -f C4.small.resumed/interrupted/log.interDemFoam ] \
    || fail "the stopped log is not in C4.small.resumed/interrupted/"
echo "  resumed: summary identical to the uninterrupted run's"

# resuming the finished case: analysed, not rerun
before=$(md5sum < C4.small.resumed/log.interDemFoam)
./Allrun $options -tag resumed -resume > log.Allrun.again 2>&1 \
    || { tail -20 log.Allrun.again; fail "Allrun -resume of the finished case failed"; }
grep -q "^Allrun: -resume C4.small.resumed: finished" log.Allrun.again \
    || fail "the finished case was not recognised as finished (log.Allrun.again)"
grep -q "^Running interDemFoam" log.Allrun.again \
    && fail "the finished case was run again"
[ "$(md5sum < C4.small.resumed/log.interDemFoam)" = "$before" ] \
    || fail "the finished case's solver log changed"
diff "$whole" C4.small.resumed/damBreach.summary > /dev/null \
    || fail "the finished case's summary changed when resumed again"

pass "a run killed past 5 s (writes of 2 and 4 s on disk) and resumed gives the same damBreach.summary as the uninterrupted run, its stopped log kept in interrupted/; resuming it again only analyses it; resuming from the latest write instead gives another summary"
