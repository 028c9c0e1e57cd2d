#!/usr/bin/python3
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
"""Allrun's options checked, all in one place, and the run's settings
derived from them (scripts/options.sh calls this once):

    options.py NAME=VALUE...      (the option values as parseOptions left them)

Checks every option in turn; at the first that is wrong, prints one line
naming the option and what it takes and exits 1. Otherwise prints the
settings as shell assignments for Allrun to eval: the scale's geometry
(width, nCells, sides, yBoundary, sideWalls), the lake (lakeLevel), the
run's length (endTime, untilEnded, maxEnd, pieceLength), the scenarios
(all expanded) and the fluctuation's two numbers."""
import os
import re
import shlex
import sys

# per scale: the slice's width (m) and cells across, its sides, the lake
# at the start (m at the dam's toe; "": a dry bed), the first piece's end
# and the longest run of "until the breach has ended" (s)
SCALES = {
    'small': dict(width='0.1', nCells='2', sides='cyclic', yBoundary='p', sideWalls='0',
                  defaultLake='0.15', defaultEnd='60', maxEnd='300'),
    'full': dict(width='0.5', nCells='10', sides='wall', yBoundary='f', sideWalls='1',
                 defaultLake='', defaultEnd='200', maxEnd='600'),
}
PIECE_LENGTH = '20'     # s, the pieces after the first
# all eight: the long F runs early, so that two cores stay busy to the end
ALL = 'C2 F1 F2 F3 F4 C1 C3 C4'
# the options that make a variant of the scene (its own case: -tag)
VARIANTS = ('-width, -cellSize, -voidFraction, -sphereRatio, -forces, -fluidVelocity, '
            '-fluctuation, -eddyLifetime, -fluctuationSize, -fluctuationAt, -lift, -turbulence, -minVoidFraction, -voidFractionFloor, -grading, -bed, -maxCo, '
            '-semiImplicitAlpha, -maxTime, -demStep')


class OptionError(Exception):
    pass


def number(text, ok):
    """True when text is a number (float) for which ok holds."""
    try:
        return bool(ok(float(text)))
    except (ValueError, OverflowError):
        return False


def words(text):
    """The words of text as the shell splits an unquoted $text."""
    return [w for w in re.split('[ \t\n]+', text) if w]


def counted(text):
    """A count of ranks or runs: digits only, not 0 ('' too is none)."""
    return re.fullmatch('[0-9]+', text) is not None and text != '0'


def check_run_length(o, s):
    """-maxTime (the longest run) and -endTime (a fixed end)."""
    if o['maxTime']:
        if not number(o['maxTime'], lambda t: t >= float(s['defaultEnd'])):
            raise OptionError(
                "-maxTime needs the longest run in s, at least the first "
                "piece's %s s at this scale, got '%s'"
                % (s['defaultEnd'], o['maxTime']))
        if o['endTime']:
            raise OptionError(
                '-maxTime is the longest run of "until the breach has '
                'ended"; with -endTime %s the run has a fixed end: use one '
                'of them' % o['endTime'])
        if o['maxTime'] == s['maxEnd']:
            o['maxTime'] = ''


def is_variant(o):
    return any(o[k] for k in ('width', 'voidFraction', 'sphereRatio', 'forces',
                              'fluidVelocity', 'fluctuation', 'eddyLifetime',
                              'fluctuationSize', 'fluctuationAt', 'lift',
                              'minVoidFraction', 'voidFractionFloor',
                              'grading', 'maxTime',
                              'demStep')) \
        or o['cellSize'] != '0.05' or o['bed'] != 'rough' \
        or o['turbulence'] != 'laminar' \
        or o['maxCo'] != '0.5' or o['semiImplicitAlpha'] == 'yes'


def check_cells(o, s):
    """-width and -cellSize: the cells across the slice."""
    if o['width']:
        if o['scale'] != 'small':
            raise OptionError('-width is for the small scale (the full flume '
                              'is 0.5 m)')
        s['width'] = o['width']
    try:
        c, w = float(o['cellSize']), float(s['width'])
        ok = 0.01 <= c <= 0.05 and all(abs(n/c - round(n/c)) < 1e-6
                                       for n in (7, 0.05, 0.45, w))
    except (ValueError, OverflowError):
        ok = False
    if not ok:
        raise OptionError("-cellSize must divide 7 m, 0.05 m, 0.45 m and the "
                          "width %s m, between 0.01 and 0.05 m, got '%s'"
                          % (s['width'], o['cellSize']))
    s['nCells'] = str(round(w/c))


def check_coupling(o, s):
    """-fluidVelocity, -minVoidFraction, -voidFractionFloor, -fluctuation,
    -eddyLifetime, -voidFraction."""
    if o['fluidVelocity'] not in ('', 'voidFractionAverage', 'cellPoint',
                                  'grainTop', 'roughnessLayer'):
        raise OptionError("-fluidVelocity: use voidFractionAverage (the "
                          "default), cellPoint, grainTop or roughnessLayer, "
                          "got '%s'" % o['fluidVelocity'])
    if o['minVoidFraction'] and not number(o['minVoidFraction'],
                                           lambda v: 0 < v < 1):
        raise OptionError("-minVoidFraction takes the floor of the void "
                          "fraction, a number between 0 and 1 (exclusive), "
                          "got '%s'" % o['minVoidFraction'])
    if o['voidFractionFloor'] not in ('', 'clip', 'spill'):
        raise OptionError("-voidFractionFloor: use clip (the default: eps "
                          "set to the floor, -minVoidFraction, where the "
                          "grains hold more) or spill (the solid beyond it "
                          "moved to the neighbouring cells), got '%s'"
                          % o['voidFractionFloor'])
    if o['turbulence'] not in ('laminar', 'kOmegaSST'):
        raise OptionError("-turbulence: use laminar (the default) or "
                          "kOmegaSST (k-omega SST with the fluid fraction in "
                          "its equations), got '%s'" % o['turbulence'])
    if o['fluctuation'] == 'turbulence':
        if o['turbulence'] == 'laminar':
            raise OptionError("-fluctuation turbulence takes the "
                              "fluctuations from a turbulence model: give "
                              "-turbulence kOmegaSST")
    elif o['fluctuation']:
        # as the shell's read of one line: two words and the rest
        w = words(o['fluctuation'].split('\n')[0]) + ['', '']
        s['intensity'], s['eddyTime'] = w[0], w[1]
        if not (number(w[0], lambda i: i >= 0) and number(w[1], lambda t: t > 0)
                and not ''.join(w[2:])):
            raise OptionError("-fluctuation takes two numbers, the intensity "
                              "(>= 0) and the eddy time (s, > 0), or "
                              "turbulence, got '%s'"
                              % o['fluctuation'])
    # the choices of velocityFluctuation source turbulence: the option, its
    # words, what they mean and what the option does (for the message
    # without -fluctuation turbulence)
    for key, words, meaning, needs in (
            ('eddyLifetime', ('crossing', 'turnover'),
             "crossing (the default: the time the flow takes to carry an "
             "eddy past the grain) or turnover (k/epsilon)",
             "is how long a grain keeps an eddy of the turbulence model"),
            ('fluctuationSize', ('k', 'shearStress'),
             "k (the default: the eddies' energy is k) or shearStress (the "
             "local Reynolds shear stress)",
             "sizes the eddies of the turbulence model"),
            ('fluctuationAt', ('average', 'grainTop', 'cellAbove'),
             "average (the default: over the grain's cells), grainTop (at "
             "its top) or cellAbove (in the cell above its host cell)",
             "takes the turbulence model's k, epsilon and shear stress at "
             "the grain")):
        if not o[key]:
            continue
        if o[key] not in words:
            raise OptionError("-%s: use %s, got '%s'" % (key, meaning, o[key]))
        if o['fluctuation'] != 'turbulence':
            raise OptionError("-%s %s: give -fluctuation turbulence "
                              "-turbulence kOmegaSST" % (key, needs))
    if o['lift'] and not number(o['lift'], lambda c: 0 <= c <= 2):
        raise OptionError("-lift takes the bed lift's coefficient C_L "
                          "(WibergSmithLift), between 0 and 2 (Wiberg & "
                          "Smith 1985: 0.2), got '%s'" % o['lift'])
    if 'WibergSmithLift' in o['forces'].split() and not o['lift']:
        raise OptionError("-forces with WibergSmithLift: give its "
                          "coefficient with -lift C_L (e.g. -lift 0.2)")
    if o['voidFraction'] not in ('', 'virtualSphere', 'divided', 'centre'):
        raise OptionError("-voidFraction: unknown model '%s': use "
                          "virtualSphere, divided or centre" % o['voidFraction'])
    if o['sphereRatio']:
        if o['voidFraction'] not in ('', 'virtualSphere'):
            raise OptionError("-sphereRatio is the virtual sphere's diameter "
                              "over the grain's: it needs the virtualSphere "
                              "model, not -voidFraction %s" % o['voidFraction'])
        if not number(o['sphereRatio'], lambda k: k >= 1):
            raise OptionError("-sphereRatio takes the virtual sphere's "
                              "diameter over the grain's, at least 1 "
                              "(default 4, the seed's), got '%s'"
                              % o['sphereRatio'])


def check_grading(o):
    if o['grading'] and not os.path.isfile('DEM/in.material.' + o['grading']):
        have = sorted(n[len('in.material.'):] for n in os.listdir('DEM')
                      if n.startswith('in.material.'))
        raise OptionError('-grading: no DEM/in.material.%s (have: %s)'
                          % (o['grading'], ''.join(n + ' ' for n in have)))


def check_scenarios(o, s):
    """-scenario (all: the eight) and -buildDam's materials."""
    s['scenario'] = ALL if o['scenario'] == 'all' else o['scenario']
    for sc in words(s['scenario']):
        if not re.fullmatch('[CF][1-4]', sc):
            raise OptionError("unknown scenario '%s': use C1, C2, C3, C4, F1, "
                              "F2, F3 or F4 (seed Table 2)" % sc)
    for m in words(o['buildDam']):
        if m not in ('C', 'F', 'Fcoarse'):
            raise OptionError("-buildDam: unknown material '%s': use C, F, "
                              "Fcoarse or \"C F\"" % m)


def check_ranks(o):
    """-parallel, -demGrid (its product the ranks) and -jobs."""
    nProcs = o['parallel']
    if not counted(nProcs):
        raise OptionError("-parallel needs a number of ranks (1, 2, ...), "
                          "got '%s'" % nProcs)
    if o['demGrid'] not in ('auto', '* * *'):
        w = o['demGrid'].split()
        # (as a number in Python's syntax: no leading zeros)
        ranks = int(nProcs) if re.fullmatch('0+|[1-9][0-9]*', nProcs) else None
        try:
            ok = len(w) == 3 and all(x.isdigit() and int(x) > 0 for x in w) \
                and int(w[0])*int(w[1])*int(w[2]) == ranks
        except ValueError:
            ok = False
        if not ok:
            raise OptionError(
                "-demGrid needs three whole numbers of ranks (along the "
                "flume, across, up) whose product is the -parallel %s ranks, "
                "e.g. \"1 %s 1\", or auto (the default: chosen from the "
                "dam's grains) or \"* * *\" (LIGGGHTS's choice), got '%s'"
                % (nProcs, nProcs, o['demGrid']))
    if not counted(o['jobs']):
        raise OptionError("-jobs needs a number of runs side by side (1, 2, "
                          "...), got '%s'" % o['jobs'])


def check_sample(o, s):
    """-sample: a (the run as set) or b, the second sample of the matrix:
    every step 10 % shorter (maxCo x 0.9, and the DEM step the run would
    have x 0.9: demStepScale, setup.sh), in the cases
    <scenario>.<scale>[.<tag>].b; firstTag names the first sample's."""
    s['maxCo'], s['tag'] = o['maxCo'], o['tag']
    s['firstTag'], s['demStepScale'] = o['tag'], '1'
    if o['sample'] not in ('a', 'b'):
        raise OptionError("-sample: use a (the run as set) or b (the "
                          "matrix's second sample, every step 10 %% "
                          "shorter), got '%s'" % o['sample'])
    if o['tag'] == 'b' or o['tag'].endswith('.b'):
        raise OptionError("-tag %s: a tag b or ending in .b names a second "
                          "sample's cases: use -sample b" % o['tag'])
    if o['sample'] == 'b':
        s['maxCo'] = '%g' % (0.9*float(o['maxCo']))
        s['demStepScale'] = '0.9'
        s['tag'] = o['tag'] + '.b' if o['tag'] else 'b'


def check(o):
    """The settings of the options o, or OptionError at the first wrong
    one (in the order Allrun has always checked them)."""
    if o['resume'] == 'yes' and o['setupOnly'] == 'yes':
        raise OptionError('-resume continues runs; -setupOnly stops before '
                          'running: use one of them')
    if o['scale'] not in SCALES:
        raise OptionError("unknown scale '%s': use small or full" % o['scale'])
    s = dict(SCALES[o['scale']], pieceLength=PIECE_LENGTH, intensity='',
             eddyTime='')
    if o['bed'] not in ('rough', 'smooth', 'pocket'):
        raise OptionError("-bed: use rough (the tutorial's), smooth (Table "
                          "3's particle-geometry values) or pocket (rolling "
                          "friction 0.577), got '%s'" % o['bed'])
    check_run_length(o, s)
    if not number(o['maxCo'], lambda c: 0 < c <= 5):
        raise OptionError("-maxCo needs a Courant number > 0 and at most 5 "
                          "(default 0.5), got '%s'" % o['maxCo'])
    if o['demStep'] and not number(o['demStep'], lambda f: 0 < f <= 0.5):
        raise OptionError("-demStep needs the DEM step as a fraction of the "
                          "smallest grains' Rayleigh time, > 0 and at most "
                          "0.5 (default 0.18), got '%s'" % o['demStep'])
    if is_variant(o) and not re.fullmatch('[A-Za-z0-9_-]+', o['tag']):
        raise OptionError("a variant (%s) needs -tag NAME (letters, digits, "
                          "_ or -), got '%s'" % (VARIANTS, o['tag']))
    if o['maxTime']:
        s['maxEnd'] = o['maxTime']
    check_cells(o, s)
    check_coupling(o, s)
    check_grading(o)
    if o['lakeLevel'] == 'unset':
        s['lakeLevel'] = s['defaultLake']
    elif o['lakeLevel'] and not number(o['lakeLevel'], lambda d: 0 <= d < 0.3):
        raise OptionError("-lakeLevel needs a depth in m at the dam's toe, "
                          "0 <= depth < 0.3 (the crest), got '%s'"
                          % o['lakeLevel'])
    else:
        s['lakeLevel'] = o['lakeLevel']
    check_scenarios(o, s)
    check_ranks(o)
    check_sample(o, s)
    if o['endTime']:
        if not number(o['endTime'], lambda t: t > 0):
            raise OptionError("-endTime needs a positive time in s, got '%s'"
                              % o['endTime'])
        s['endTime'], s['untilEnded'] = o['endTime'], 'no'
    else:
        s['endTime'], s['untilEnded'] = s['defaultEnd'], 'yes'
    return s


def main(argv):
    o = dict(a.split('=', 1) for a in argv)
    try:
        s = check(o)
    except OptionError as e:
        print('Allrun: %s' % e)
        return 1
    for k in ('scenario', 'width', 'nCells', 'sides', 'yBoundary', 'sideWalls',
              'lakeLevel', 'endTime', 'untilEnded', 'maxEnd', 'pieceLength',
              'intensity', 'eddyTime', 'maxCo', 'demStepScale', 'tag',
              'firstTag'):
        print('%s=%s' % (k, shlex.quote(s[k])))
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
