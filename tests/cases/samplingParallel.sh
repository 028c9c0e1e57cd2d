#!/bin/bash
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#------------------------------------------------------------------------------
# The fluid velocity at the particle's centre (fluidVelocity cellPoint) and
# the turbulent fluctuations (velocityFluctuation) on 2 ranks give what they
# give on one. Case tests/cases/particleBed: 20 cell-sized particles
# (virtual spheres of 4 d) falling through water for 60 coupling steps,
# across the METIS boundary, with intensity 0.5 and eddies of 1 ms (six
# eddies in the run). On 2 ranks only the host rank interpolates at the
# centre and the others add zero, so a particle whose cells straddle the
# boundary must see the same velocity as in the serial run; every rank
# draws the same u' (a hash of the particle id, the eddy and the combined
# velocity).
#
# Compared at the end (t = 0.006 s), each particle matched by its id: the
# fluid force F and the velocity U the solver writes for it, and the DEM's
# positions and velocities. Serial and parallel runs differ by the linear
# solvers' order of sums, which the 60 steps carry into the flow: the
# plain run (the default voidFractionAverage, no fluctuations) measures
# that spread (measured 9.7e-10 of the largest F), and the cellPoint +
# fluctuation run must stay within 1e-7 of each quantity's largest value
# (measured 1.1e-9). A rank adding its share of the centre
# value too (each straddling particle seeing up to twice the velocity)
# or a rank drawing other u' gives differences of order one.
# Negative control: the comparison must fail on F of one run against F of
# a run with another seed (measured 5.5e-2).
# The velocity at the particle's top (fluidVelocity grainTop, reconstructed
# in the host cell from its gradient, host rank only) likewise: 2 ranks
# within 1e-7 of 1 rank, and its F differs from the default run's by more
# than 1e-4 of the largest F (the option takes effect). Control, run by
# hand: a build in which a rank that does not host a particle adds its own
# average instead of zero differs by 3.9e-3 in F and fails.
# The rough-bed log law in the host cell (fluidVelocity bedSurfaceLogLaw:
# the cells below and above the host across the METIS boundary, host rank
# only) likewise: 2 ranks within 1e-7 of 1 rank, and its F differs from the
# default run's by more than 1e-4 of the largest F.
#------------------------------------------------------------------------------
. "${0%/*}/caseFunctions.sh"

src="$testsDir/cases/particleBed"
name=samplingParallel
rm -rf "$runDir/$name"; mkdir -p "$runDir/$name"; cd "$runDir/$name" || fail "no run dir"
endTime=0.006
tolerance=1e-7

runCase()  # <name> <ranks> <extra couplingProperties lines>
{
    local d="$1" n="$2" extra="$3"
    cp -r "$src" "$d"
    (
        cd "$d" || exit 1
        printf '%s\n' "$extra" >> constant/couplingProperties
        fallingBed $endTime
        runApplication blockMesh || exit 1
        runApplication setFields || exit 1
        if [ "$n" -gt 1 ]
        then
            setEntry system/decomposeParDict numberOfSubdomains $n
            runApplication decomposePar || exit 1
            mpirun --oversubscribe -np $n interDemFoam -parallel \
                > log.interDemFoam 2>&1 < /dev/null || exit 1
            runApplication reconstructPar -latestTime || exit 1
        else
            interDemFoam > log.interDemFoam 2>&1 < /dev/null || exit 1
        fi
        grep -q "^End" log.interDemFoam
    ) || fail "$d did not run (see $runDir/$name/$d/log.*)"
    awk '/^ITEM: ATOMS/ { f = 1; next } f' "$d/post/bed.600.dump" > "$d.atoms"
    [ "$(wc -l < "$d.atoms")" -eq 20 ] || fail "$d: no DEM dump of 20 particles"
}

# largest |a - b| / largest |a| over the particles (matched by id) of the
# Lagrangian fields F and U, and over the DEM dumps: "<F> <U> <DEM>";
# fails on a missing field, a count other than 20 or ids that differ
compareRuns()
{
    /usr/bin/python3 - "$1" "$2" "$endTime" <<'PYEOF'
import re, sys
a, b, t = sys.argv[1:4]
def values(f):
    s = open(f).read()
    s = s[s.index('FoamFile'):]
    s = s[s.index('}') + 1:]
    m = re.search(r'(\d+)\s*\((.*)\)', s, re.S)
    if not m:
        sys.exit('no list in ' + f)
    return int(m.group(1)), m.group(2)
def field(case, name):
    n, body = values('%s/%s/lagrangian/demParticles/%s' % (case, t, name))
    if name == 'id':
        v = [int(x) for x in body.split()]
    else:
        v = [tuple(float(x) for x in g.split()) for g in re.findall(r'\(([^()]*)\)', body)]
    if n != 20 or len(v) != 20:
        sys.exit('%s: %s has %d of 20 particles' % (case, name, len(v)))
    return v
def byId(case, name):
    return dict(zip(field(case, 'id'), field(case, name)))
out = []
for name in ('F', 'U'):
    fa, fb = byId(a, name), byId(b, name)
    if sorted(fa) != sorted(fb):
        sys.exit('%s: the particle ids differ between %s and %s' % (name, a, b))
    scale = max(abs(x) for v in fa.values() for x in v) or 1.0
    out.append(max(abs(x - y) for k in fa for x, y in zip(fa[k], fb[k]))/scale)
da = [[float(x) for x in l.split()] for l in open(a + '.atoms')]
db = [[float(x) for x in l.split()] for l in open(b + '.atoms')]
if len(da) != 20 or len(db) != 20 or [r[0] for r in da] != [r[0] for r in db]:
    sys.exit('the DEM dumps differ in their particles')
for cols in (slice(1, 4), slice(4, 7)):
    scale = max(abs(x) for r in da for x in r[cols]) or 1.0
    out.append(max(abs(x - y) for ra, rb in zip(da, db) for x, y in zip(ra[cols], rb[cols]))/scale)
print(' '.join('%.3e' % x for x in out))
PYEOF
}

options="fluidVelocity     cellPoint;
velocityFluctuation { intensity 0.5; eddyTime 0.001; }"
runCase plain-1 1 ""
runCase plain-2 2 ""
runCase sampled-1 1 "$options"
runCase sampled-2 2 "$options"
runCase seed-2 2 "fluidVelocity     cellPoint;
velocityFluctuation { intensity 0.5; eddyTime 0.001; seed 5; }"
runCase top-1 1 "fluidVelocity     grainTop;"
runCase top-2 2 "fluidVelocity     grainTop;"
logLaw="fluidVelocity     bedSurfaceLogLaw;
bedSurfaceLogLawCoeffs { roughness 2.9; bedSolidFraction 0.56; }"
runCase log-1 1 "$logLaw"
runCase log-2 2 "$logLaw"
grep -q "fluidVelocity bedSurfaceLogLaw" log-2/log.interDemFoam \
    || fail "the 2-rank run did not report fluidVelocity bedSurfaceLogLaw"
grep -q "fluidVelocity grainTop" top-2/log.interDemFoam \
    || fail "the 2-rank run did not report fluidVelocity grainTop"
grep -q "fluidVelocity cellPoint" sampled-2/log.interDemFoam \
    && grep -q "Turbulent velocity fluctuations seen by the particles" sampled-2/log.interDemFoam \
    || fail "the 2-rank run did not report fluidVelocity cellPoint and its fluctuations"

plain=$(compareRuns plain-1 plain-2) || fail "cannot compare the default runs"
sampled=$(compareRuns sampled-1 sampled-2) || fail "cannot compare the cellPoint + fluctuation runs"
control=$(compareRuns sampled-2 seed-2) || fail "cannot compare the seeds"
top=$(compareRuns top-1 top-2) || fail "cannot compare the grainTop runs"
topEffect=$(compareRuns plain-1 top-1) || fail "cannot compare grainTop with the default"
logRanks=$(compareRuns log-1 log-2) || fail "cannot compare the bedSurfaceLogLaw runs"
logEffect=$(compareRuns plain-1 log-1) || fail "cannot compare bedSurfaceLogLaw with the default"
echo "1 rank against 2, largest difference / largest value (F, U, DEM position, DEM velocity):"
echo "  default:                   $plain"
echo "  cellPoint + fluctuations:  $sampled"
echo "  grainTop:                  $top"
echo "  bedSurfaceLogLaw:          $logRanks"
echo "  another seed (control):    $control"
echo "  grainTop against the default, 1 rank: $topEffect"
echo "  bedSurfaceLogLaw against the default, 1 rank: $logEffect"
labels="F U position velocity"
set -- $sampled
for l in $labels
do
    check "cellPoint + fluctuations, 1 against 2 ranks: $l" "$1" "v <= $tolerance" \
        "$l differs between 1 and 2 ranks by $1 of its largest value (> $tolerance)"
    shift
done
set -- $top
for l in $labels
do
    check "grainTop, 1 against 2 ranks: $l" "$1" "v <= $tolerance" \
        "$l differs between 1 and 2 ranks by $1 of its largest value (> $tolerance)"
    shift
done
set -- $logRanks
for l in $labels
do
    check "bedSurfaceLogLaw, 1 against 2 ranks: $l" "$1" "v <= $tolerance" \
        "$l differs between 1 and 2 ranks by $1 of its largest value (> $tolerance)"
    shift
done
set -- $logEffect
check "bedSurfaceLogLaw against the default: F" "$1" "v > 1e-4" \
    "bedSurfaceLogLaw gives the default's F within $1 of the largest: the option has no effect"
set -- $topEffect
check "grainTop against the default: F" "$1" "v > 1e-4" \
    "grainTop gives the default's F within $1 of the largest: the option has no effect"
set -- $control
if awk -v v="$1" -v t="$tolerance" 'BEGIN { exit !(v <= t) }'
then
    fail "negative control: F with another seed agrees within $tolerance ($1): the check cannot fail"
fi
echo "negative control: F with another seed differs by $1 (> $tolerance): the check fails on it"
pass "cellPoint + fluctuations, grainTop and bedSurfaceLogLaw on 2 ranks = 1 rank within $tolerance (F, U, DEM: $sampled, $top and $logRanks; default runs: $plain)"
