#!/bin/bash
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#------------------------------------------------------------------------------
# Stability map of the void-fraction models: a settling cloud of 64 particles
# of d = 1 mm (4 x 4 x 4 on a 1.5 d lattice, solid fraction 15 % inside the
# cloud) released at rest in a 20 x 20 x 40 mm water column, 0.1 s, for each
# model and cell size dx/d. For each run: did it end, did anything go
# non-finite, the lowest eps reached, the time steps where the floor bit, the
# largest continuity error, the wall time. Writes etc/sceneMaps/stabilityMap.dat and
# stabilityMap.png (run from anywhere; the cases go to ./runs).
#   runStabilityMap.sh ["models"] ["ratios"]
#------------------------------------------------------------------------------
cd "${0%/*}" || exit 1
[ -n "$WM_PROJECT_DIR" ] || . ../../etc/bashrc || exit 1

models="${1:-centre divided virtualSphere diffusion}"
ratios="${2:-1 1.25 1.5 2 3 4}"
template=../../tutorials/interDemFoam/settlingMeshStudy/template
d=0.001

mkdir -p runs
for model in $models
do
    for r in $ratios
    do
        case="runs/$model-$r"
        if [ -f "$case/log.interDemFoam" ] && grep -q "^End\|FATAL" "$case/log.interDemFoam"
        then
            continue
        fi
        rm -rf "$case"
        cp -r "$template" "$case"
        set -- $(awk -v r="$r" -v d="$d" 'BEGIN {
            dx = r*d; nxy = int(0.02/dx + 0.5); nz = int(0.04/dx + 0.5)
            printf "%.6g %d %d %.6g %.6g\n", dx, nxy, nz, nxy*dx, nz*dx }')
        sed -i "s/NXY/$2/g; s/NZ/$3/g; s/LXY/$4/g; s/LZ/$5/g" "$case/system/blockMeshDict"
        sed -i "s/MODEL/$model/" "$case/constant/couplingProperties"
        sed -i "s/^endTime .*/endTime         0.1;/; s/^writeInterval .*/writeInterval   0.1;/" \
            "$case/system/controlDict"
        # the cloud: 4 x 4 x 4 particles, lattice 1.5 mm, centred, top 8 mm below the surface
        awk -v lxy="$4" -v lz="$5" '
            /^create_atoms/ {
                c = lxy/2; top = lz - 0.008
                printf "lattice         sc 0.0015 origin 0 0 0\n"
                printf "region          cloud block %.6g %.6g %.6g %.6g %.6g %.6g units box\n",
                    c - 0.0029, c + 0.0029, c - 0.0029, c + 0.0029, top - 0.0059, top
                printf "create_atoms    1 region cloud\n"
                next }
            /^set / { print "set             type 1 diameter 0.001 density 2500"; next }
            /^region          box/ { printf "region          box block 0 %s 0 %s 0 %s units box\n", lxy, lxy, lz; next }
            /^variable|^fix             history/ { next }
            { print }' "$case/DEM/in.liggghts" > "$case/DEM/in.tmp" \
            && mv "$case/DEM/in.tmp" "$case/DEM/in.liggghts"
        (
            cd "$case" || exit 1
            blockMesh > log.blockMesh 2>&1 || exit 1
            timeout 1800 interDemFoam > log.interDemFoam 2>&1
        )
        echo "$case: exit code $?"
    done
done

/usr/bin/python3 plotStabilityMap.py runs
