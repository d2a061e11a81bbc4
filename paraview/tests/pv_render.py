# Run by pvbatch (alone or under mpirun), or by pvpython as the client of a pvserver: draws a
# mesh file with the plugin's "Aniso Surface" representation and saves the composited image. The
# camera is `aniso render --view -y`'s (vtkpasses/render/ViewSettings.cxx: the bounding sphere,
# its radius times 1.1 filling half the 30-degree view's height), so the two images can be
# compared pixel by pixel.
#   pvbatch pv_render.py PLUGIN MESH.vtp OUT.png SIZE SAMPLES [redistribute] [LIBRARY NAME]
#   pvpython pv_render.py PLUGIN MESH.vtp OUT.png SIZE SAMPLES connect=PORT [redistribute] [...]
# As a client it loads the plugin on both sides, renders on the server (remote rendering for any
# size of data: the server's ranks draw and composite, the client shows their image) and checks
# that ParaView did render there.
import math
import os
import sys

# pvpython (python3-paraview, unpacked beside the build where python3-vtk9 is installed) puts
# the system's dist-packages, with VTK 9.1's vtkmodules, before PYTHONPATH: ParaView's modules
# first (pvbatch does not need this).
sys.path[:0] = [p for p in os.environ.get("PYTHONPATH", "").split(os.pathsep) if p]

from paraview import servermanager
from paraview.simple import (Connect, GetActiveViewOrCreate, GetSettingsProxy, LoadPlugin,
                             ProcessIdScalars, RedistributeDataSet, Render, SaveScreenshot, Show,
                             XMLPolyDataReader)
from paraview.vtk.util import numpy_support  # noqa: F401 (numpy is what the bounds use)
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

plugin, mesh, out, size, samples = sys.argv[1:6]
rest = sys.argv[6:]
port = None
if rest and rest[0].startswith("connect="):
    port = int(rest[0][len("connect="):])
    rest = rest[1:]
redistribute = bool(rest) and rest[0] == "redistribute"
if redistribute:
    rest = rest[1:]
if port is not None:
    Connect("localhost", port)
    # The server's ranks draw; the client needs the plugin's proxies (and could draw too).
    LoadPlugin(plugin, remote=True, ns=globals())
    # Remote rendering whatever the data's size (ParaView delivers small data to the client and
    # draws it there otherwise).
    GetSettingsProxy("RenderViewSettings").RemoteRenderThreshold = 0.0
LoadPlugin(plugin, remote=False, ns=globals())

# The bounding sphere as the application computes it: the bounds' centre, the farthest point.
whole = vtkXMLPolyDataReader()
whole.SetFileName(mesh)
whole.Update()
poly = whole.GetOutput()
b = poly.GetBounds()
centre = [0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5])]
points = numpy_support.vtk_to_numpy(poly.GetPoints().GetData())
radius = float(((points - centre) ** 2).sum(axis=1).max() ** 0.5)

reader = XMLPolyDataReader(FileName=[mesh])
source = RedistributeDataSet(Input=reader) if redistribute else reader
view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [int(size), int(size)]
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.Background = [0.0, 0.0, 0.0]
# ParaView smooths edges with FXAA by default, a pass after the material; `aniso render` samples
# pixel centres (no jitter): the comparison is of the material, without it.
view.UseFXAA = 0
display = Show(source, view)
display.Representation = "Aniso Surface"
display.AnisoSamples = int(samples)
if rest:
    display.AnisoMaterialLibrary = rest[0]
    display.AnisoMaterialName = rest[1]

# paraview.simple resets the camera on a view's first render: the camera is set after it.
Render(view)
distance = radius * 1.1 / math.sin(math.radians(15.0))
view.CameraFocalPoint = centre
view.CameraPosition = [centre[0], centre[1] - distance, centre[2]]
view.CameraViewUp = [0.0, 0.0, 1.0]
view.CameraViewAngle = 30.0
view.CameraParallelProjection = 0
Render(view)
display.UpdatePropertyInformation()
status = display.GetPropertyValue("AnisoStatus")
if status:
    raise SystemExit("pv_render.py: the material reports: " + status)
SaveScreenshot(out, view, ImageResolution=[int(size), int(size)])
if port is not None:
    ranks = servermanager.ActiveConnection.GetNumberOfDataPartitions()
    if not view.GetClientSideObject().GetUseDistributedRenderingForRender():
        raise SystemExit("pv_render.py: the client drew the image, not the server")
    print("pv_render.py: rendered by the server")
else:
    ranks = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
if redistribute and port is not None:
    # The client holds no piece: the ranks' ids on the points say where the points are.
    ids = ProcessIdScalars(Input=source)
    low, high = ids.PointData["ProcessId"].GetRange()
    print("pv_render.py: the points lie on ranks %d to %d" % (low, high))
    if ranks > 1 and not (low == 0 and high == ranks - 1):
        raise SystemExit("pv_render.py: the points are not spread over the ranks")
elif redistribute:
    # Each rank holds a partition: the piece rank 0 draws (what Fetch gives pvbatch's root) is
    # a part of the whole, whose size ParaView gathers from every rank.
    local = servermanager.Fetch(source).GetNumberOfPoints()
    total = source.GetDataInformation().GetNumberOfPoints()
    print("pv_render.py: rank 0 holds %d of %d points" % (local, total))
    if ranks > 1 and not 0 < local < total:
        raise SystemExit("pv_render.py: rank 0 holds all or none of the points: not partitioned")
print("pv_render.py: %d rank(s), wrote %s" % (ranks, out))
