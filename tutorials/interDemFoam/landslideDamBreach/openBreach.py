# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
# ParaView state of a landslide-dam breach run, built by a script:
#
#     cd C2.small && paraview --script=../openBreach.py
#     paraview --script=openBreach.py          (picks the newest run here)
#     BREACH_CASE=C4.small paraview --script=openBreach.py
#
# Opens, all on the same time line (the case's write times):
#   water      the fluid's internal mesh clipped to alpha.water > 0.5,
#              coloured by |U| (blues), semi-transparent
#   surface    the free surface, alpha.water = 0.5
#   grains     the Lagrangian cloud demParticles as spheres of their true
#              diameter (Glyph scaled by d, factor 1), coloured by |U|
#   forceChain the DEM's grain-grain contacts (post/forceChain_<step>.vtk,
#              written every write time by DEM/in.dam) as lines coloured by
#              the contact force |F|; hidden: tick its eye (and hide the
#              grains) to see the chains inside the dam
#   bed        the flume's bed patch
# The camera looks across the flume with the real world's up (against g).
# Also runs under pvbatch (BREACH_SCREENSHOT=file.png saves a picture).
import glob
import json
import math
import os
import re
import sys

from paraview import servermanager

from paraview.simple import (Clip, ColorBy, Contour, Glyph,
                             GetActiveViewOrCreate, GetAnimationScene,
                             GetColorTransferFunction, OpenDataFile,
                             GetScalarBar, MergeBlocks, OpenFOAMReader,
                             RenameSource, Render,
                             SaveScreenshot, Show, Hide, ExtractBlock)


def find_case():
    case = os.environ.get('BREACH_CASE')
    if case:
        return os.path.abspath(case)
    if os.path.isdir('constant') and os.path.isdir('system'):
        return os.getcwd()
    runs = [os.path.dirname(os.path.dirname(p))
            for p in glob.glob('*/constant/couplingProperties')]
    if not runs:
        raise RuntimeError('openBreach.py: no case here: run it in a case '
                           '(e.g. C2.small) or set BREACH_CASE')
    return os.path.abspath(max(runs, key=os.path.getmtime))


# the DEM step of a case: renderBreach.py's (this script's folder; ParaView's
# --script may run it without __file__: then the case's parent folder, or the
# tutorial of $INTERDEMFOAM_TUTORIALS)
for _d in ([os.path.dirname(os.path.abspath(__file__))] if '__file__' in globals() else []) \
        + [os.path.join(os.getcwd(), '..'),
           os.path.join(os.environ.get('INTERDEMFOAM_TUTORIALS', '.'), 'landslideDamBreach')]:
    if os.path.isfile(os.path.join(_d, 'renderBreach.py')):
        sys.path.insert(0, os.path.abspath(_d))
        break
from renderBreach import dem_step  # noqa: E402


def series(case, stem):
    """post/<stem>.vtk.series: the DEM's VTK dumps on the CFD time line"""
    dt = dem_step(case)
    files = []
    for p in glob.glob(os.path.join(case, 'post', stem + '_*.vtk')):
        m = re.match(re.escape(stem) + r'_(\d+)\.vtk$', os.path.basename(p))
        if m:
            files.append((int(m.group(1))*dt, os.path.basename(p)))
    if not files:
        return None
    out = os.path.join(case, 'post', stem + '.vtk.series')
    with open(out, 'w') as f:
        json.dump({'file-series-version': '1.0',
                   'files': [{'name': n, 'time': round(t, 9)}
                             for t, n in sorted(files)]}, f, indent=1)
    return out


def colours(name, points, top):
    f = GetColorTransferFunction(name)
    f.VectorMode = 'Magnitude'
    f.ColorSpace = 'RGB'
    f.RGBPoints = [v for x, r, g, b in points for v in (x*top, r, g, b)]
    f.AutomaticRescaleRangeMode = 'Never'
    f.RescaleTransferFunction(0.0, top)
    return f


case = find_case()
foam = os.path.join(case, 'case.foam')
if not os.path.exists(foam):
    open(foam, 'w').close()
view = GetActiveViewOrCreate('RenderView')
view.OrientationAxesVisibility = 1
view.Background = [1, 1, 1]
try:
    view.UseColorPaletteForBackground = 0
except AttributeError:
    pass

fluid = OpenFOAMReader(FileName=foam, SkipZeroTime=0)
fluid.MeshRegions = ['internalMesh', 'patch/bed']
fluid.CellArrays = ['U', 'alpha.water', 'voidfraction']
RenameSource('fluid', fluid)
t0 = min(fluid.TimestepValues)
fluid.UpdatePipeline(t0)
view.ViewTime = t0                 # a time with the cloud (not 0)

mesh = ExtractBlock(Input=fluid)
mesh.Selectors = ['/Root/internalMesh']
bedPatch = ExtractBlock(Input=fluid)
bedPatch.Selectors = ['/Root/patch/bed']
RenameSource('bed', bedPatch)
bd = Show(bedPatch, view)
bd.ColorArrayName = ['POINTS', '']
bd.DiffuseColor = bd.AmbientColor = [0.45, 0.45, 0.45]

water = Clip(Input=mesh)
water.ClipType = 'Scalar'
water.Scalars = ['POINTS', 'alpha.water']
water.Value = 0.5
water.Invert = 0
RenameSource('water', water)
wd = Show(water, view)
ColorBy(wd, ('POINTS', 'U', 'Magnitude'))
WATER = [(0.0, 0.80, 0.90, 0.98), (0.4, 0.42, 0.68, 0.88),
         (0.75, 0.13, 0.40, 0.72), (1.0, 0.03, 0.15, 0.42)]
wd.LookupTable = colours('U', WATER, 1.5)
wd.Opacity = 0.35
wd.SetScalarBarVisibility(view, True)

surface = Contour(Input=mesh)
surface.ContourBy = ['POINTS', 'alpha.water']
surface.Isosurfaces = [0.5]
RenameSource('surface', surface)
sd = Show(surface, view)
sd.ColorArrayName = ['POINTS', '']
sd.DiffuseColor = sd.AmbientColor = [0.03, 0.15, 0.42]
sd.Opacity = 0.5

cloud = OpenFOAMReader(FileName=foam, SkipZeroTime=0)
cloud.MeshRegions = ['lagrangian/demParticles']
cloud.UpdatePipeline(t0)
cloud.LagrangianArrays = ['d', 'U', 'F', 'omega', 'id', 'type']
RenameSource('demParticles', cloud)
grains = Glyph(Input=cloud, GlyphType='Sphere')
grains.ScaleArray = ['POINTS', 'd']
grains.ScaleFactor = 1.0           # sphere of diameter d
grains.OrientationArray = ['POINTS', 'No orientation array']
grains.GlyphMode = 'All Points'
grains.GlyphType.ThetaResolution = 16
grains.GlyphType.PhiResolution = 12
RenameSource('grains', grains)
gd = Show(grains, view)
ColorBy(gd, ('POINTS', 'U', 'Magnitude'))
# the particle U has its own map: sand at rest, red when fast
gd.LookupTable = colours('grainU', [(0.0, 0.80, 0.70, 0.52),
                                    (0.3, 0.96, 0.60, 0.16),
                                    (0.65, 0.84, 0.14, 0.10),
                                    (1.0, 0.45, 0.02, 0.10)], 0.5)
gd.SetScalarBarVisibility(view, True)
colours('U', WATER, 1.5)           # ColorBy of the grains rescaled it
for lut, title, pos in ((gd.LookupTable, 'grain speed (m/s)', [0.40, 0.05]),
                        (wd.LookupTable, 'water speed (m/s)', [0.85, 0.05])):
    bar = GetScalarBar(lut, view)
    bar.Title, bar.ComponentTitle = title, ''
    bar.WindowLocation = 'Any Location'
    bar.Position = pos
    bar.Orientation = 'Horizontal'
    bar.ScalarBarLength = 0.25
    bar.TitleFontSize = bar.LabelFontSize = 12
    bar.RangeLabelFormat = '%-#.2g'
    bar.TitleColor = bar.LabelColor = [0, 0, 0]

chains = series(case, 'forceChain')
if chains:
    fc = OpenDataFile(chains)
    RenameSource('forceChain', fc)
    fd = Show(fc, view)
    ColorBy(fd, ('CELLS', 'force', 'Magnitude'))
    fd.LookupTable = GetColorTransferFunction('force')
    fd.LookupTable.ApplyPreset('Inferno (matplotlib)', True)
    fd.LookupTable.AutomaticRescaleRangeMode = 'Never'
    fd.LookupTable.RescaleTransferFunction(0.0, 2.0)
    fd.LineWidth = 3
    fd.RenderLinesAsTubes = 1
    Hide(fc, view)

# look across the flume, up against gravity, framed on the dam (after a
# first render: that one resets the camera)
Render(view)
text = open(os.path.join(case, 'constant', 'g')).read()
g = [float(v) for v in re.search(r'value\s*\(([^)]*)\)', text).group(1).split()]
n = math.sqrt(sum(v*v for v in g))
up = [-v/n for v in g]
merged = MergeBlocks(Input=cloud)
merged.UpdatePipeline(t0)
data = servermanager.Fetch(merged)
if data.GetNumberOfPoints():
    b = data.GetBounds()
else:
    b = fluid.GetDataInformation().GetBounds()
cx, cz = 0.5*(b[0] + b[1]), 0.5*(b[4] + b[5])
view.CameraFocalPoint = [cx, 0.05, cz]
view.CameraPosition = [cx, -8.0, cz]
view.CameraViewUp = up
view.CameraParallelProjection = 1
view.CameraParallelScale = 0.45*(b[1] - b[0])
scene = GetAnimationScene()
scene.UpdateAnimationUsingDataTimeSteps()
scene.AnimationTime = t0
Render(view)
shot = os.environ.get('BREACH_SCREENSHOT')
if shot:
    view.ViewSize = [1200, 500]
    SaveScreenshot(shot, view)
