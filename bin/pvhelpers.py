# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
"""The tutorials' ParaView scripts share these (pvbatch, run by pvrender
beside this file; paraview --script for openBreach.py). A script finds
this folder from $INTERDEMFOAM_DIR, else three folders above its own:

    sys.path.insert(0, os.path.join(os.environ.get('INTERDEMFOAM_DIR') or
                                    os.path.join(HERE, '..', '..', '..'),
                                    'bin'))
    import pvhelpers as pv

  the case       foam_file, open_fluid, open_cloud (the Lagrangian cloud
                 demParticles), dem_step (the DEM dumps' times), gravity_up
  the data       merged, points, point_bounds (fetched from the pipeline)
  the drawing    the colour maps (GRAIN_MAP, WATER_MAP, VOID_MAP), lut,
                 white_view, white_background, water_clip, free_surface,
                 sphere_glyphs, scalar_bar; matplotlib's colour bar of a
                 map (colour_bar) and its pyplot (pyplot)
  the times      evenly
  the side view  side_view_main: a coupled case seen from the side at a
                 few write times (renderSettling.py, renderBed.py)
"""
import argparse
import math
import os
import re
import sys
import time as clock

from paraview import servermanager
from paraview.simple import (Clip, ColorBy, Contour, CreateRenderView,
                             Delete, GetColorTransferFunction, GetScalarBar,
                             Glyph, MergeBlocks, OpenFOAMReader, Render,
                             SaveScreenshot, Show, Slice)

# Colour maps, shared by ParaView and the matplotlib colour bars:
# (position 0..1, r, g, b). Grains: sand at rest, orange, red, dark red when
# fast. Water: light to deep blue. Fluid volume fraction (voidfraction):
# dark (dense) to light (open).
GRAIN_MAP = [(0.0, 0.80, 0.70, 0.52), (0.3, 0.96, 0.60, 0.16),
             (0.65, 0.84, 0.14, 0.10), (1.0, 0.45, 0.02, 0.10)]
WATER_MAP = [(0.0, 0.80, 0.90, 0.98), (0.4, 0.42, 0.68, 0.88),
             (0.75, 0.13, 0.40, 0.72), (1.0, 0.03, 0.15, 0.42)]
VOID_MAP = [(0.0, 0.05, 0.10, 0.30), (0.5, 0.15, 0.45, 0.65),
            (0.8, 0.55, 0.80, 0.85), (1.0, 0.97, 0.99, 1.00)]
BED_COLOUR = (0.45, 0.45, 0.45)
SURFACE_COLOUR = [0.03, 0.15, 0.42]      # the free surface: deep blue


# ---------------------------------------------------------------------------
# The case
def foam_file(case):
    """CASE/case.foam, the file ParaView's OpenFOAM reader opens (made
    empty if missing)."""
    foam = os.path.join(case, 'case.foam')
    if not os.path.exists(foam):
        open(foam, 'w').close()
    return foam


def open_fluid(foam, regions, arrays=None):
    """The case's mesh regions (internalMesh, patch/<name>) with these cell
    arrays, zero time included."""
    fluid = OpenFOAMReader(FileName=foam, SkipZeroTime=0)
    fluid.MeshRegions = regions
    if arrays is not None:
        fluid.CellArrays = arrays
    return fluid


def open_cloud(foam, t, arrays):
    """The Lagrangian cloud demParticles with these arrays (d, U, ...),
    read at time t (the arrays are known once read)."""
    cloud = OpenFOAMReader(FileName=foam, SkipZeroTime=0)
    cloud.MeshRegions = ['lagrangian/demParticles']
    cloud.UpdatePipeline(t)
    cloud.LagrangianArrays = arrays
    return cloud


def dem_step(case):
    """DEM time step (s) from DEM/in.case (written by the tutorial's
    Allrun); no default: the dump steps are times only with the step the
    run used"""
    f = os.path.join(case, 'DEM', 'in.case')
    try:
        text = open(f).read()
        return float(re.search(r'variable\s+demDt\s+index\s+(\S+)', text).group(1))
    except (OSError, AttributeError, ValueError):
        raise SystemExit('%s: no "variable demDt index <s>" (written by Allrun):'
                         ' cannot tell the time of the DEM dumps' % f)


def gravity_up(case):
    """The real world's up: against constant/g, a unit vector."""
    text = open(os.path.join(case, 'constant', 'g')).read()
    m = re.search(r'value\s*\(\s*([^\s)]+)\s+([^\s)]+)\s+([^\s)]+)\s*\)', text)
    g = [float(v) for v in m.groups()]
    n = math.sqrt(sum(v*v for v in g))
    return [-v/n for v in g]


# ---------------------------------------------------------------------------
# The data
def merged(source, t):
    """The source's data at time t, its blocks merged, fetched."""
    m = MergeBlocks(Input=source)
    m.UpdatePipeline(t)
    data = servermanager.Fetch(m)
    Delete(m)
    return data


def points(source, t):
    """The source's points at time t."""
    data = merged(source, t)
    return [data.GetPoint(i) for i in range(data.GetNumberOfPoints())]


def point_bounds(source, t):
    """Bounds of a source's points at time t (None if it has none)"""
    pts = points(source, t)
    if not pts:
        return None
    return [f(p[k] for p in pts) for k in range(3) for f in (min, max)]


# ---------------------------------------------------------------------------
# The drawing
def lut(name, cmap, lo, hi, above=False):
    """The colour map cmap over lo..hi of the magnitude of array name,
    fixed (not rescaled); above: values over hi in its last colour."""
    f = GetColorTransferFunction(name)
    f.VectorMode = 'Magnitude'
    f.ColorSpace = 'RGB'
    f.RGBPoints = [v for x, r, g, b in cmap for v in (lo + x*(hi - lo), r, g, b)]
    f.AutomaticRescaleRangeMode = 'Never'
    f.RescaleTransferFunction(lo, hi)
    if above:
        f.AboveRangeColor = list(cmap[-1][1:])
        f.UseAboveRangeColor = 1
    return f


def white_background(view):
    view.Background = [1, 1, 1]
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass


def white_view(size):
    """A render view of size [w, h] px for pictures: white, no axes,
    parallel projection."""
    v = CreateRenderView()
    v.ViewSize = size
    v.OrientationAxesVisibility = 0
    white_background(v)
    v.CameraParallelProjection = 1
    return v


def water_clip(source):
    """The water of source: where alpha.water > 0.5."""
    water = Clip(Input=source)
    water.ClipType = 'Scalar'
    water.Scalars = ['POINTS', 'alpha.water']
    water.Value = 0.5
    water.Invert = 0
    return water


def free_surface(source):
    """The free surface of source: alpha.water = 0.5."""
    surf = Contour(Input=source)
    surf.ContourBy = ['POINTS', 'alpha.water']
    surf.Isosurfaces = [0.5]
    return surf


def sphere_glyphs(source, theta=16, phi=12):
    """The grains of source as spheres of their diameter d."""
    gl = Glyph(Input=source, GlyphType='Sphere')
    gl.ScaleArray = ['POINTS', 'd']
    gl.ScaleFactor = 1.0                # spheres of diameter d
    gl.OrientationArray = ['POINTS', 'No orientation array']
    gl.GlyphMode = 'All Points'
    gl.GlyphType.ThetaResolution = theta
    gl.GlyphType.PhiResolution = phi
    return gl


def scalar_bar(table, view, title, **properties):
    """The colour bar of table in view: title, black text, and these
    properties of the bar, set in their order (the order matters: setting
    Orientation after Position moves the bar)."""
    bar = GetScalarBar(table, view)
    bar.Title, bar.ComponentTitle = title, ''
    for key, value in properties.items():
        setattr(bar, key, value)
    bar.TitleColor = bar.LabelColor = [0, 0, 0]
    return bar


def pyplot():
    """matplotlib's pyplot, drawing to files (no display)."""
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    return plt


def colour_bar(fig, rect, cmap, lo, hi, label, fontsize, extend='neither'):
    """A horizontal matplotlib colour bar of the map cmap (lo..hi) in the
    axes rect of fig."""
    from matplotlib.cm import ScalarMappable
    from matplotlib.colors import LinearSegmentedColormap, Normalize
    cm = LinearSegmentedColormap.from_list(
        label, [(x, (r, g, b)) for x, r, g, b in cmap])
    cax = fig.add_axes(rect)
    cb = fig.colorbar(ScalarMappable(Normalize(lo, hi), cm), cax=cax,
                      orientation='horizontal', extend=extend)
    cb.set_label(label, fontsize=fontsize)
    return cb


# ---------------------------------------------------------------------------
# The times
def evenly(times, n):
    """n write times evenly spread over times, the first and the last
    among them (all of them when there are no more than n)."""
    if len(times) <= n:
        return list(times)
    return [times[int(round(i*(len(times) - 1)/max(n - 1, 1)))]
            for i in range(n)]


# ---------------------------------------------------------------------------
# The side view of a coupled case (renderSettling.py, renderBed.py)
SIDE_VIEW = 'Pictures of a coupled case seen from the side (ParaView, pvbatch).'


def side_view_options(defaults=None):
    p = argparse.ArgumentParser(description=SIDE_VIEW)
    p.add_argument('case', nargs='?', default='.')
    p.add_argument('--frames', type=int, default=4)
    p.add_argument('--time', help='one time only (a value, or latest)')
    p.add_argument('--window', type=float, default=0.04)
    p.add_argument('--field', choices=('U', 'voidfraction'), default='U')
    p.add_argument('--speedMax', type=float, default=1.0,
                   help='top of the speed colour bars (m/s)')
    p.add_argument('--voidMin', type=float, default=0.3,
                   help='bottom of the voidfraction colour bar')
    p.add_argument('--out', default='settling.png')
    p.add_argument('--title', default=None)
    p.add_argument('--raw', action='store_true',
                   help='the first frame alone, no labels or colour bars')
    if defaults:
        p.set_defaults(**defaults)
    return p.parse_args()


def side_view_times(times, args):
    """The write times to render: --time (a value or latest), else
    --frames of them evenly spread."""
    if args.time == 'latest':
        return [times[-1]]
    if args.time is not None:
        return [min(times, key=lambda w: abs(w - float(args.time)))]
    return evenly(times, min(args.frames, len(times)))


def show_field(args, fluid, sl, v):
    """The field on the slice sl: the water's speed and its surface (U), or
    the fluid volume fraction; its colour bar (map, lo, hi, name)."""
    if args.field == 'U':
        fluid.CellArrays = ['U', 'alpha.water']
        water = water_clip(sl)
        wd = Show(water, v)
        ColorBy(wd, ('POINTS', 'U', 'Magnitude'))
        wd.LookupTable = lut('waterU', WATER_MAP, 0, args.speedMax)
        wd.Ambient, wd.Diffuse = 1.0, 0.0     # the map's own colours
        sd = Show(free_surface(sl), v)
        sd.ColorArrayName = ['POINTS', '']
        sd.AmbientColor = sd.DiffuseColor = SURFACE_COLOUR
        sd.LineWidth = 3
        return (WATER_MAP, 0, args.speedMax, 'water speed (m/s)')
    fluid.CellArrays = ['voidfraction']
    sd_ = Show(sl, v)
    ColorBy(sd_, ('CELLS', 'voidfraction'))
    sd_.LookupTable = lut('voidfraction', VOID_MAP, args.voidMin, 1.0)
    sd_.Ambient, sd_.Diffuse = 1.0, 0.0
    return (VOID_MAP, args.voidMin, 1.0, 'fluid volume fraction')


def show_grains(args, cloud, b, v):
    """The grains as spheres coloured by speed; with the voidfraction a
    cut-away: the grains of the left half only."""
    grains = cloud
    if args.field == 'voidfraction':
        # a cut-away: grains on the left half, the field on the right
        grains = Clip(Input=cloud)
        grains.ClipType = 'Plane'
        grains.ClipType.Origin = [0.5*(b[0] + b[1]), 0, 0]
        grains.ClipType.Normal = [1, 0, 0]
        grains.Invert = 1
    gd = Show(sphere_glyphs(grains), v)
    ColorBy(gd, ('POINTS', 'U', 'Magnitude'))
    gd.LookupTable = lut('grainU', GRAIN_MAP, 0, args.speedMax)


def side_view_frame(case, i, t, cloud, v, b, y, win, width, height):
    """The frame of time t (CASE/.render<i>.png), following the first
    particle within a window (win, m; None: the whole domain), and its
    label."""
    v.ViewTime = t
    cloud.MeshRegions = ['lagrangian/demParticles']
    pts = points(cloud, t)
    speed = None
    if win is None or not pts:
        cx, cz = 0.5*(b[0] + b[1]), 0.5*(b[4] + b[5])
    else:
        p = pts[0]
        cx = min(max(p[0], b[0] + 0.5*width), b[1] - 0.5*width)
        cz = min(max(p[2], b[4] + 0.5*height), b[5] - 0.5*height)
    if pts:
        u = merged(cloud, t).GetPointData().GetArray('U')
        if u is not None:
            speed = sum(c*c for c in u.GetTuple3(0))**0.5
    v.CameraFocalPoint = [cx, y, cz]
    v.CameraPosition = [cx, b[2] - 1.0, cz]
    v.CameraViewUp = [0, 0, 1]
    v.CameraParallelScale = 0.5*height*1.02
    f = os.path.join(case, '.render%d.png' % i)
    SaveScreenshot(f, v)
    label = 't = %g s' % t
    if len(pts) == 1 and speed is not None:
        label += ', |v| = %.3f m/s' % speed
    return f, label


def side_view_frames(args):
    """The frames (file, label) of the side view, the vertical mid-plane
    through the first particle (or the domain's centre), and its two
    colour bars."""
    case = os.path.abspath(args.case)
    foam = foam_file(case)
    fluid = open_fluid(foam, ['internalMesh'])
    times = sorted(fluid.TimestepValues)
    if not times:
        sys.exit('render: no write times in %s' % case)
    picks = side_view_times(times, args)
    fluid.UpdatePipeline(picks[0])
    b = fluid.GetDataInformation().GetBounds()
    cloud = open_cloud(foam, picks[0], ['d', 'U'])

    first = points(cloud, picks[0])
    y = first[0][1] if first else 0.5*(b[2] + b[3])
    sl = Slice(Input=fluid)
    sl.SliceType = 'Plane'
    sl.SliceType.Origin = [0, min(max(y, b[2] + 1e-6), b[3] - 1e-6), 0]
    sl.SliceType.Normal = [0, 1, 0]

    win = args.window if args.window > 0 else None
    width = b[1] - b[0] if win is None else min(b[1] - b[0], win)
    height = b[5] - b[4] if win is None else win
    px = 900 if win is None and height > 1.5*width else 500
    size = [int(px*width/height), px]
    v = white_view([max(200, size[0] + size[0] % 2), size[1]])
    v.ViewTime = picks[0]

    fieldBar = show_field(args, fluid, sl, v)
    show_grains(args, cloud, b, v)
    Render(v)                           # the first render resets the camera

    frames = [side_view_frame(case, i, t, cloud, v, b, y, win, width, height)
              for i, t in enumerate(picks)]
    return case, frames, fieldBar, (GRAIN_MAP, 0, args.speedMax,
                                    'particle speed (m/s)')


def side_view_compose(case, frames, bars, out, title):
    """The frames side by side, their labels, the colour bars: CASE/out."""
    plt = pyplot()
    import matplotlib.image as mpimg

    imgs = [mpimg.imread(f) for f, _ in frames]
    h, w = imgs[0].shape[:2]
    fh = 4.5
    fw = fh*w/h
    gap, head, lab, foot = 0.15, 0.45, 0.35, 1.0
    W = max(len(imgs)*(fw + gap) + gap, 6.5)
    H = head + lab + fh + foot
    fig = plt.figure(figsize=(W, H), dpi=h/fh)
    x0 = 0.5*(W - (len(imgs)*(fw + gap) - gap))
    for i, (img, (_, label)) in enumerate(zip(imgs, frames)):
        ax = fig.add_axes([(x0 + i*(fw + gap))/W, foot/H, fw/W, fh/H])
        ax.imshow(img, interpolation='none')
        ax.set_xticks([])
        ax.set_yticks([])
        for s in ax.spines.values():
            s.set_color('0.6')
        fig.text((x0 + i*(fw + gap))/W, (foot + fh + 0.08)/H, label,
                 fontsize=10 if len(imgs) > 2 else 12)
    for k, (cmap, lo, hi, name) in enumerate(bars):
        colour_bar(fig, [(0.06 + 0.5*k), 0.55/H, 0.38, 0.16/H], cmap, lo, hi,
                   name, 10)
    fig.text(0.5, 1 - 0.25/H, title, ha='center', va='center', fontsize=12)
    fig.savefig(os.path.join(case, out))
    plt.close(fig)
    for f, _ in frames:
        os.remove(f)


def side_view_main(defaults=None, title='Particle settling from air into water'):
    """The side view's command line (side_view_options, with these
    defaults): the frames composed with their colour bars and title, or
    (--raw) the first frame alone."""
    start = clock.time()
    args = side_view_options(defaults)
    case, frames, fieldBar, grainBar = side_view_frames(args)
    if args.raw:
        os.replace(frames[0][0], os.path.join(case, args.out))
        for f, _ in frames[1:]:
            os.remove(f)
    else:
        side_view_compose(case, frames, [grainBar, fieldBar], args.out,
                          args.title or title)
    print('render: %s (%s) in %.0f s' % (os.path.join(args.case, args.out),
          ', '.join(l for _, l in frames), clock.time() - start))
