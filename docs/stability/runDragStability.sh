#!/bin/bash
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#------------------------------------------------------------------------------
# Stability of the drag in the DEM steps, explicit (the force held over the
# coupling interval dt) against implicit (K (u - v) in every DEM step,
# LIGGGHTS's couple/cfd/force/implicit), across the ratio of the coupling
# interval to the particle response time tau_p = rho_p d^2/(18 mu):
#   settling: one 0.2 mm glass particle (2500 kg/m3) released at rest in
#     water 20 mm below its surface (tau_p = 5.6 ms; terminal velocity
#     21 mm/s by eq. 19), cells 2 mm (10 d), dt = 5e-4 ... 5e-2 s
#     (dt/tau_p 0.09 ... 9), no surface tension (its capillary time-step
#     limit, 4 ms at these cells, would end the larger steps first),
#     DEM step 1e-5 s; 0.3 s. Measured: velocity over the last 0.1 s: mean
#     against eq. 19 and its standard deviation.
#   bed: benchmarks/quietBed (825 beads of 2 mm at rest under 8 mm/s, its
#     drag response time tau_b = m/K = 0.042 s from Rong's K at eps 0.41),
#     dt = 5e-4 ... 0.1 s (dt/tau_b 0.012 ... 2.4); plate pressure noise.
# Writes etc/sceneMaps/dragStability.dat (scene scheme dt ratio
# error_or_std blown; the map checkDemScene reads) and,
# with plotDragStability.py, dragStability.png. About 5 min on one core.
#------------------------------------------------------------------------------
cd "${0%/*}" || exit 1
. ../../etc/bashrc || exit 1
. "$WM_PROJECT_DIR/bin/tools/RunFunctions"
runs="$PWD/runs/dragStability"
mkdir -p "$runs"
out="$INTERDEMFOAM_DIR/etc/sceneMaps/dragStability.dat"
echo "# scene scheme dt_s dt_over_tau error_or_noise blown" > "$out"

tau=$(awk 'BEGIN { printf "%.6g", 2500*2e-4^2/(18*1e-3) }')
vt=$(/usr/bin/python3 -c "
import sys; sys.path.insert(0, '$INTERDEMFOAM_TUTORIALS/singleParticleSettling')
from plotSettling import terminal_velocity
print('%.6g' % terminal_velocity(2e-4, 2500.0))")
echo "settling: tau_p $tau s, eq. 19 terminal velocity $vt m/s"

for scheme in explicit implicit
do
    for dt in 5e-4 1e-3 2.5e-3 5e-3 1e-2 2e-2 5e-2
    do
        c="$runs/settling-$scheme-$dt"
        rm -rf "$c"; cp -r "$INTERDEMFOAM_TUTORIALS/singleParticleSettling" "$c"
        (
            cd "$c" || exit 1
            ./Allclean > /dev/null 2>&1
            sed -i 's/^Lx .*/Lx  0.01;/; s/^Ly .*/Ly  0.01;/; s/^Lz .*/Lz  0.06;/;
                    s/^nx .*/nx  5;/; s/^ny .*/ny  5;/; s/^nz .*/nz  30;/' system/blockMeshDict
            sed -i 's/(1 1 0.1)/(1 1 0.05)/' system/setFieldsDict
            sed -i 's/^region .*/region          box block 0 0.01 0 0.01 0 0.06 units box/;
                    s/^create_atoms .*/create_atoms    1 single 0.005 0.005 0.03 units box/;
                    s/^set .*/set             atom 1 diameter 0.0002 density 2500/' DEM/in.liggghts
            n=$(awk -v a="$dt" 'BEGIN { printf "%d", a/1e-5 + 0.5 }')
            sed -i "s/couple_every [0-9]*/couple_every $n/" DEM/in.settings
            foamDictionary -entry demDrag -set $scheme constant/couplingProperties > /dev/null
            # no surface tension: its capillary time-step limit (4 ms at 2 mm
            # cells) is not what this chart is about
            foamDictionary -entry sigma -set 0 constant/transportProperties > /dev/null
            foamDictionary -entry deltaT -set $dt system/controlDict > /dev/null
            foamDictionary -entry endTime -set 0.3 system/controlDict > /dev/null
            foamDictionary -entry writeInterval -set 0.3 system/controlDict > /dev/null
            restore0Dir > /dev/null
            blockMesh > log.blockMesh 2>&1
            setFields > log.setFields 2>&1
            timeout 600 interDemFoam > log.interDemFoam 2>&1
            /usr/bin/python3 - "$vt" <<'PYEOF'
import sys
import numpy as np
vt = float(sys.argv[1])
try:
    d = np.loadtxt('particleHistory.dat', comments='#', ndmin=2)
except Exception:
    d = np.zeros((0, 4))
if d.shape[0] < 10 or d[-1, 0] < 0.29 or not np.all(np.isfinite(d)):
    print('nan 1')
    sys.exit()
v = -d[d[:, 0] > 0.2, 2]
blown = int(np.abs(v).max() > 10*vt)
print('%.4g %d' % (max(abs(v.mean() - vt), v.std())/vt, blown))
PYEOF
        ) > "$c.result" 2>&1
        r=$(tail -n 1 "$c.result")
        echo "settling $scheme $dt $(awk -v a=$dt -v t=$tau 'BEGIN { printf "%.4g", a/t }') $r" | tee -a "$out"
    done
done

taub=0.042
for scheme in explicit implicit
do
    for dt in 5e-4 2e-3 1e-2 2.5e-2 5e-2 1e-1
    do
        end=$(awk -v a=$dt 'BEGIN { e = 100*a; if (e < 1) e = 1; printf "%g", e }')
        ../../benchmarks/quietBed/Allrun -runDir "$runs" -name bed-$scheme-$dt -U 0.008 \
            -endTime $end -deltaT $dt -demDrag $scheme > "$runs/bed-$scheme-$dt.log" 2>&1
        s=$(awk '$1 == "std_over_W" { print $2 }' "$runs/bed-$scheme-$dt/noise.summary" 2>/dev/null)
        blown=0
        [ -n "$s" ] && awk -v v="$s" 'BEGIN { exit !(v == v + 0 && v < 1) }' || { blown=1; s=nan; }
        echo "bed $scheme $dt $(awk -v a=$dt -v t=$taub 'BEGIN { printf "%.4g", a/t }') $s $blown" | tee -a "$out"
    done
done
/usr/bin/python3 plotDragStability.py
