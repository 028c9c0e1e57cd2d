# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
"""The poured dam: its shape (DEM/in.buildDam) and the check of a build's
grading (damBreachAnalysis.py grading, which Allrun runs after each
build): the dam a build poured (BUILD/dam.grains) against its grading
(BUILD/DEM/in.material.<material>), its solid fraction and the DEM step
against the Rayleigh time of the smallest grain."""
import os
import sys

import numpy as np

from .dumps import case_variables, dem_step

GRADING_TOLERANCE = 0.03   # largest |measured - target| mass fraction
RAYLEIGH_LIMIT = 0.2       # largest DEM step / Rayleigh time of the smallest

# The dam (DEM/in.buildDam): upstream toe at x = 3 m, height and crest width
# 0.3 m, slopes 35 and 25 degrees to the bed
DAM_TOE, DAM_HEIGHT, DAM_CREST = 3.0, 0.3, 0.3
DAM_SLOPES = (35.0, 25.0)
# the core of the dam, where the solid fraction is sampled: 0.3 m along the
# bed under the crest, 0.04-0.24 m above the bed (away from every surface)
CORE_X, CORE_Z = (3.45, 3.75), (0.04, 0.24)


def dam_area():
    """The dam's cross-section, m2."""
    up, down = (DAM_HEIGHT/np.tan(np.radians(a)) for a in DAM_SLOPES)
    return DAM_HEIGHT*(DAM_CREST + 0.5*(up + down))


def dam_downstream_toe():
    """x of the poured dam's downstream toe, m."""
    up, down = (DAM_HEIGHT/np.tan(np.radians(a)) for a in DAM_SLOPES)
    return DAM_TOE + up + DAM_CREST + down


def liggghts_lines(path):
    """The commands of a LIGGGHTS input file, comments and continuations
    (&) joined, as lists of words."""
    text = open(path).read().replace('&\n', ' ')
    return [l.split('#')[0].split() for l in text.splitlines()
            if l.split('#')[0].strip()]


def read_grading(path):
    """Diameters (m), target mass fractions and densities of the size classes
    of an in.material file: the particle templates and the weights of its
    fix particledistribution/discrete (mass-based unless /numberbased)."""
    templates, dist = {}, None
    for w in liggghts_lines(path):
        if len(w) > 3 and w[0] == 'fix' and w[3] == 'particletemplate/sphere':
            d = dict(zip(w[4:], w[5:]))
            i = w.index('radius')
            if w[i + 1] != 'constant' or w[w.index('density') + 1] != 'constant':
                sys.exit('damBreachAnalysis: %s: template %s: only constant '
                         'radius and density are checked' % (path, w[1]))
            templates[w[1]] = (2*float(w[i + 2]),
                               float(w[w.index('density') + 2]))
        elif len(w) > 3 and w[0] == 'fix' \
                and w[3].startswith('particledistribution/discrete'):
            n = int(w[5])
            dist = (w[3], [(w[6 + 2*k], float(w[7 + 2*k])) for k in range(n)])
    if dist is None or not templates:
        sys.exit('damBreachAnalysis: no particle templates or fix '
                 'particledistribution/discrete in %s' % path)
    style, pairs = dist
    d = np.array([templates[t][0] for t, _ in pairs])
    rho = np.array([templates[t][1] for t, _ in pairs])
    weight = np.array([wt for _, wt in pairs])
    if style.endswith('/numberbased'):
        weight = weight*rho*d**3
    return d, weight/weight.sum(), rho


def read_grains(path):
    """The grains of a LIGGGHTS custom dump: dict of columns."""
    lines = open(path).read().splitlines()
    i = next((k for k, l in enumerate(lines) if l.startswith('ITEM: ATOMS')),
             None)
    if i is None:
        sys.exit('damBreachAnalysis: %s is not a LIGGGHTS dump' % path)
    names = lines[i].split()[2:]
    rows = [l.split() for l in lines[i + 1:] if l.strip()]
    a = np.array(rows, dtype=float).reshape(-1, len(names))
    return {n: a[:, k] for k, n in enumerate(names)}


def core_solid_fraction(g, width, periodic, h=0.002):
    """Fraction of the core box (CORE_X x width x CORE_Z) inside grains,
    sampled on a grid of spacing h (periodic images across y)."""
    xs = np.arange(CORE_X[0] + h/2, CORE_X[1], h)
    ys = np.arange(h/2, width, h)
    zs = np.arange(CORE_Z[0] + h/2, CORE_Z[1], h)
    occ = np.zeros((len(xs), len(ys), len(zs)), bool)
    shifts = (-width, 0.0, width) if periodic else (0.0,)
    for r, x, y, z in zip(g['radius'], g['x'], g['y'], g['z']):
        if x + r < CORE_X[0] or x - r > CORE_X[1] \
                or z + r < CORE_Z[0] or z - r > CORE_Z[1]:
            continue
        i0, i1 = np.searchsorted(xs, [x - r, x + r])
        k0, k1 = np.searchsorted(zs, [z - r, z + r])
        for s in shifts:
            j0, j1 = np.searchsorted(ys, [y + s - r, y + s + r])
            if j1 <= j0:
                continue
            d2 = (xs[i0:i1, None, None] - x)**2 \
                + (ys[None, j0:j1, None] - y - s)**2 \
                + (zs[None, None, k0:k1] - z)**2
            occ[i0:i1, j0:j1, k0:k1] |= d2 < r*r
    return occ.mean()


def rayleigh_time(build, r, rho):
    """T_R = pi r sqrt(rho/G)/(0.1631 nu + 0.8766) with the particles' E and
    nu of DEM/in.common (as interDemFoam checks it), s."""
    E = nu = None
    for w in liggghts_lines(os.path.join(build, 'DEM', 'in.common')):
        if len(w) > 5 and w[0] == 'fix' and w[3] == 'property/global':
            if w[4] == 'youngsModulus':
                E = float(w[6])
            elif w[4] == 'poissonsRatio':
                nu = float(w[6])
    if E is None or nu is None:
        sys.exit('damBreachAnalysis: no youngsModulus/poissonsRatio in '
                 '%s/DEM/in.common' % build)
    G = E/(2*(1 + nu))
    return np.pi*r*np.sqrt(rho/G)/(0.1631*nu + 0.8766)


def measure_dam(build, grains=None):
    """The dam poured in BUILD measured against its grading: a dict of the
    material, DEM step, classes (d, target, measured, count), stray grains,
    solid fractions, the smallest class's Rayleigh time and the pour's
    times (DEM/in.buildDam)."""
    v = case_variables(build)
    material = v.get('material')
    if not material:
        sys.exit('damBreachAnalysis: no material in %s/DEM/in.case' % build)
    dt = dem_step(build)
    width = float(v['width'])
    periodic = v.get('yBoundary', 'p') == 'p'
    d, target, rho = read_grading(
        os.path.join(build, 'DEM', 'in.material.' + material))
    g = read_grains(grains or os.path.join(build, 'dam.grains'))
    n = len(g['radius'])
    if n == 0:
        sys.exit('damBreachAnalysis: no grains in the dam of %s' % build)
    # each grain to its class: the template diameter it has (to 1e-6)
    dg = 2*g['radius']
    k = np.argmin(np.abs(dg[:, None] - d[None, :]), axis=1)
    stray = np.abs(dg - d[k]) > 1e-6*d[k]
    mass = g['mass']
    count = np.bincount(k[~stray], minlength=len(d))
    measured = np.bincount(k[~stray], weights=mass[~stray],
                           minlength=len(d))/mass.sum()
    volume = np.sum(4/3*np.pi*g['radius']**3)
    bulk = volume/(dam_area()*width)
    core = core_solid_fraction(g, width, periodic)
    i = np.argmin(d)
    tR = rayleigh_time(build, d[i]/2, rho[i])
    times = {}
    for w in liggghts_lines(os.path.join(build, 'DEM', 'in.buildDam')):
        if len(w) >= 4 and w[0] == 'variable' and w[1].endswith('Time'):
            times[w[1]] = w[3]
    return dict(material=material, dt=dt, width=width, d=d, target=target,
                measured=measured, count=count, stray=stray, dg=dg,
                mass=mass, n=n, bulk=bulk, core=core, smallest=i, tR=tR,
                times=times)


def grading_rows(m):
    """The dam's lines of the grading file: its summary ('# X: ...') and
    one row per class."""
    d, target, measured, count = m['d'], m['target'], m['measured'], m['count']
    dt, tR, i, times = m['dt'], m['tR'], m['smallest'], m['times']
    rows = ['%-6s %.4f %.4f %.4f %d' % (m['material'], d[c], target[c],
                                        measured[c], count[c])
            for c in range(len(d))]
    summary = ('# %s: %d grains, %.2f kg; solid fraction %.3f (grain volume '
               '/ trapezoid %.4f m3), %.3f (core); DEM step %g s = %.1f %% of '
               'the Rayleigh time %.3g s of the %g mm grains; pour %s s, '
               'settle %s + %s s'
               % (m['material'], m['n'], m['mass'].sum(), m['bulk'],
                  dam_area()*m['width'], m['core'], dt, 100*dt/tR, tR,
                  1000*d[i], times.get('pourTime', '?'),
                  times.get('settleTime', '?'), times.get('restTime', '?')))
    return summary, rows


def print_grading(build, m, summary):
    print('Grading of the dam, material %s (%s):' % (m['material'], build))
    print('  %-6s %-7s %-7s %-8s %s' % ('', 'd [mm]', 'target', 'measured',
                                        'count'))
    for c in range(len(m['d'])):
        print('  %-6s %-7g %-7.3f %-8.3f %d' % (m['material'], 1000*m['d'][c],
                                                m['target'][c],
                                                m['measured'][c],
                                                m['count'][c]))
    print(summary[2:])


def grading_problems(m):
    """Why the dam is not its grading (empty when it is)."""
    d, target, measured, count = m['d'], m['target'], m['measured'], m['count']
    stray, dg, dt, tR, i = m['stray'], m['dg'], m['dt'], m['tR'], m['smallest']
    problems = []
    for c in range(len(d)):
        if abs(measured[c] - target[c]) > GRADING_TOLERANCE + 1e-12:
            problems.append('d = %g mm: %.3f of the mass, target %.3f '
                            '(+-%g allowed), %d grains'
                            % (1000*d[c], measured[c], target[c],
                               GRADING_TOLERANCE, count[c]))
    if stray.any():
        problems.append('%d grains of diameters %s mm match no class'
                        % (stray.sum(), ', '.join('%g' % (1000*x) for x in
                                                   sorted(set(dg[stray])))))
    if dt > RAYLEIGH_LIMIT*tR:
        problems.append('DEM step %g s is %.1f %% of the Rayleigh time %.3g s '
                        'of the %g mm grains (at most %g %%)'
                        % (dt, 100*dt/tR, tR, 1000*d[i], 100*RAYLEIGH_LIMIT))
    return problems


def write_grading(out, scale, material, lines):
    """The grading file OUT with this material's lines; the rows of the
    other materials in it are kept."""
    # the other materials' summaries ('# X: ...') and rows ('X d ...')
    other = {}
    if os.path.isfile(out):
        for line in open(out).read().splitlines():
            w = line.split()
            if len(w) > 1 and w[0] == '#' and w[1].endswith(':'):
                m = w[1][:-1]
            elif w and w[0] != '#' and not w[0].startswith('#'):
                m = w[0]
            else:
                continue
            if m != material:
                other.setdefault(m, []).append(line)
    other[material] = lines
    with open(out, 'w') as f:
        f.write('# The grading of the poured dams%s (written by '
                'damBreachAnalysis.py grading after each build)\n'
                % (', %s scale' % scale if scale else ''))
        f.write('# targets from DEM/in.material.<material>; a class passes '
                'within +-%g of its mass fraction\n' % GRADING_TOLERANCE)
        f.write('# material d_m target_mass_fraction '
                'measured_mass_fraction count\n')
        for m in sorted(other):
            f.write('\n'.join(other[m]) + '\n')
    print('Grading written to %s' % out)


def grading(build, out=None, grains=None, scale=None):
    """Check the grading of the dam poured in BUILD; True when it passes."""
    m = measure_dam(build, grains)
    summary, rows = grading_rows(m)
    print_grading(build, m, summary)
    problems = grading_problems(m)
    if out:
        write_grading(out, scale, m['material'], [summary] + rows)
    if problems:
        print('GRADING CHECK FAILED: the dam of material %s is not its '
              'grading:\n  %s' % (m['material'], '\n  '.join(problems)))
        return False
    print('Grading check passed: every class within %g of its target mass '
          'fraction' % GRADING_TOLERANCE)
    return True
