#!/bin/bash
# CTest fixture of the unit tests: tests/run/meshCase with its blockMesh
. "${0%/*}/../cases/caseFunctions.sh"
rm -rf "$runDir/meshCase"; mkdir -p "$runDir"
cp -r "$testsDir/unit/meshCase" "$runDir/meshCase"
blockMesh -case "$runDir/meshCase" > "$runDir/meshCase/log.blockMesh" 2>&1 \
    || fail "blockMesh of the unit-test mesh"
pass "unit-test mesh"
