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
import os
import shutil
import subprocess
import sys
import tempfile
import time as clock

from paraview.simple import (Box, Calculator, ColorBy, LegacyVTKReader,
                             SaveScreenshot, Show, Slice, Text)

# the helpers shared with the other tutorials' ParaView scripts (opening
# the case, the cloud, the colour maps GRAIN_MAP and WATER_MAP, ...):
# bin/pvhelpers.py
sys.path.insert(0, os.path.join(
    os.environ.get('INTERDEMFOAM_DIR')
    or os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', '..'),
    'bin'))
import pvhelpers as pv  # noqa: E402
from pvhelpers import GRAIN_MAP, WATER_MAP  # noqa: E402

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
    return [(w, 't = %g s (evenly spaced)' % w) for w in pv.evenly(times, 6)]


# ---------------------------------------------------------------------------
# ParaView pipeline
class Scene:
    def __init__(self, case, args, size):
        self.case = case
        self.args = args
        foam = pv.foam_file(case)
        self.fluid = pv.open_fluid(foam, ['internalMesh'], ['U', 'alpha.water'])
        self.fluid.UpdatePipelineInformation()
        self.fluid.UpdatePipeline(min(self.fluid.TimestepValues))
        b = self.fluid.GetDataInformation().GetBounds()
        self.bounds = b
        self.cloud = pv.open_cloud(foam, min(self.fluid.TimestepValues),
                                   ['d', 'U'])
        self.dirs = time_dirs(case)
        self.dt = pv.dem_step(case)
        self.vtkGrains = {}

        v = pv.white_view(list(size))
        # never at a time without the cloud: the reader would drop the
        # lagrangian region from its selection
        v.ViewTime = min(self.fluid.TimestepValues)
        self.view = v

        self.show_water(b, v, args)
        self.show_bed(b, v)
        # grains from the cloud, glyphs sized by d
        self.grainLut = pv.lut('grainSpeed', GRAIN_MAP, 0, args.grainMax,
                               above=True)
        self.cloudGlyph = self.glyph(self.cloud)
        self.cloudDisplay = self.show_grains(self.cloudGlyph)
        self.vtkDisplay = None
        self.show_labels(v)
        self.frame_camera()

    def show_water(self, b, v, args):
        """The water on the back plane of the flume, where alpha.water >
        0.5, coloured by its speed, and its surface."""
        y = b[3] - 1e-3*(b[3] - b[2])
        sl = Slice(Input=self.fluid)
        sl.SliceType = 'Plane'
        sl.SliceType.Origin = [0, y, 0]
        sl.SliceType.Normal = [0, 1, 0]
        water = pv.water_clip(sl)
        self.waterLut = pv.lut('waterSpeed', WATER_MAP, 0, args.waterMax,
                               above=True)
        wd = Show(water, v)
        ColorBy(wd, ('POINTS', 'U', 'Magnitude'))
        wd.LookupTable = self.waterLut
        wd.Opacity = 0.85
        wd.Ambient, wd.Diffuse = 1.0, 0.0     # the map's own colours
        sd = Show(pv.free_surface(sl), v)
        sd.ColorArrayName = ['POINTS', '']
        sd.AmbientColor = sd.DiffuseColor = pv.SURFACE_COLOUR
        sd.LineWidth = 2.5
        self.waterDisplay, self.surfDisplay = wd, sd

    def show_bed(self, b, v):
        """The bed: a slab under z = 0 along the whole flume."""
        bed = Box(XLength=b[1] - b[0], YLength=b[3] - b[2], ZLength=0.04,
                  Center=[0.5*(b[0] + b[1]), 0.5*(b[2] + b[3]), -0.02])
        bd = Show(bed, v)
        bd.AmbientColor = bd.DiffuseColor = list(pv.BED_COLOUR)

    def show_labels(self, v):
        """The time label (upper left) and the two colour bars (hidden
        until render asks for them)."""
        self.text = Text(Text='')
        td = Show(self.text, v)
        td.WindowLocation = 'Upper Left Corner'
        td.FontSize = 22
        td.Color = [0, 0, 0]
        self.textDisplay = td
        self.bars = []
        for f, loc, title in ((self.grainLut, [0.40, 0.66], 'grain speed (m/s)'),
                              (self.waterLut, [0.70, 0.66], 'water speed (m/s)')):
            self.bars.append(pv.scalar_bar(
                f, v, title, Orientation='Horizontal',
                WindowLocation='Any Location', Position=loc,
                ScalarBarLength=0.26, ScalarBarThickness=12,
                TitleFontSize=16, LabelFontSize=14, AddRangeLabels=1,
                RangeLabelFormat='%-#.1f', DrawTickLabels=0))

    def glyph(self, source):
        return pv.sphere_glyphs(source, theta=14, phi=10)

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
                gb = pv.point_bounds(src, t)
                break
        if gb is None:
            gb = self.bounds
        x0 = gb[0] - 0.25*(gb[1] - gb[0])
        x1 = gb[1] + 0.30*(gb[1] - gb[0])
        top = max(gb[5], 0.1)*1.25           # room for the overtopping flow
        up = pv.gravity_up(self.case)        # real world's up, flume frame
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
    plt = pv.pyplot()
    import matplotlib.image as mpimg

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
        pv.colour_bar(fig, [(gap + k*(fw + gap) + 1.2)/W, 0.62/H, 5.0/W,
                            0.2/H], cmap, 0, top_, title, 11, extend='max')
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
