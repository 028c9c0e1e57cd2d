# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
"""grains2data.py GRAINS DATA: a LIGGGHTS data file (atom_style granular:
id type diameter density x y z) from a built dam's grains dump
(landslideDamBreach's build.<dam>/dam.grains: id type radius mass x y z vx
vy vz), in the build's box. The grains start at rest. It carries a large
dam to another machine as text (F's full-scale restart is 52 MB, its
grains as text compress to a tenth); in.data2restart makes the restart
there."""
import math
import sys

if len(sys.argv) != 3:
    sys.exit('usage: grains2data.py GRAINS DATA')
src, dst = sys.argv[1], sys.argv[2]
lines = open(src).read().split('\n')
if len(lines) < 9 or lines[2] != 'ITEM: NUMBER OF ATOMS' \
        or not lines[8].startswith('ITEM: ATOMS id type radius mass x y z'):
    sys.exit('grains2data.py: %s is not a dam grains dump (ITEM: ATOMS id '
             'type radius mass x y z ...)' % src)
n = int(lines[3])
box = [lines[5 + i].split() for i in range(3)]
rows = [l.split() for l in lines[9:9 + n]]
if len(rows) != n or any(len(r) < 7 for r in rows):
    sys.exit('grains2data.py: %s holds fewer than its %d grains' % (src, n))
with open(dst, 'w') as f:
    f.write('dam grains from %s\n\n%d atoms\n2 atom types\n\n' % (src, n))
    for (lo, hi), ax in zip(box, 'xyz'):
        f.write('%s %s %slo %shi\n' % (lo, hi, ax, ax))
    f.write('\nAtoms\n\n')
    for r in rows:
        radius, mass = float(r[2]), float(r[3])
        density = mass/(4.0/3.0*math.pi*radius**3)
        f.write('%s %s %.9g %.9g %s %s %s\n'
                % (r[0], r[1], 2*radius, density, r[4], r[5], r[6]))
print('%s: %d grains' % (dst, n))
