#!/bin/bash
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
# Where a stopped landslide-dam run goes on (tutorials/interDemFoam/
# landslideDamBreach/damBreachResume.py, the rule in its package's
# damBreach/resume.py, which `Allrun -resume` calls): a
# run is a chain of pieces (to 60 s, then 20 s each, a restart from the
# write at the previous piece's end); it goes on from the end of its last
# complete piece (log ending in `End`), and what the interrupted piece
# wrote after that state is removed. Seconds, no solver: synthetic case
# folders (empty files) laid out as Allrun leaves them. Checks:
#   - stopped in the piece to 100 s (log.interDemFoam.to100 without End,
#     writes up to 96 s): prints "from 80 .to80"; time folders 82-96 gone,
#     0 and 80/liggghts.restart kept; postProcessing/*/80 and
#     log.liggghts.80 gone, */60 and log.liggghts.60 kept; dumps past step
#     800000 (80 s at 1e-4 s) gone, 800000 kept; the interrupted log moved
#     to interrupted/; the same with --dry-run first prints the same and
#     keeps 96 and the stopped log;
#   - stopped in the first piece (to 60 s, writes up to 36 s): "start";
#     every time folder but 0, every postProcessing/*/0, log.liggghts and
#     every dump past step 0 gone;
#   - finished (wallTime there): "finished", nothing removed;
#   - on 2 ranks (the DEM state in processor0's folders only, as the
#     solver writes it), stopped in the piece to 100 s: both processors'
#     time folders 82-96 gone, 80 kept; with processor0/80/liggghts.restart
#     missing: exit 1 naming processor0 and liggghts.restart, and nothing
#     removed or moved (96 and the stopped log still there);
#   - the last piece ended with every grain gone (80/liggghts.restart.
#     emptied, the solver's mark, instead of the state): "from 80 .to80";
#   - a longest run of 250 s: Allrun's last piece ends at 260 s, so a run
#     stopped in it goes on "from 240 .to240", its log.interDemFoam.to260
#     moved to interrupted/ and 256 gone;
#   - a fixed end (untilEnded no, firstEnd 8) whose one piece completed:
#     "from 8 -";
#   - Allrun.run without demDt: exit 1 naming Allrun.run and demDt; no
#     Allrun.run and no wallTime: exit 1 naming Allrun.run.
# Negative controls: the checks fail on copies of the module (damBreach/
# resume.py, with damBreachResume.py and the package beside it) that keep the
# dumps past the restart step, that restart from the latest write (not the
# last complete piece's end) and that take a log without End as complete.
# Reference: the folders Allrun leaves, laid out by hand. Measured: every
# check as constructed; no number.
. "$(dirname "$0")/caseFunctions.sh"

module="$INTERDEMFOAM_TUTORIALS/landslideDamBreach/damBreachResume.py"
resumeModule="$INTERDEMFOAM_TUTORIALS/landslideDamBreach/damBreach/resume.py"
[ -f "$module" ] && [ -f "$resumeModule" ] || fail "no $module or $resumeModule"
rm -rf "$runDir/breachResume"
mkdir -p "$runDir/breachResume"
cd "$runDir/breachResume" || fail "cannot enter $runDir/breachResume"

# synthCase <name> <firstEnd> <untilEnded> <nProcs> <last write s>
#           <complete pieces' suffixes ("-" for the first)> [<interrupted suffix>]
synthCase()
{
    local c=$1 first=$2 until=$3 np=$4 last=$5 done=$6 stopped=$7
    rm -rf "$c"
    mkdir -p "$c/post" "$c/postProcessing/lakeLevel"
    printf 'firstEnd %s\npieceLength 20\nuntilEnded %s\nmaxEnd 200\nnProcs %s\ndemDt 1e-4\n' \
        "$first" "$until" "$np" > "$c/Allrun.run"
    local s
    for s in $done
    do
        [ "$s" = - ] && s=""
        printf 'Time = 1\n\nEnd\n\n' > "$c/log.interDemFoam$s"
    done
    [ -n "$stopped" ] && printf 'Time = 1\n' > "$c/log.interDemFoam$stopped"
    local roots="$c" r t k
    [ "$np" -gt 1 ] && roots="$c/processor0 $c/processor1"
    for r in $roots
    do
        for t in $(seq 0 2 "$last")
        do
            mkdir -p "$r/$t"
            # the DEM state: in processor0's folder when decomposed
            [ "$t" = 0 ] || [ "$r" = "$c/processor1" ] || touch "$r/$t/liggghts.restart"
        done
    done
    for t in 0 60 80
    do
        [ "$t" -le "$last" ] && mkdir -p "$c/postProcessing/lakeLevel/$t" \
            && if [ "$t" = 0 ]; then touch "$c/log.liggghts"; else touch "$c/log.liggghts.$t"; fi
    done
    for k in $(seq 0 5000 $((last*10000)))
    do
        touch "$c/post/particles.$k.txt" "$c/post/particles_$k.vtk"
    done
}

there() { [ -e "$1" ] || fail "$2: $1 is gone, it must be kept"; }
gone() { [ ! -e "$1" ] || fail "$2: $1 is still there, it must be removed"; }

# resumeChecks <module>: exits non-zero (FAIL) when a check fails
resumeChecks()
{
    py=$1

    synthCase stopped100 60 yes 1 96 "- .to80" .to100
    dry=$(/usr/bin/python3 "$py" stopped100 --dry-run 2>/dev/null)
    [ "$dry" = "from 80 .to80" ] || fail "stopped100 --dry-run printed '$dry', expected 'from 80 .to80'"
    there stopped100/96 "stopped100 --dry-run"
    there stopped100/log.interDemFoam.to100 "stopped100 --dry-run"
    out=$(/usr/bin/python3 "$py" stopped100 2>/dev/null)
    echo "  stopped100: $out"
    [ "$out" = "from 80 .to80" ] || fail "stopped100 printed '$out', expected 'from 80 .to80'"
    for t in $(seq 82 2 96); do gone stopped100/$t stopped100; done
    there stopped100/80/liggghts.restart stopped100
    there stopped100/0 stopped100
    gone stopped100/postProcessing/lakeLevel/80 stopped100
    there stopped100/postProcessing/lakeLevel/60 stopped100
    gone stopped100/log.liggghts.80 stopped100
    there stopped100/log.liggghts.60 stopped100
    for k in $(seq 805000 5000 960000)
    do
        gone stopped100/post/particles.$k.txt stopped100
        gone stopped100/post/particles_$k.vtk stopped100
    done
    there stopped100/post/particles.800000.txt stopped100
    there stopped100/post/particles_800000.vtk stopped100
    gone stopped100/log.interDemFoam.to100 stopped100
    there stopped100/interrupted/log.interDemFoam.to100 stopped100
    there stopped100/log.interDemFoam.to80 stopped100

    synthCase stoppedFirst 60 yes 1 36 "" ""
    printf 'Time = 1\n' > stoppedFirst/log.interDemFoam
    out=$(/usr/bin/python3 "$py" stoppedFirst 2>/dev/null)
    echo "  stoppedFirst: $out"
    [ "$out" = start ] || fail "stoppedFirst printed '$out', expected 'start'"
    there stoppedFirst/0 stoppedFirst
    for t in $(seq 2 2 36); do gone stoppedFirst/$t stoppedFirst; done
    gone stoppedFirst/postProcessing/lakeLevel/0 stoppedFirst
    gone stoppedFirst/log.liggghts stoppedFirst
    for k in $(seq 5000 5000 360000)
    do
        gone stoppedFirst/post/particles.$k.txt stoppedFirst
        gone stoppedFirst/post/particles_$k.vtk stoppedFirst
    done
    there stoppedFirst/post/particles.0.txt stoppedFirst

    synthCase finished 60 yes 1 80 "- .to80" ""
    echo 612 > finished/wallTime
    out=$(/usr/bin/python3 "$py" finished 2>/dev/null)
    echo "  finished: $out"
    [ "$out" = finished ] || fail "finished printed '$out', expected 'finished'"
    there finished/80 finished
    there finished/post/particles.800000.txt finished

    synthCase ranks2 60 yes 2 96 "- .to80" .to100
    out=$(/usr/bin/python3 "$py" ranks2 2>/dev/null)
    echo "  ranks2: $out"
    [ "$out" = "from 80 .to80" ] || fail "ranks2 printed '$out', expected 'from 80 .to80'"
    for r in processor0 processor1
    do
        for t in $(seq 82 2 96); do gone ranks2/$r/$t ranks2; done
        there ranks2/$r/80 ranks2
    done
    there ranks2/processor0/80/liggghts.restart ranks2
    synthCase ranks2bad 60 yes 2 96 "- .to80" .to100
    rm ranks2bad/processor0/80/liggghts.restart
    msg=$(/usr/bin/python3 "$py" ranks2bad 2>&1) \
        && fail "ranks2bad (processor0/80/liggghts.restart missing): exit 0, expected 1"
    echo "  ranks2bad: $msg"
    echo "$msg" | grep -q "processor0" && echo "$msg" | grep -q "liggghts.restart" \
        || fail "ranks2bad: the message does not name processor0 and liggghts.restart: $msg"
    there ranks2bad/processor0/96 "ranks2bad (nothing may be removed)"
    there ranks2bad/log.interDemFoam.to100 "ranks2bad (nothing may be moved)"

    synthCase emptied 60 yes 1 96 "- .to80" .to100
    mv emptied/80/liggghts.restart emptied/80/liggghts.restart.emptied
    out=$(/usr/bin/python3 "$py" emptied 2>/dev/null)
    echo "  emptied: $out"
    [ "$out" = "from 80 .to80" ] || fail "emptied (80/liggghts.restart.emptied) printed '$out', expected 'from 80 .to80'"

    synthCase longest250 60 yes 1 256 "- .to80 .to100 .to120 .to140 .to160 .to180 .to200 .to220 .to240" .to260
    sed -i 's/^maxEnd 200$/maxEnd 250/' longest250/Allrun.run
    out=$(/usr/bin/python3 "$py" longest250 2>/dev/null)
    echo "  longest250: $out"
    [ "$out" = "from 240 .to240" ] || fail "longest250 printed '$out', expected 'from 240 .to240'"
    there longest250/interrupted/log.interDemFoam.to260 longest250
    gone longest250/log.interDemFoam.to260 longest250
    gone longest250/256 longest250

    synthCase fixedEnd 8 no 1 8 "-" ""
    out=$(/usr/bin/python3 "$py" fixedEnd 2>/dev/null)
    echo "  fixedEnd: $out"
    [ "$out" = "from 8 -" ] || fail "fixedEnd printed '$out', expected 'from 8 -'"
    there fixedEnd/8/liggghts.restart fixedEnd

    synthCase noDt 60 yes 1 80 "-" .to80
    sed -i '/demDt/d' noDt/Allrun.run
    msg=$(/usr/bin/python3 "$py" noDt 2>&1) && fail "noDt: exit 0, expected 1"
    echo "  noDt: $msg"
    echo "$msg" | grep -q "Allrun.run" && echo "$msg" | grep -q "demDt" \
        || fail "noDt: the message does not name Allrun.run and demDt: $msg"
    there noDt/80 "noDt (nothing may be removed)"
    synthCase noSettings 60 yes 1 70 "-" .to80
    rm noSettings/Allrun.run
    msg=$(/usr/bin/python3 "$py" noSettings 2>&1) && fail "noSettings: exit 0, expected 1"
    echo "  noSettings: $msg"
    echo "$msg" | grep -q "Allrun.run" || fail "noSettings: the message does not name Allrun.run: $msg"
    there noSettings/70 "noSettings (nothing may be removed)"
    return 0
}

# mutant <name> <sed expression>: a copy of damBreachResume.py and its
# package damBreach/ in <name>/, damBreach/resume.py changed by the expression
mutant()
{
    rm -rf "$1" && mkdir -p "$1/damBreach" && cp "$module" "$1"/ \
        && cp "$(dirname "$resumeModule")"/*.py "$1"/damBreach/ \
        || fail "negative control $1: cannot copy the module"
    sed -i "$2" "$1"/damBreach/resume.py
    cmp -s "$resumeModule" "$1"/damBreach/resume.py \
        && fail "negative control $1: the line to break was not found"
}

# negative controls: the module broken in three ways must fail the checks
mutant keepDumps 's/if m and int(m.group(1)) > step0:/if False:/'
mutant latestWrite 's/    return "from", done\[1\], done\[0\], settings/    return "from", max(time_folders(case)), done[0], settings/'
mutant noEnd 's/return any(line.strip() == "End" for line in f)/return True/'
for broken in keepDumps latestWrite noEnd
do
    msg=$( (resumeChecks $broken/damBreachResume.py) 2>&1 ) \
        && fail "the checks pass with the module broken ($broken)"
    echo "negative control $broken: ${msg##*FAIL: }"
done

resumeChecks "$module"
pass "a stopped run goes on from its last complete piece's end (80 s; the first piece stopped: from the start; on 2 ranks too), what the interrupted piece wrote after it removed and its log kept in interrupted/; a finished run is left as it is; a missing restart or setting stops with a message naming it"
