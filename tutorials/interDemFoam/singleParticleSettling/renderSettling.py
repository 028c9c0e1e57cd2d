#!/usr/bin/env pvbatch
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
"""Pictures of a coupled case seen from the side (ParaView, pvbatch).

    pvrender renderSettling.py [CASE] [--frames 4] [--window 0.04]
                               [--field U|voidfraction] [--out settling.png]

(pvrender, in the project's bin/, runs pvbatch on a private virtual X
server; `xvfb-run -a pvbatch ...` works too.) Writes CASE/<out>: a few write
times side by side, each the vertical mid-plane through the first particle
(or the domain's centre) coloured by the water's speed (--field U, where
alpha.water > 0.5, with the free surface alpha.water = 0.5 as a line) or by
the fluid volume fraction (--field voidfraction), and the particles as
spheres of their true diameter (Lagrangian cloud demParticles, glyph scaled
by d) coloured by speed; with voidfraction only the particles of the left
half, the field on the right. --window: the height (m) of the window that follows
the first particle; 0 shows the whole domain. --time T renders that one time
only (latest: the last); --raw writes that frame alone (tests count its
pixels).
"""
import argparse
import os
import sys
import time as clock

from paraview.simple import (Clip, ColorBy, Contour, CreateRenderView,
                             Delete, GetColorTransferFunction, Glyph,
                             MergeBlocks, OpenFOAMReader, Render,
                             SaveScreenshot, Show, Slice)
from paraview import servermanager

# (position 0..1, r, g, b): particles sand -> red, water light -> deep
# blue, voidfraction dark (dense) -> light (open)
GRAIN_MAP = [(0.0, 0.80, 0.70, 0.52), (0.3, 0.96, 0.60, 0.16),
             (0.65, 0.84, 0.14, 0.10), (1.0, 0.45, 0.02, 0.10)]
WATER_MAP = [(0.0, 0.80, 0.90, 0.98), (0.4, 0.42, 0.68, 0.88),
             (0.75, 0.13, 0.40, 0.72), (1.0, 0.03, 0.15, 0.42)]
VOID_MAP = [(0.0, 0.05, 0.10, 0.30), (0.5, 0.15, 0.45, 0.65),
            (0.8, 0.55, 0.80, 0.85), (1.0, 0.97, 0.99, 1.00)]


def parse(defaults=None):
    p = argparse.ArgumentParser(description=__doc__.split('\n')[0])
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


def lut(name, cmap, lo, hi):
    f = GetColorTransferFunction(name)
    f.VectorMode = 'Magnitude'
    f.ColorSpace = 'RGB'
    f.RGBPoints = [v for x, r, g, b in cmap for v in (lo + x*(hi - lo), r, g, b)]
    f.AutomaticRescaleRangeMode = 'Never'
    f.RescaleTransferFunction(lo, hi)
    return f


def fetch_points(source, t):
    m = MergeBlocks(Input=source)
    m.UpdatePipeline(t)
    data = servermanager.Fetch(m)
    Delete(m)
    return [data.GetPoint(i) for i in range(data.GetNumberOfPoints())]


def render_frames(args):
    case = os.path.abspath(args.case)
    foam = os.path.join(case, 'case.foam')
    if not os.path.exists(foam):
        open(foam, 'w').close()
    fluid = OpenFOAMReader(FileName=foam, SkipZeroTime=0)
    fluid.MeshRegions = ['internalMesh']
    times = sorted(fluid.TimestepValues)
    if not times:
        sys.exit('render: no write times in %s' % case)
    if args.time == 'latest':
        picks = [times[-1]]
    elif args.time is not None:
        picks = [min(times, key=lambda w: abs(w - float(args.time)))]
    else:
        n = min(args.frames, len(times))
        picks = sorted(set(times[int(round(i*(len(times) - 1)/max(n - 1, 1)))]
                           for i in range(n)))
    fluid.UpdatePipeline(picks[0])
    b = fluid.GetDataInformation().GetBounds()
    cloud = OpenFOAMReader(FileName=foam, SkipZeroTime=0)
    cloud.MeshRegions = ['lagrangian/demParticles']
    cloud.UpdatePipeline(picks[0])
    cloud.LagrangianArrays = ['d', 'U']

    first = fetch_points(cloud, picks[0])
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
    size = [max(200, size[0] + size[0] % 2), size[1]]
    v = CreateRenderView()
    v.ViewSize = size
    v.OrientationAxesVisibility = 0
    v.Background = [1, 1, 1]
    try:
        v.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    v.CameraParallelProjection = 1
    v.ViewTime = picks[0]

    if args.field == 'U':
        fluid.CellArrays = ['U', 'alpha.water']
        water = Clip(Input=sl)
        water.ClipType = 'Scalar'
        water.Scalars = ['POINTS', 'alpha.water']
        water.Value = 0.5
        water.Invert = 0
        wd = Show(water, v)
        ColorBy(wd, ('POINTS', 'U', 'Magnitude'))
        wd.LookupTable = lut('waterU', WATER_MAP, 0, args.speedMax)
        wd.Ambient, wd.Diffuse = 1.0, 0.0     # the map's own colours
        surf = Contour(Input=sl)
        surf.ContourBy = ['POINTS', 'alpha.water']
        surf.Isosurfaces = [0.5]
        sd = Show(surf, v)
        sd.ColorArrayName = ['POINTS', '']
        sd.AmbientColor = sd.DiffuseColor = [0.03, 0.15, 0.42]
        sd.LineWidth = 3
        fieldBar = (WATER_MAP, 0, args.speedMax, 'water speed (m/s)')
    else:
        fluid.CellArrays = ['voidfraction']
        sd_ = Show(sl, v)
        ColorBy(sd_, ('CELLS', 'voidfraction'))
        sd_.LookupTable = lut('voidfraction', VOID_MAP, args.voidMin, 1.0)
        sd_.Ambient, sd_.Diffuse = 1.0, 0.0
        fieldBar = (VOID_MAP, args.voidMin, 1.0, 'fluid volume fraction')

    grains = cloud
    if args.field == 'voidfraction':
        # a cut-away: grains on the left half, the field on the right
        grains = Clip(Input=cloud)
        grains.ClipType = 'Plane'
        grains.ClipType.Origin = [0.5*(b[0] + b[1]), 0, 0]
        grains.ClipType.Normal = [1, 0, 0]
        grains.Invert = 1
    gl = Glyph(Input=grains, GlyphType='Sphere')
    gl.ScaleArray = ['POINTS', 'd']
    gl.ScaleFactor = 1.0                # spheres of diameter d
    gl.OrientationArray = ['POINTS', 'No orientation array']
    gl.GlyphMode = 'All Points'
    gl.GlyphType.ThetaResolution = 16
    gl.GlyphType.PhiResolution = 12
    gd = Show(gl, v)
    ColorBy(gd, ('POINTS', 'U', 'Magnitude'))
    gd.LookupTable = lut('grainU', GRAIN_MAP, 0, args.speedMax)
    Render(v)                           # the first render resets the camera

    frames = []
    for i, t in enumerate(picks):
        v.ViewTime = t
        cloud.MeshRegions = ['lagrangian/demParticles']
        pts = fetch_points(cloud, t)
        speed = None
        if win is None or not pts:
            cx, cz = 0.5*(b[0] + b[1]), 0.5*(b[4] + b[5])
        else:
            p = pts[0]
            cx = min(max(p[0], b[0] + 0.5*width), b[1] - 0.5*width)
            cz = min(max(p[2], b[4] + 0.5*height), b[5] - 0.5*height)
        if pts:
            m = MergeBlocks(Input=cloud)
            m.UpdatePipeline(t)
            u = servermanager.Fetch(m).GetPointData().GetArray('U')
            Delete(m)
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
        frames.append((f, label))
    return case, frames, fieldBar, (GRAIN_MAP, 0, args.speedMax,
                                    'particle speed (m/s)')


def compose(case, frames, bars, out, title):
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.image as mpimg
    import matplotlib.pyplot as plt
    from matplotlib.cm import ScalarMappable
    from matplotlib.colors import LinearSegmentedColormap, Normalize

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
        cm = LinearSegmentedColormap.from_list(
            name, [(x, (r, g, b)) for x, r, g, b in cmap])
        cax = fig.add_axes([(0.06 + 0.5*k), 0.55/H, 0.38, 0.16/H])
        cb = fig.colorbar(ScalarMappable(Normalize(lo, hi), cm), cax=cax,
                          orientation='horizontal')
        cb.set_label(name, fontsize=10)
    fig.text(0.5, 1 - 0.25/H, title, ha='center', va='center', fontsize=12)
    fig.savefig(os.path.join(case, out))
    plt.close(fig)
    for f, _ in frames:
        os.remove(f)


def main(defaults=None, title='Particle settling from air into water'):
    start = clock.time()
    args = parse(defaults)
    case, frames, fieldBar, grainBar = render_frames(args)
    if args.raw:
        os.replace(frames[0][0], os.path.join(case, args.out))
        for f, _ in frames[1:]:
            os.remove(f)
    else:
        compose(case, frames, [grainBar, fieldBar], args.out, args.title or title)
    print('render: %s (%s) in %.0f s' % (os.path.join(args.case, args.out),
          ', '.join(l for _, l in frames), clock.time() - start))


if __name__ == '__main__':
    main()
