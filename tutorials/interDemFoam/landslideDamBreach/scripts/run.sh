# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
# Running a case in pieces (sourced by Allrun): where a stopped run goes
# on (resumeCase, -resume), one piece (solvePiece) and the chain of pieces
# with the run-length rule (runPieces).

# -resume: where the case $dir's run stopped (damBreachResume.py; it
# removes what the interrupted piece wrote), in resumeState: "" (set the
# case up: not there yet, or no -resume), start, "from <time> <suffix>" or
# finished; the run's own settings (its Allrun.run) replace this command
# line's
resumeCase()
{
resumeState=""
if [ "$resume" = yes ] && [ -d "$dir" ]
then
    resumeState=$(/usr/bin/python3 damBreachResume.py "$dir") \
        || { echo "Allrun: -resume: cannot resume $dir (above)"; return 1; }
    if [ -f "$dir/Allrun.run" ]
    then
        # the run's own settings, as it was set up; the command line's
        # are not used (said when they differ)
        given="$untilEnded $endTime $maxEnd $nProcs $pieceLength"
        setting() { awk -v k="$1" '$1 == k {print $2}' "$dir/Allrun.run"; }
        untilEnded=$(setting untilEnded)
        endTime=$(setting firstEnd)
        maxEnd=$(setting maxEnd)
        nProcs=$(setting nProcs)
        pieceLength=$(setting pieceLength)
        [ "$given" = "$untilEnded $endTime $maxEnd $nProcs $pieceLength" ] \
            || echo "Allrun: -resume $dir: it runs with the settings it was set up with ($dir/Allrun.run: until ended $untilEnded, first piece to $endTime s, longest run $maxEnd s, $nProcs rank(s)), not with this command line's"
    fi
    echo "Allrun: -resume $dir: $resumeState"
elif [ "$resume" = yes ]
then
    echo "Allrun: -resume: no $dir yet: setting it up"
fi
}

# In the case: one piece of the run, to $end s, logged to
# log.interDemFoam.$suffix (no suffix: the first piece); complete when its
# log ends in End
solvePiece()
{
    echo "Running $dir: $material grains, inflow $inflowRate m3/s, to ${end} s"
    if [ "$nProcs" -gt 1 ]
    then
        runParallel ${suffix:+-s $suffix} interDemFoam || return 1
    else
        runApplication ${suffix:+-s $suffix} interDemFoam || return 1
    fi
    grep -q '^End' log.interDemFoam${suffix:+.$suffix} || return 1
    echo "$(( $(date +%s) - start ))" > wallTime.partial
}

# In the case: the run, a chain of pieces, from where resumeState says:
# the first to $endTime s, then pieces of $pieceLength s (each a restart
# from the last write) while the breach goes on (until ended), up to the
# longest run $maxEnd s; the wall time in wallTime
runPieces()
{
    # decomposed once (a case set up with -setupOnly is not yet)
    if [ "$nProcs" -gt 1 ] && [ ! -d processor0 ]
    then
        runApplication decomposePar || return 1
    fi
    # wall time so far: the pieces a stopped run completed (wallTime.partial;
    # none in a case just set up)
    elapsed=$(cat wallTime.partial 2> /dev/null)
    case "$elapsed" in
        ''|*[!0-9]*) elapsed=0 ;;
    esac
    start=$(( $(date +%s) - elapsed ))
    end=$endTime
    suffix=""
    runPiece=yes
    # (stopped in its first piece, "start": controlDict's endTime is
    # still the first piece's, changed only after a complete piece)
    case "$resumeState" in
        from*)
            set -- $resumeState
            end=$2
            suffix=${3#-}; suffix=${suffix#.}
            runPiece=no ;;
    esac
    while [ "$resumeState" != finished ]
    do
        if [ "$runPiece" = yes ]
        then
            solvePiece || return 1
        fi
        runPiece=yes
        grep -h "^Timing split" log.interDemFoam${suffix:+.$suffix}
        [ "$untilEnded" = yes ] || break
        # the breach has ended when, over the last 20 s, the dam height
        # changed by less than 5 mm and [E] by less than 0.02, or every
        # grain has left the flume (the rule's defaults, breach_state, which
        # the matrix applies too), or the run has reached the longest run
        # of its scale, $maxEnd s (the piece just run ended at $end s)
        /usr/bin/python3 ../damBreachAnalysis.py ended . --maxTime $maxEnd \
            --pieceEnd $end && break
        end=$(/usr/bin/python3 -c "print('%g' % ($end + $pieceLength))")
        foamDictionary -entry endTime -set "$end" system/controlDict > /dev/null
        suffix=to$end
    done
    [ "$resumeState" = finished ] || echo "$(( $(date +%s) - start ))" > wallTime
}
