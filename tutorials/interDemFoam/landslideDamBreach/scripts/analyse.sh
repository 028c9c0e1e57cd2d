# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
# The analysis (sourced by Allrun; the analysis itself is the damBreach/
# package, its command line damBreachAnalysis.py): one run's tables, plots
# and pictures (analyseCase), several runs side by side and, with all
# eight, the matrix, the findings, Figs. 8-11 and the Shields numbers
# (analyseTogether).

# The case $dir: its tables and plots, then its pictures (ParaView, never
# fatal)
analyseCase()
{
# Analysis and plots
/usr/bin/python3 damBreachAnalysis.py "$dir" 2>&1 | tee "$dir"/log.damBreachAnalysis
[ "${PIPESTATUS[0]}" -eq 0 ] \
    || { echo "Allrun: analysis failed: see $dir/log.damBreachAnalysis"; return 1; }
echo "Allrun: results in $dir/damBreach.png, profiles.png, damBreach.dat, damBreach.summary"

# Pictures (ParaView): breach.png (six phases, seed Fig. 6), breach.gif;
# skipped with a message when ParaView is missing, never fatal
if command -v pvrender > /dev/null 2>&1
then
    pvrender renderBreach.py "$dir" > "$dir"/log.renderBreach 2>&1
    case $? in
        0) echo "Allrun: pictures in $dir/breach.png, breach.gif" ;;
        3) head -n 1 "$dir"/log.renderBreach ;;
        *) echo "Allrun: renderBreach.py failed (the run is fine): see $dir/log.renderBreach" ;;
    esac
else
    echo "Allrun: no pvrender on PATH (. etc/bashrc): no pictures"
fi
}

# The runs $dirs of the scenarios $scenarios side by side
# (compare.<scale>[.<tag>].png/.txt); with all eight the matrix, the
# findings, Figs. 8-11 and the Shields numbers in results/ (a variant's in
# results/<tag>/; with -sample b both samples' matrices and their findings)
# samplesMatch <first sample's case> <second's>: the second's maxCo and DEM
# step are 0.9 x the first's (else the two were run with other options)
samplesMatch()
{
local coA coB dtA dtB
coA=$(foamDictionary -entry maxCo -value "$1"/system/controlDict)
coB=$(foamDictionary -entry maxCo -value "$2"/system/controlDict)
dtA=$(sed -n 's/^variable *demDt *index *//p' "$1"/DEM/in.case)
dtB=$(sed -n 's/^variable *demDt *index *//p' "$2"/DEM/in.case)
/usr/bin/python3 -c "import sys; a, b, c, d = map(float, sys.argv[1:]); sys.exit(0 if abs(b - 0.9*a) <= 1e-3*a and abs(d - 0.9*c) <= 1e-3*c else 1)" \
    "$coA" "$coB" "$dtA" "$dtB" 2>/dev/null \
    || { echo "Allrun: -sample b: $2 has maxCo $coB and DEM step $dtB s, not 0.9 x $1's $coA and $dtA s: run both samples with the same options"; return 1; }
}

analyseTogether()
{
/usr/bin/python3 damBreachAnalysis.py compare compare.$scale${tag:+.$tag} $dirs \
    || { echo "Allrun: comparison failed"; exit 1; }
echo "Allrun: side by side in compare.$scale${tag:+.$tag}.png, compare.$scale${tag:+.$tag}.txt"
if [ "$(echo $scenarios | tr ' ' '\n' | sort | tr '\n' ' ')" = "C1 C2 C3 C4 F1 F2 F3 F4 " ]
then
    # a variant's matrix in results/<tag>/, beside the tutorial's own; the
    # second sample (-sample b) beside the first, the findings on both
    resultsDir=results${firstTag:+/$firstTag}
    mkdir -p "$resultsDir"
    if [ "$sample" = b ]
    then
        local sc first second firstDirs=""
        for sc in $scenarios
        do
            first=$sc.$scale${firstTag:+.$firstTag} second=$sc.$scale.$tag
            firstDirs="$firstDirs $first"
            [ -f "$first/damBreach.summary" ] \
                || { echo "Allrun: -sample b: the first sample's $first has not run (./Allrun -scenario all${firstTag:+ -tag $firstTag} first)"; exit 1; }
            # the two samples of a scenario: the same run, every step 0.9 x
            samplesMatch "$first" "$second" || exit 1
        done
        /usr/bin/python3 damBreachAnalysis.py matrix "$resultsDir" $scale \
            $firstDirs --second $dirs \
            || { echo "Allrun: the matrix analysis failed"; exit 1; }
    else
        /usr/bin/python3 damBreachAnalysis.py matrix "$resultsDir" $scale $dirs \
            || { echo "Allrun: the matrix analysis failed"; exit 1; }
    fi
    # where the runs sit on the bedload chart (docs/erosion.md; the first
    # sample's)
    [ "$sample" = b ] || /usr/bin/python3 damBreachAnalysis.py shields "$resultsDir" $scale $dirs \
        || { echo "Allrun: the Shields analysis failed"; exit 1; }
fi
}
