#!/bin/bash
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#------------------------------------------------------------------------------
# Step-to-step scatter of the fluid force on the landslide dam's grains
# during seepage: scenario C1, small scale, the first 10 s (before any
# overtopping), with the current scheme and with the former one (d(eps)/dt
# from two eps snapshots, drag held over the coupling interval). The total
# fluid force on all grains (LIGGGHTS's couple/cfd/force/implicit total,
# every coupling step) is compared with the grains' buoyant weight:
# mean |change between coupling steps| and standard deviation over 5-10 s.
#   ./flagshipSeepage.sh        (about 5 min on one core: two runs)
# Results: runs/seepage-<scheme>/seepage.summary
#------------------------------------------------------------------------------
cd "${0%/*}" || exit 1
. ../../etc/bashrc || exit 1
runs="$PWD/runs"
mkdir -p "$runs"
for scheme in current former
do
    c="$runs/seepage-$scheme"
    rm -rf "$c"; cp -r "$INTERDEMFOAM_TUTORIALS/landslideDamBreach" "$c"
    (
        cd "$c" || exit 1
        ./Allclean > /dev/null 2>&1
        cat >> DEM/in.dam <<'DEMEOF'

# benchmark: total fluid force on the grains, every coupling step
variable        tq  equal time
variable        fqx equal f_cfd2[1]
variable        fqz equal f_cfd2[3]
variable        mq  equal mass(all)
fix             fluidForcePrint all print 10 "${tq} ${fqx} ${fqz} ${mq}" file fluidForce.dat screen no title "# t Fx Fz mass"
DEMEOF
        if [ "$scheme" = former ]
        then
            foamDictionary -entry demDrag -set explicit constant/couplingProperties > /dev/null
            foamDictionary -entry PIMPLE.voidFractionRate -set snapshot system/fvSolution > /dev/null
        fi
        ./Allrun -scenario C1 -endTime 10 > log.Allrun 2>&1
        /usr/bin/python3 - <<'PYEOF' | tee seepage.summary
import glob, math
import numpy as np
f = glob.glob('C1.small/fluidForce.dat') + glob.glob('fluidForce.dat')
d = np.loadtxt(f[0], comments='#')
t, fx, fz, m = d[:, 0], d[:, 1], d[:, 2], d[:, 3]
keep = t >= 5
# buoyant weight of the grains (2650 kg/m3 in water)
W = m[keep].mean()*9.81*(2650 - 1000)/2650
F = np.hypot(fx[keep], fz[keep])
print('grains_buoyant_weight_N %.4g' % W)
print('mean_force_over_W %.4g' % (F.mean()/W))
print('std_force_over_W %.4g' % (F.std()/W))
print('mean_step_change_over_W %.4g' % (np.abs(np.diff(F)).mean()/W))
PYEOF
    )
done
