#!/bin/bash
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#------------------------------------------------------------------------------
# Damaged DEM restart files (the 20 mm settling column of the single-particle
# benchmark, writing every 0.01 s), on 1 and on 2 ranks:
#
#   restartDamaged.sh truncated
#       0.03/liggghts.restart cut to its first 200 bytes (what a kill during
#       the write or a full disk leaves): the restart must stop within 30 s,
#       with less than 10 MB of output (log + LIGGGHTS logs), naming the
#       file, what is wrong ("200 bytes where ... were written") and the
#       latest complete time 0.02; -restartFromLastComplete then runs from
#       0.02 to 0.05 and ends where the uninterrupted run ends (1e-5).
#       Then the same file with its check file forged to match: LIGGGHTS
#       reads it and repeats its version warning without end; the output
#       guard must stop the run within 30 s and 10 MB.
#   restartDamaged.sh killed
#       the run is held inside the DEM restart write of t = 0.03 (its
#       temporary file made a named pipe beforehand: LIGGGHTS blocks opening
#       it) and killed there with SIGKILL: 0.03 has no liggghts.restart; a
#       restart says the run was stopped while writing it and names 0.02;
#       -restartFromLastComplete finishes the run, ending where the
#       uninterrupted run ends (1e-5).
#   restartDamaged.sh diskFull
#       the case on a tmpfs with room for 1/4, 2/4 and 3/4 of one more
#       write time (the disk fills in the fluid's fields, the particles'
#       lagrangian/ files or the DEM restart file): each run must stop
#       within 30 s with "The write of t = ... failed" and leave 0.01 and
#       0.02 unchanged (md5). Then room for about 1.5 write times: the
#       run must stop with "The write of t = ... failed", the earlier time
#       folders unchanged (md5), and, with room again,
#       -restartFromLastComplete finishes the run (1e-5). Skipped (exit 77)
#       where no tmpfs can be mounted (not root).
#
# 1e-5 of the field's largest value over all ranks: a restarted DEM is set
# up anew by LIGGGHTS (run without "pre no"), which changes the particle's
# velocity in the 7th-8th digit (case.restart); d(eps)/dt from the solid
# flux carries the particle's velocity into the pressure equation, so that
# reaches U at about 3e-6 (the particle itself agrees to 3e-10).
# Reference: the uninterrupted run (1e-5) and the limits above (30 s, 10 MB).
# Measured (docs/reliability.md, 1 / 2 ranks): truncated 0.18 / 0.52 s,
# 74 / 76 kB, then U within 2.6e-6 / 1.7e-6; forged 0.59 / 1.54 s, 3.3 MB;
# killed 0.07 / 0.34 s, 71 / 73 kB; disk full 0.98 / 0.66 s, 441 / 249 kB;
# room for 1/4-3/4 of a write 0.92-1.09 / 0.81-0.82 s, 225-250 kB.
#------------------------------------------------------------------------------
. "${0%/*}/caseFunctions.sh"

mode="$1"
case "$mode" in
    truncated|killed|diskFull) ;;
    *) fail "usage: restartDamaged.sh truncated|killed|diskFull" ;;
esac

# run <np> [options]: the solver on 1 or 2 ranks, output to stdout
solve()
{
    local np="$1"; shift
    if [ "$np" = 1 ]
    then
        interDemFoam "$@"
    else
        mpirun --oversubscribe -np "$np" interDemFoam -parallel "$@"
    fi
}

# The base case (mesh, water, particle), decomposed for 2 ranks
makeBase()
{
    local np="$1"
    copyTutorial singleParticleSettling "restartDamaged-$mode-base$np"
    narrowSettlingColumn
    setEntry system/controlDict endTime 0.05
    setEntry system/controlDict writeInterval 0.01
    setEntry system/controlDict writeFormat ascii
    setEntry system/controlDict writePrecision 17
    restore0Dir > /dev/null
    runApplication blockMesh || fail "blockMesh"
    runApplication setFields || fail "setFields"
    if [ "$np" = 2 ]
    then
        runApplication decomposePar || fail "decomposePar"
    fi
}

# newCase <np> <name>: a copy of the base case in $runDir/<name>, entered
newCase()
{
    rm -rf "$runDir/$2"
    cp -r "$runDir/restartDamaged-$mode-base$1" "$runDir/$2"
    cd "$runDir/$2" || fail "cd $2"
}

# timeDir <np>: where the time folders with the DEM state are
timeDir() { [ "$1" = 1 ] && echo . || echo processor0; }

# sameEnd <np> <case> <reference>: U and voidfraction at t = 0.05 agree to
# 1e-5 of their largest value over all ranks
sameEnd()
{
    local dirs tag="$1 rank(s)"
    dirs=$([ "$1" = 1 ] && echo . || echo processor0 processor1)
    /usr/bin/python3 - "$2" "$3" "$tag" $dirs <<'PYEOF' || fail "$tag: the restarted run does not end where the uninterrupted one does"
import re, sys
a, b, tag, dirs = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
def field(case, name):
    s = open('%s/0.05/%s' % (case, name)).read()
    m = re.search(r'internalField\s+nonuniform\s+List<\w+>\s*(\d+)\s*\(', s)
    if m:
        body = s[m.end():].split(')\n;')[0]
    else:
        m = re.search(r'internalField\s+uniform\s+([^;]+);', s)
        if not m:
            raise SystemExit('%s: no internalField in %s/0.05/%s' % (tag, case, name))
        body = m.group(1)
    return [float(x) for x in re.findall(r'[-+0-9.eE]+', body)]
worst = 0.0
for name in ('U', 'voidfraction'):
    diff, scale = 0.0, 1e-30
    for d in dirs:
        x, y = field(a + '/' + d, name), field(b + '/' + d, name)
        if not x or len(x) != len(y):
            raise SystemExit('%s: %s/%s has %d vs %d values' % (tag, d, name, len(x), len(y)))
        diff = max(diff, max(abs(p - q) for p, q in zip(x, y)))
        scale = max(scale, max(abs(p) for p in x))
    print('%s: %s at 0.05 s, max |difference| / max |value| (all ranks) = %.3e' % (tag, name, diff/scale))
    worst = max(worst, diff/scale)
sys.exit(0 if worst < 1e-5 else 1)
PYEOF
}

# stopsQuickly <what> <log> <pattern>: the last solve stopped non-zero
# within 30 s with less than 10 MB written; its log matches <pattern>
stopsQuickly()
{
    local what="$1" log="$2" pattern="$3" bytes
    [ "$rc" -ne 0 ] || fail "$what: the run did not stop (exit 0)"
    [ "$rc" -ne 124 ] || fail "$what: the run did not stop within 60 s"
    check "$what: seconds to the error" "$secs" 'v < 30' "$what: took $secs s (limit 30)"
    bytes=$(cat "$log" log.liggghts* 2>/dev/null | wc -c)
    check "$what: bytes written" "$bytes" 'v < 10e6' "$what: wrote $bytes bytes (limit 10 MB)"
    grep -q -- "$pattern" "$log" || fail "$what: '$pattern' not in $log"
    echo "$what: stopped after $secs s, $bytes bytes of output"
}

# timed <log> <np> [options]: solve with a 60 s timeout; sets rc and secs
timed()
{
    local log="$1" t0 t1; shift
    t0=$(date +%s.%N)
    timeout 60 bash -c "$(declare -f solve); solve $*" > "$log" 2>&1
    rc=$?
    t1=$(date +%s.%N)
    secs=$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.2f", b - a }')
}

for np in 1 2
do
    makeBase $np
    newCase $np "restartDamaged-$mode-reference$np"
    solve $np > log.interDemFoam 2>&1 || fail "$np rank(s): uninterrupted run (log.interDemFoam)"
    ref="$PWD"
    d=$(timeDir $np)

    case "$mode" in
    truncated)
        newCase $np "restartDamaged-truncated$np"
        setEntry system/controlDict endTime 0.03
        solve $np > log.interDemFoam.1 2>&1 || fail "$np rank(s): run to 0.03"
        size=$(stat -c %s $d/0.03/liggghts.restart)
        head -c 200 $d/0.03/liggghts.restart > cut && mv cut $d/0.03/liggghts.restart
        setEntry system/controlDict startFrom latestTime
        setEntry system/controlDict endTime 0.05
        cp -r . ../restartDamaged-forged$np
        timed log.interDemFoam.2 $np
        stopsQuickly "$np rank(s), truncated restart file" log.interDemFoam.2 \
            "it has 200 bytes where $size were written"
        grep -q "latest complete write time is 0.02" log.interDemFoam.2 \
            || fail "$np rank(s): the error does not name the latest complete time 0.02"
        grep -q "liggghts.restart" log.interDemFoam.2 || fail "the error does not name the file"
        timed log.interDemFoam.3 $np -restartFromLastComplete
        [ "$rc" = 0 ] || fail "$np rank(s): -restartFromLastComplete failed (log.interDemFoam.3)"
        grep -q "starting from t = 0.02" log.interDemFoam.3 || fail "did not start from 0.02"
        [ -d $d/0.03.incomplete ] || fail "0.03 was not renamed 0.03.incomplete"
        sameEnd $np "$PWD" "$ref"

        # the forged check file: LIGGGHTS itself reads the damaged file
        cd ../restartDamaged-forged$np || fail "cd"
        sum=$(sha1sum $d/0.03/liggghts.restart | cut -d' ' -f1)
        sed -i "s/^size .*/size        200;/; s/^sha1 .*/sha1        $sum;/" \
            $d/0.03/liggghts.restart.check
        timed log.interDemFoam.2 $np
        stopsQuickly "$np rank(s), damaged file read by LIGGGHTS" log.interDemFoam.2 \
            "LIGGGHTS wrote the same line more than"
        ;;

    killed)
        newCase $np "restartDamaged-killed$np"
        # The write of t = 0.03 is held in the middle: its temporary DEM file
        # is made a named pipe beforehand, so LIGGGHTS blocks opening it
        # (the fields and particles of 0.03 are written by then); the run
        # is killed there, while the DEM restart file is being written
        mkdir -p $d/0.03 && mkfifo $d/0.03/liggghts.restart.writing || fail "mkfifo"
        solve $np > log.interDemFoam.1 2>&1 &
        pid=$!
        for i in $(seq 1 600)
        do
            [ -f $d/0.03/U ] && break
            kill -0 $pid 2>/dev/null || break
            sleep 0.1
        done
        sleep 1
        kill -0 $pid 2>/dev/null || fail "$np rank(s): the run ended before it was held at t = 0.03"
        [ -p $d/0.03/liggghts.restart.writing ] && [ ! -e $d/0.03/liggghts.restart ] \
            || fail "$np rank(s): the run is not held in the DEM restart write"
        # this case's solver processes (others may run on the machine)
        for p in $(pgrep -f "^(mpirun|interDemFoam)")
        do
            [ "$(readlink /proc/$p/cwd)" = "$PWD" ] && kill -KILL $p
        done
        wait $pid 2>/dev/null
        killed=0.03
        echo "$np rank(s): killed while writing t = $killed"
        [ ! -f $d/$killed/liggghts.restart ] || fail "a liggghts.restart exists under its final name in the killed time $killed"
        setEntry system/controlDict startFrom latestTime
        timed log.interDemFoam.2 $np
        stopsQuickly "$np rank(s), killed while writing t = $killed" log.interDemFoam.2 \
            "the run was stopped while writing it"
        last=0.02
        grep -q "latest complete write time is $last\." log.interDemFoam.2 \
            || fail "$np rank(s): the error does not name $last as the latest complete time"
        timed log.interDemFoam.3 $np -restartFromLastComplete
        [ "$rc" = 0 ] || fail "$np rank(s): -restartFromLastComplete failed (log.interDemFoam.3)"
        grep -q "starting from t = $last s" log.interDemFoam.3 || fail "did not start from $last"
        sameEnd $np "$PWD" "$ref"
        ;;

    diskFull)
        newCase $np "restartDamaged-diskFull$np"
        setEntry system/controlDict endTime 0.02
        solve $np > log.interDemFoam.1 2>&1 || fail "$np rank(s): run to 0.02"
        # room for the case as it is and about one more write time
        used=$(du -sb . | cut -f1)
        oneTime=$(du -sb $d/0.02 | cut -f1)
        [ "$np" = 2 ] && oneTime=$((2*oneTime))
        mnt="$runDir/restartDamaged-tmpfs$np"
        mkdir -p "$mnt"
        # Where the disk fills moves with the room left: in the fluid's
        # fields, in the particles' lagrangian/ files, in the DEM restart
        # file. Rooms of 1/4, 2/4 and 3/4 of one more write time each stop
        # the run with the message and leave 0.01 and 0.02 as they were
        find $d/0.01 $d/0.02 -type f | sort | xargs md5sum > "$runDir/restartDamaged-before$np.md5"
        for quarter in 1 2 3
        do
            room=$(( (used + quarter*oneTime/4)/1024 + 64 ))
            mount -t tmpfs -o size=${room}k tmpfs "$mnt" 2>/dev/null \
                || { echo "SKIPPED: cannot mount a tmpfs (needs root) to fill a disk"; exit 77; }
            cp -r . "$mnt/case" 2>/dev/null
            (
                cd "$mnt/case" || exit 1
                setEntry system/controlDict startFrom latestTime
                setEntry system/controlDict endTime 0.05
                timed "$runDir/restartDamaged-diskFull$np-$quarter.log" $np
                stopsQuickly "$np rank(s), disk full with $quarter/4 of a write time" \
                    "$runDir/restartDamaged-diskFull$np-$quarter.log" "The write of t = .* failed"
                md5sum -c --quiet "$runDir/restartDamaged-before$np.md5" \
                    || fail "$np rank(s): the full disk ($quarter/4) changed earlier write times"
                echo "$np rank(s), room for $quarter/4 of a write time: stopped with the message in" \
                    "$(grep -A3 'The write of t = .* failed' "$runDir/restartDamaged-diskFull$np-$quarter.log" \
                       | grep -o "$mnt/case/[^ )\"]*" | head -1 | sed "s|$mnt/case/||")"
            ) || { umount "$mnt"; exit 1; }
            umount "$mnt" || fail "umount"
        done
        room=$(( (used + 3*oneTime/2)/1024 + 64 ))
        mount -t tmpfs -o size=${room}k tmpfs "$mnt" 2>/dev/null \
            || { echo "SKIPPED: cannot mount a tmpfs (needs root) to fill a disk"; exit 77; }
        trap 'cd / && umount "$mnt" 2>/dev/null' EXIT
        cp -r . "$mnt/case" || fail "copy to tmpfs"
        cd "$mnt/case" || fail "cd tmpfs"
        setEntry system/controlDict startFrom latestTime
        setEntry system/controlDict endTime 0.05
        timed "$runDir/restartDamaged-diskFull$np.log" $np
        stopsQuickly "$np rank(s), disk full" "$runDir/restartDamaged-diskFull$np.log" \
            "The write of t = .* failed"
        grep -q "disk is full" "$runDir/restartDamaged-diskFull$np.log" \
            || fail "the message does not say the disk is full"
        md5sum -c --quiet "$runDir/restartDamaged-before$np.md5" \
            || fail "$np rank(s): the full disk changed earlier write times"
        echo "$np rank(s): 0.01 and 0.02 unchanged after the failed write"
        mount -o remount,size=64m "$mnt" || fail "remount"
        timed log.interDemFoam.3 $np -restartFromLastComplete
        [ "$rc" = 0 ] || fail "$np rank(s): -restartFromLastComplete after the full disk failed (log.interDemFoam.3)"
        sameEnd $np "$PWD" "$ref"
        cd "$runDir" && umount "$mnt" && trap - EXIT
        ;;
    esac
done
pass "damaged restart ($mode): stops in seconds with a clear message, restarts from the last complete time, serial and on 2 ranks"
