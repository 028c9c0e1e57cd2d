#!/bin/bash
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#------------------------------------------------------------------------------
# Bad environment: ./Allwmake without network to the package registry, on an
# empty cache, must end with a clear message and a non-zero exit, and leave
# no half-unpacked OpenFOAM source tree behind. Needs root (unshare -n);
# skipped (77) otherwise.
# Reference: none, a behaviour (docs/reliability.md, row 30). Measured: the
# ERROR line and no half-built tree; no number.
#------------------------------------------------------------------------------
. "${0%/*}/caseFunctions.sh"

if [ "$(id -u)" != 0 ] || ! unshare -n true 2>/dev/null
then
    echo "SKIP: needs root and unshare -n"
    exit 77
fi

cache="$runDir/offlineCache"
rm -rf "$cache"; mkdir -p "$cache"
out="$runDir/allwmakeOffline.log"
# a clean environment: the project's own is not yet sourced on a new machine
if env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME="$HOME" \
    INTERDEMFOAM_CACHE="$cache" \
    unshare -n "$INTERDEMFOAM_DIR/Allwmake" > "$out" 2>&1 < /dev/null
then
    fail "Allwmake succeeded without network on an empty cache"
fi
cat "$out"
grep -q "Allwmake: ERROR: could not obtain Debian's openfoam source package" "$out" \
    || fail "no clear error message (see $out)"
grep -q "no network" "$out" || fail "message does not mention the network"
[ ! -e "$cache/OpenFOAM-v1912" ] || fail "half-built OpenFOAM-v1912 left in $cache"
rm -rf "$cache"
pass "offline Allwmake stops cleanly"
