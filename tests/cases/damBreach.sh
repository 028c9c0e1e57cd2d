#!/bin/bash
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
#   - tables, plots and the ParaView files are written.
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

value() { awk -v k="$1" 'index($0, k) == 1 { print $NF }' "$case"/damBreach.summary; }
H0=$(value 'initial dam height')
moved=$(value 'largest grain displacement')
over=$(value 'overtopping from t')
lost=$(value 'height lost after overtopping')
balance=$(value 'water balance error')

awk -v h="$H0" 'BEGIN { exit !(h >= 0.26 && h <= 0.32) }' \
    || fail "the poured dam is $H0 m high, not 0.3 m (0.26-0.32)"
awk -v d="$moved" 'BEGIN { exit !(d > 0.04) }' \
    || fail "no grain moved more than 40 mm (largest displacement $moved m)"
awk -v t="$over" 'BEGIN { exit !(t >= 0) }' \
    || fail "the lake never overtopped the crest"
awk -v l="$lost" 'BEGIN { exit !(l > 0.02) }' \
    || fail "the crest lost only ${lost:-nothing} m after overtopping (> 0.02 m expected)"
awk -v b="$balance" 'BEGIN { if (b < 0) b = -b; exit !(b < 1) }' \
    || fail "water balance off by $balance % of the inflow (1 % allowed)"

pass "dam ${H0} m, overtopped at ${over} s, crest lowered ${lost} m after," \
     "largest displacement ${moved} m, water balance ${balance} %"
