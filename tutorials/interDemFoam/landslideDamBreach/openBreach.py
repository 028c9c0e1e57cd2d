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
import os
import re
import sys

from paraview.simple import (ColorBy, GetActiveViewOrCreate,
                             GetAnimationScene, GetColorTransferFunction,
                             OpenDataFile, RenameSource, Render,
                             SaveScreenshot, Show, Hide, ExtractBlock)

# the helpers shared with the other tutorials' ParaView scripts:
# bin/pvhelpers.py ($INTERDEMFOAM_DIR's, else three folders above this
# script; ParaView's --script may run it without __file__: then the case's
# parent folder is the tutorial)
_here = os.path.dirname(os.path.abspath(__file__)) if '__file__' in globals() \
    else os.path.join(os.getcwd(), '..')
sys.path.insert(0, os.path.join(
    os.environ.get('INTERDEMFOAM_DIR') or os.path.join(_here, '..', '..', '..'),
    'bin'))
import pvhelpers as pv  # noqa: E402


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


def series(case, stem):
    """post/<stem>.vtk.series: the DEM's VTK dumps on the CFD time line"""
    dt = pv.dem_step(case)
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


case = find_case()
foam = pv.foam_file(case)
view = GetActiveViewOrCreate('RenderView')
view.OrientationAxesVisibility = 1
pv.white_background(view)

fluid = pv.open_fluid(foam, ['internalMesh', 'patch/bed'],
                      ['U', 'alpha.water', 'voidfraction'])
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
bd.DiffuseColor = bd.AmbientColor = list(pv.BED_COLOUR)

water = pv.water_clip(mesh)
RenameSource('water', water)
wd = Show(water, view)
ColorBy(wd, ('POINTS', 'U', 'Magnitude'))
wd.LookupTable = pv.lut('U', pv.WATER_MAP, 0, 1.5)
wd.Opacity = 0.35
wd.SetScalarBarVisibility(view, True)

surface = pv.free_surface(mesh)
RenameSource('surface', surface)
sd = Show(surface, view)
sd.ColorArrayName = ['POINTS', '']
sd.DiffuseColor = sd.AmbientColor = pv.SURFACE_COLOUR
sd.Opacity = 0.5

cloud = pv.open_cloud(foam, t0, ['d', 'U', 'F', 'omega', 'id', 'type'])
RenameSource('demParticles', cloud)
grains = pv.sphere_glyphs(cloud)
RenameSource('grains', grains)
gd = Show(grains, view)
ColorBy(gd, ('POINTS', 'U', 'Magnitude'))
# the particle U has its own map: sand at rest, red when fast
gd.LookupTable = pv.lut('grainU', pv.GRAIN_MAP, 0, 0.5)
gd.SetScalarBarVisibility(view, True)
pv.lut('U', pv.WATER_MAP, 0, 1.5)  # ColorBy of the grains rescaled it
for lut, title, pos in ((gd.LookupTable, 'grain speed (m/s)', [0.40, 0.05]),
                        (wd.LookupTable, 'water speed (m/s)', [0.85, 0.05])):
    pv.scalar_bar(lut, view, title, WindowLocation='Any Location',
                  Position=pos, Orientation='Horizontal',
                  ScalarBarLength=0.25, TitleFontSize=12, LabelFontSize=12,
                  RangeLabelFormat='%-#.2g')

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
up = pv.gravity_up(case)
data = pv.merged(cloud, t0)
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
