#!/usr/bin/env pvbatch
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
"""Landslide dam breach in pictures (the longitudinal view of seed Fig. 6).

    pvrender renderBreach.py CASE [--noGif] [--grainMax 0.5] [--waterMax 1.5]
                                  [--frames DIR]

(pvrender, in the project's bin/, runs pvbatch on a private virtual X server;
`xvfb-run -a pvbatch renderBreach.py CASE` works too.)

CASE is a run of this tutorial (e.g. C2.small). Writes, in CASE:

  breach.png   six moments of the breach side by side: the grains as
               spheres of their true diameter coloured by speed, the water
               (alpha.water > 0.5 on the flume's back plane) coloured by its
               speed, the free surface, the bed; one colour bar each
  breach.gif   every write time, ~800 px wide (needs ImageMagick's convert)

The six moments come from the analysis (damBreachAnalysis.py writes
damBreach.dat and damBreach.summary; run it first):
  start         the first write time (t = 0 has no cloud: the first after)
  seepage       half-way between the start and the overtopping
  overtopping   the first write time at or after 'overtopping from t'
  backward      half-way between the overtopping and the onset of the crest's
  erosion       lowering (the crest has lost 10 % of what it will lose)
  head-cut      the crest has lost half of what it will lose
  end           the analysis's end (its last DEM dump with grains), else the
                last write time
Without an overtopping (or without the analysis) the six are evenly spaced
write times, and the panel says so.

Grains come from the Lagrangian cloud 'demParticles' that interDemFoam writes
at each write time (d, U); where a time has none, from the DEM's own dump
post/particles_<step>.vtk if there is one.
The view is the flume's side (looking across it), turned so that up is the
real world's up (against constant/g): the bed falls 5 degrees downstream.
"""
import argparse
import glob
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time as clock

from paraview.simple import (Box, Calculator, Clip, ColorBy, Contour,
                             CreateRenderView, Delete, Glyph,
                             GetColorTransferFunction, GetScalarBar,
                             LegacyVTKReader, OpenFOAMReader, Render,
                             SaveScreenshot, Show, Slice, Text)
from paraview import servermanager

# Colour maps, shared by ParaView and the matplotlib colour bars:
# (position 0..1, r, g, b). Grains: sand at rest, orange, red, dark red when
# fast. Water: light to deep blue.
GRAIN_MAP = [(0.0, 0.80, 0.70, 0.52), (0.3, 0.96, 0.60, 0.16),
             (0.65, 0.84, 0.14, 0.10), (1.0, 0.45, 0.02, 0.10)]
WATER_MAP = [(0.0, 0.80, 0.90, 0.98), (0.4, 0.42, 0.68, 0.88),
             (0.75, 0.13, 0.40, 0.72), (1.0, 0.03, 0.15, 0.42)]
BED_COLOUR = (0.45, 0.45, 0.45)
PHASES = ['start', 'seepage', 'overtopping', 'backward erosion',
          'head-cut erosion', 'end']


def parse():
    p = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    p.add_argument('case', nargs='?', default='C2.small')
    p.add_argument('--noGif', action='store_true', help='panel only')
    p.add_argument('--grainMax', type=float, default=0.5,
                   help='top of the grain speed colour bar (m/s)')
    p.add_argument('--waterMax', type=float, default=1.5,
                   help='top of the water speed colour bar (m/s)')
    p.add_argument('--frames', metavar='DIR',
                   help='keep the single frames in DIR')
    p.add_argument('--width', type=int, default=1000,
                   help='width of one frame of the panel (px)')
    return p.parse_args()


# ---------------------------------------------------------------------------
# Case data
def time_dirs(case):
    """{time: folder name} of the case's write times"""
    out = {}
    for d in os.listdir(case):
        try:
            t = float(d)
        except ValueError:
            continue
        if os.path.isdir(os.path.join(case, d)):
            out[t] = d
    return out


def gravity(case):
    text = open(os.path.join(case, 'constant', 'g')).read()
    m = re.search(r'value\s*\(\s*([^\s)]+)\s+([^\s)]+)\s+([^\s)]+)\s*\)', text)
    g = [float(v) for v in m.groups()]
    n = math.sqrt(sum(v*v for v in g))
    return [v/n for v in g]


def dem_step(case):
    """DEM time step (s) from DEM/in.case (written by Allrun); no default:
    the dump steps are times only with the step the run used"""
    f = os.path.join(case, 'DEM', 'in.case')
    try:
        text = open(f).read()
        return float(re.search(r'variable\s+demDt\s+index\s+(\S+)', text).group(1))
    except (OSError, AttributeError, ValueError):
        raise SystemExit('%s: no "variable demDt index <s>" (written by Allrun):'
                         ' cannot tell the time of the DEM dumps' % f)


def summary(case):
    out = {}
    try:
        for line in open(os.path.join(case, 'damBreach.summary')):
            parts = line.rsplit(None, 1)
            if len(parts) == 2:
                out[parts[0].strip()] = float(parts[1])
    except OSError:
        pass
    return out


def breach_table(case):
    """t, H columns of damBreach.dat, or None"""
    try:
        rows = [l.split() for l in open(os.path.join(case, 'damBreach.dat'))
                if l.strip() and not l.startswith('#')]
        return [float(r[0]) for r in rows], [float(r[1]) for r in rows]
    except (OSError, ValueError, IndexError):
        return None


def evenly(times, n=6):
    if len(times) <= n:
        return list(times)
    return [times[int(round(i*(len(times) - 1)/(n - 1)))] for i in range(n)]


def choose_times(case, times):
    """Six (time, label) pairs: the breach phases, or evenly spaced"""
    s = summary(case)
    tab = breach_table(case)
    over = s.get('overtopping from t [s] (-1: none)', -1)
    why = None
    if tab is None:
        why = 'no damBreach.dat (run damBreachAnalysis.py)'
    elif over < 0:
        why = 'no overtopping in damBreach.summary'
    elif len(times) < 6:
        why = 'fewer than six write times'
    if why is None:
        t, h = tab

        def snap(x, after=None, ceil=False):
            cands = [w for w in times if (after is None or w > after)
                     and (not ceil or w >= x - 1e-9)]
            return min(cands, key=lambda w: abs(w - x)) if cands else None
        # the analysis ends with the last DEM dump that has grains
        end = snap(s.get('end time [s]', times[-1]))
        tail = [hh for tt, hh in zip(t, h) if tt >= t[0] + 0.9*(t[-1] - t[0])]
        hOver = [hh for tt, hh in zip(t, h) if tt >= over][0]
        loss = hOver - sum(tail)/len(tail)

        def lost(frac):
            for tt, hh in zip(t, h):
                if tt > over and hh < hOver - frac*loss:
                    return tt
            return None
        onset, half = lost(0.1), lost(0.5)
        if loss < 0.01 or onset is None or half is None:
            why = 'the crest lost under 10 mm after overtopping'
        else:
            pick = [times[0]]
            for target, ceil in ((0.5*(times[0] + over), False),
                                 (over, True), (0.5*(over + onset), False),
                                 (half, False), (end, False)):
                w = snap(target, after=pick[-1], ceil=ceil)
                if w is None:
                    break
                pick.append(w)
            if len(pick) == 6 and pick[-1] == end:
                return [(w, '%s, t = %g s' % (name, w))
                        for w, name in zip(pick, PHASES)]
            why = 'the phases fall on too few write times'
    print('renderBreach: phase times not available (%s): evenly spaced '
          'write times instead' % why)
    return [(w, 't = %g s (evenly spaced)' % w) for w in evenly(times)]


# ---------------------------------------------------------------------------
# ParaView pipeline
def rgb_points(cmap, top):
    pts = []
    for x, r, g, b in cmap:
        pts += [x*top, r, g, b]
    return pts


def lut(name, cmap, top, title):
    f = GetColorTransferFunction(name)
    f.VectorMode = 'Magnitude'
    f.RGBPoints = rgb_points(cmap, top)
    f.ColorSpace = 'RGB'
    f.AutomaticRescaleRangeMode = 'Never'
    f.RescaleTransferFunction(0.0, top)
    f.AboveRangeColor = list(cmap[-1][1:])
    f.UseAboveRangeColor = 1
    return f


def point_bounds(source, t):
    """Bounds of a source's points at time t (None if it has none)"""
    from paraview.simple import MergeBlocks
    m = MergeBlocks(Input=source)
    m.UpdatePipeline(t)
    data = servermanager.Fetch(m)
    Delete(m)
    n = data.GetNumberOfPoints()
    if not n:
        return None
    pts = [data.GetPoint(i) for i in range(n)]
    return [f(p[k] for p in pts) for k in range(3) for f in (min, max)]


class Scene:
    def __init__(self, case, args, size):
        self.case = case
        self.args = args
        foam = os.path.join(case, 'case.foam')
        if not os.path.exists(foam):
            open(foam, 'w').close()
        self.fluid = OpenFOAMReader(FileName=foam, SkipZeroTime=0)
        self.fluid.SkipZeroTime = 0
        self.fluid.MeshRegions = ['internalMesh']
        self.fluid.CellArrays = ['U', 'alpha.water']
        self.fluid.UpdatePipelineInformation()
        self.fluid.UpdatePipeline(min(self.fluid.TimestepValues))
        b = self.fluid.GetDataInformation().GetBounds()
        self.bounds = b
        self.cloud = OpenFOAMReader(FileName=foam, SkipZeroTime=0)
        self.cloud.MeshRegions = ['lagrangian/demParticles']
        self.cloud.UpdatePipeline(min(self.fluid.TimestepValues))
        self.cloud.LagrangianArrays = ['d', 'U']
        self.dirs = time_dirs(case)
        self.dt = dem_step(case)
        self.vtkGrains = {}

        v = CreateRenderView()
        v.ViewSize = list(size)
        v.OrientationAxesVisibility = 0
        v.Background = [1, 1, 1]
        try:
            v.UseColorPaletteForBackground = 0
        except AttributeError:
            pass
        v.CameraParallelProjection = 1
        # never at a time without the cloud: the reader would drop the
        # lagrangian region from its selection
        v.ViewTime = min(self.fluid.TimestepValues)
        self.view = v

        # water: the back plane of the flume, where alpha.water > 0.5
        y = b[3] - 1e-3*(b[3] - b[2])
        sl = Slice(Input=self.fluid)
        sl.SliceType = 'Plane'
        sl.SliceType.Origin = [0, y, 0]
        sl.SliceType.Normal = [0, 1, 0]
        water = Clip(Input=sl)
        water.ClipType = 'Scalar'
        water.Scalars = ['POINTS', 'alpha.water']
        water.Value = 0.5
        water.Invert = 0
        self.waterLut = lut('waterSpeed', WATER_MAP, args.waterMax,
                            'water |U| (m/s)')
        wd = Show(water, v)
        ColorBy(wd, ('POINTS', 'U', 'Magnitude'))
        wd.LookupTable = self.waterLut
        wd.Opacity = 0.85
        wd.Ambient, wd.Diffuse = 1.0, 0.0     # the map's own colours
        surf = Contour(Input=sl)
        surf.ContourBy = ['POINTS', 'alpha.water']
        surf.Isosurfaces = [0.5]
        sd = Show(surf, v)
        sd.ColorArrayName = ['POINTS', '']
        sd.AmbientColor = sd.DiffuseColor = [0.03, 0.15, 0.42]
        sd.LineWidth = 2.5
        self.waterDisplay, self.surfDisplay = wd, sd

        # the bed: a slab under z = 0 along the whole flume
        bed = Box(XLength=b[1] - b[0], YLength=b[3] - b[2], ZLength=0.04,
                  Center=[0.5*(b[0] + b[1]), 0.5*(b[2] + b[3]), -0.02])
        bd = Show(bed, v)
        bd.AmbientColor = bd.DiffuseColor = list(BED_COLOUR)

        # grains from the cloud, glyphs sized by d
        self.grainLut = lut('grainSpeed', GRAIN_MAP, args.grainMax,
                            'grain |U| (m/s)')
        self.cloudGlyph = self.glyph(self.cloud)
        self.cloudDisplay = self.show_grains(self.cloudGlyph)
        self.vtkDisplay = None

        self.text = Text(Text='')
        td = Show(self.text, v)
        td.WindowLocation = 'Upper Left Corner'
        td.FontSize = 22
        td.Color = [0, 0, 0]
        self.textDisplay = td
        self.bars = []
        for f, loc, title in ((self.grainLut, [0.40, 0.66], 'grain speed (m/s)'),
                              (self.waterLut, [0.70, 0.66], 'water speed (m/s)')):
            sb = GetScalarBar(f, v)
            sb.Title = title
            sb.ComponentTitle = ''
            sb.Orientation = 'Horizontal'
            sb.WindowLocation = 'Any Location'
            sb.Position = loc
            sb.ScalarBarLength = 0.26
            sb.ScalarBarThickness = 12
            sb.TitleColor = sb.LabelColor = [0, 0, 0]
            sb.TitleFontSize = 16
            sb.LabelFontSize = 14
            sb.AddRangeLabels = 1
            sb.RangeLabelFormat = '%-#.1f'
            sb.DrawTickLabels = 0
            self.bars.append(sb)
        self.frame_camera()

    def glyph(self, source):
        gl = Glyph(Input=source, GlyphType='Sphere')
        gl.ScaleArray = ['POINTS', 'd']
        gl.ScaleFactor = 1.0            # sphere of diameter 1 x d
        gl.OrientationArray = ['POINTS', 'No orientation array']
        gl.GlyphMode = 'All Points'
        gl.GlyphType.ThetaResolution = 14
        gl.GlyphType.PhiResolution = 10
        return gl

    def show_grains(self, gl):
        d = Show(gl, self.view)
        ColorBy(d, ('POINTS', 'U', 'Magnitude'))
        d.LookupTable = self.grainLut
        d.Specular = 0.2
        return d

    def grains_at(self, t):
        """True: the cloud has grains at t; else the DEM's VTK dump is shown"""
        name = self.dirs.get(t)
        has = name is not None and os.path.isdir(
            os.path.join(self.case, name, 'lagrangian', 'demParticles'))
        self.cloudDisplay.Visibility = int(has)
        if has:
            self.cloud.MeshRegions = ['lagrangian/demParticles']
            self.cloud.LagrangianArrays = ['d', 'U']
        if self.vtkDisplay is not None:
            self.vtkDisplay.Visibility = 0
        if has:
            return True
        step = int(round(t/self.dt))
        path = os.path.join(self.case, 'post', 'particles_%d.vtk' % step)
        if not os.path.exists(path):
            return False
        if path not in self.vtkGrains:
            r = LegacyVTKReader(FileNames=[path])
            dd = Calculator(Input=r, ResultArrayName='d', Function='2*radius')
            uu = Calculator(Input=dd, ResultArrayName='U', Function='v')
            self.vtkGrains[path] = self.show_grains(self.glyph(uu))
        self.vtkDisplay = self.vtkGrains[path]
        self.vtkDisplay.Visibility = 1
        return True

    def frame_camera(self):
        """Frame the dam: the grains' extent at the first time, more room
        downstream (where grains go) than upstream; up = against g"""
        later = sorted(self.fluid.TimestepValues)
        gb = None
        for t in later:
            if self.grains_at(t):
                src = self.cloud if self.cloudDisplay.Visibility \
                    else self.vtkDisplay.Input
                gb = point_bounds(src, t)
                break
        if gb is None:
            gb = self.bounds
        x0 = gb[0] - 0.25*(gb[1] - gb[0])
        x1 = gb[1] + 0.30*(gb[1] - gb[0])
        top = max(gb[5], 0.1)*1.25           # room for the overtopping flow
        g = gravity(self.case)
        up = [-g[0], -g[1], -g[2]]           # real world's up, flume frame
        right = [up[2], 0.0, -up[0]]         # along the flume, in the view
        # the box x0..x1 by bed (-0.04)..top, seen along y: its extent on
        # the screen's axes
        corners = [(x, z) for x in (x0, x1) for z in (-0.04, top)]
        su = [x*up[0] + z*up[2] for x, z in corners]
        sr = [x*right[0] + z*right[2] for x, z in corners]
        cu, cr = 0.5*(min(su) + max(su)), 0.5*(min(sr) + max(sr))
        c = self.view
        focal = [cr*right[0] + cu*up[0], 0.5*(self.bounds[2] + self.bounds[3]),
                 cr*right[2] + cu*up[2]]
        c.CameraFocalPoint = focal
        c.CameraPosition = [focal[0], self.bounds[2] - 10.0, focal[2]]
        c.CameraViewUp = up
        w, h = c.ViewSize
        # parallel scale: half the view's height
        c.CameraParallelScale = 0.5*max(max(su) - min(su),
                                        (max(sr) - min(sr))*h/w)
        self.xrange = (x0, x1)
        print('renderBreach: grains %s, view x %.3g..%.3g m, up %s'
              % (['%.3g' % v for v in gb], x0, x1, ['%.3g' % v for v in up]))

    def render(self, t, path, label=None, bars=False, size=None):
        self.view.ViewTime = t
        self.grains_at(t)
        self.text.Text = label or ''
        self.textDisplay.Visibility = int(bool(label))
        for sb in self.bars:
            sb.Visibility = int(bars)
        if size is not None:
            SaveScreenshot(path, self.view, ImageResolution=list(size))
        else:
            SaveScreenshot(path, self.view)


# ---------------------------------------------------------------------------
def compose(frames, out, args):
    """The panel: 3 x 2 frames, their labels, the two colour bars"""
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.image as mpimg
    import matplotlib.pyplot as plt
    from matplotlib.colors import LinearSegmentedColormap, Normalize
    from matplotlib.cm import ScalarMappable

    imgs = [mpimg.imread(f) for f, _ in frames]
    h, w = imgs[0].shape[:2]
    ncol, nrow = 2, (len(imgs) + 1)//2
    # layout in inches: title, rows of (label, frame), colour bars
    fw, gap, head, lab, foot = 7.5, 0.1, 0.55, 0.32, 1.05
    fh = fw*h/w
    W = ncol*fw + (ncol + 1)*gap
    H = head + nrow*(lab + fh) + foot
    fig = plt.figure(figsize=(W, H), dpi=w/fw)
    for i, (img, (_, label)) in enumerate(zip(imgs, frames)):
        r, c = divmod(i, ncol)
        y = H - head - (r + 1)*(lab + fh)
        ax = fig.add_axes([(gap + c*(fw + gap))/W, y/H, fw/W, fh/H])
        ax.imshow(img, interpolation='none')
        ax.set_axis_off()
        fig.text((gap + c*(fw + gap) + 0.05)/W, (y + fh + 0.08)/H,
                 '(%s) %s' % ('ABCDEF'[i], label), fontsize=13)
    for k, (cmap, top_, title) in enumerate((
            (GRAIN_MAP, args.grainMax, 'grain speed |U| (m/s)'),
            (WATER_MAP, args.waterMax, 'water speed |U| (m/s)'))):
        cm = LinearSegmentedColormap.from_list(
            title, [(x, (r, g, b)) for x, r, g, b in cmap])
        cax = fig.add_axes([(gap + k*(fw + gap) + 1.2)/W, 0.62/H, 5.0/W,
                            0.2/H])
        cb = fig.colorbar(ScalarMappable(Normalize(0, top_), cm), cax=cax,
                          orientation='horizontal', extend='max')
        cb.set_label(title, fontsize=11)
    fig.text(0.5, 1 - 0.3/H, 'Landslide dam breach, %s: grains at their true '
             'size, water on the flume\'s back plane (up: against gravity)'
             % os.path.basename(os.path.abspath(args.case)), fontsize=14,
             ha='center', va='center')
    fig.savefig(out)
    plt.close(fig)


def make_gif(frames, out):
    convert = shutil.which('convert')
    if convert is None:
        print('renderBreach: no ImageMagick convert: %s not written '
              '(apt-get install imagemagick)' % out)
        return False
    subprocess.check_call([convert, '-delay', '30', '-loop', '0'] + frames
                          + ['-layers', 'Optimize', out])
    return True


def main():
    args = parse()
    case = args.case.rstrip('/')
    if not os.path.isdir(os.path.join(case, 'constant')):
        sys.exit('renderBreach: %s is not a case (no constant/)' % case)
    start = clock.time()
    w = args.width
    scene = Scene(case, args, (w, int(w*0.30)))
    times = sorted(scene.fluid.TimestepValues)
    picks = choose_times(case, times)
    work = args.frames or tempfile.mkdtemp(prefix='renderBreach.')
    os.makedirs(work, exist_ok=True)
    try:
        frames = []
        for i, (t, label) in enumerate(picks):
            f = os.path.join(work, 'panel%d.png' % i)
            scene.render(t, f)
            frames.append((f, label))
        compose(frames, os.path.join(case, 'breach.png'), args)
        print('renderBreach: %s/breach.png (%s)'
              % (case, ', '.join('%g s' % t for t, _ in picks)))
        if not args.noGif:
            gif = []
            for i, t in enumerate(times):
                f = os.path.join(work, 'gif%04d.png' % i)
                scene.render(t, f, label='t = %g s' % t, bars=True,
                             size=(800, 240))
                gif.append(f)
            if make_gif(gif, os.path.join(case, 'breach.gif')):
                size = os.path.getsize(os.path.join(case, 'breach.gif'))
                print('renderBreach: %s/breach.gif (%d frames, %.1f MB)'
                      % (case, len(gif), size/1e6))
    finally:
        if not args.frames:
            shutil.rmtree(work, ignore_errors=True)
    print('renderBreach: %.0f s' % (clock.time() - start))


if __name__ == '__main__':
    main()
