#!/bin/bash
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#------------------------------------------------------------------------------
# Pictures: a short coupled run (tests/cases/particleBed: 20 particles of
# 4 mm in water, 3 steps) rendered with ParaView (bin/pvrender, the
# singleParticleSettling tutorial's renderSettling.py, one frame, whole
# domain). The picture must exist, not be blank, and show the particles:
# more than 2 % of its pixels in the particle colour map's warm tones (water
# is blue, background white). Negative control: the same render with the
# Lagrangian cloud removed from the output must fail that check.
# Skipped (77) when ParaView or Xvfb is missing.
# Measured: 11 % of the pixels in the particles' colours; the negative
# control 0 %.
#------------------------------------------------------------------------------
. "${0%/*}/caseFunctions.sh"

name=render
rm -rf "$runDir/$name"; mkdir -p "$runDir"
cp -r "$testsDir/cases/particleBed" "$runDir/$name"
cd "$runDir/$name" || fail "no run dir"
script="$INTERDEMFOAM_TUTORIALS/singleParticleSettling/renderSettling.py"

# Share of the picture's pixels in the particles' warm tones (red clearly
# above blue), e.g. 0.031; fails (exit 1) on a missing, empty or unreadable
# picture, and on a blank one (a single colour)
particlePixels()
{
    /usr/bin/python3 - "$1" <<'PY'
import os, sys
import matplotlib.image as mpimg
f = sys.argv[1]
if not os.path.isfile(f) or os.path.getsize(f) == 0:
    sys.exit('no picture %s (or empty)' % f)
img = mpimg.imread(f)[..., :3]
if img.max() - img.min() < 0.05:
    sys.exit('blank picture %s' % f)
r, g, b = img[..., 0], img[..., 1], img[..., 2]
warm = (r - b > 0.12) & (r > 0.2)
print('%.4f' % warm.mean())
PY
}

# the check itself: picture $1 shows particles
showsParticles()
{
    local share
    share=$(particlePixels "$1") || return 1
    echo "$1: particle pixels $share of the picture"
    awk -v s="$share" 'BEGIN { exit !(s > 0.02) }'
}

# the check must fail on a missing and on an empty picture
showsParticles missing.png 2> /dev/null && fail "check passed on a missing picture"
: > empty.png
showsParticles empty.png 2> /dev/null && fail "check passed on an empty picture"

runApplication blockMesh || fail "blockMesh"
runApplication setFields || fail "setFields"          # water everywhere
runApplication interDemFoam || fail "interDemFoam (log.interDemFoam)"
[ -d 0.0003/lagrangian/demParticles ] || fail "no 0.0003/lagrangian/demParticles written"

start=$(date +%s.%N)
pvrender "$script" . --window 0 --time latest --raw --out frame.png > log.render 2>&1
rc=$?
[ $rc -eq 3 ] && { cat log.render; echo "SKIP: no ParaView/Xvfb"; exit 77; }
[ $rc -eq 0 ] || { tail -20 log.render; fail "renderSettling.py failed (log.render)"; }
took=$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN { printf "%.1f", e - s }')
showsParticles frame.png || fail "frame.png does not show the particles"

# negative control: no cloud in the output -> the check must fail
rm -rf 0.0003/lagrangian
pvrender "$script" . --window 0 --time latest --raw --out noParticles.png \
    > log.renderNoParticles 2>&1 || fail "render without particles failed (log.renderNoParticles)"
if showsParticles noParticles.png
then
    fail "the check passes without particles: it cannot tell"
fi
pass "frame.png shows the particles (rendered in $took s); without the cloud the check fails"
