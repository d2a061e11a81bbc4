# Run by pvbatch, alone or under mpirun: the cost of the plugin's frame as ranks are added.
# Draws the isosurface of ParaView's wavelet (WholeExtent +-N, redistributed over the ranks) with
# the Aniso Surface representation at SIZE x SIZE and SAMPLES samples, and prints, on rank 0:
# the triangles of rank 0's piece and of the whole, the first render (the pieces prepared, the
# environment and lookup tables baked or read, the shaders compiled), and the median of RENDERS
# renders with the camera turned by 10 degrees each (shading and IceT compositing only).
#   pvbatch pv_scaling.py PLUGIN [N SIZE SAMPLES RENDERS]
import statistics
import sys
import time

from paraview import servermanager
from paraview.simple import (Contour, GetActiveCamera, GetActiveViewOrCreate, LoadPlugin,
                             RedistributeDataSet, Render, ResetCamera, Show, Wavelet)

plugin = sys.argv[1]
extent, size, samples, renders = (int(v) for v in (sys.argv[2:6] + ["60", "1024", "16", "5"]
                                                     [len(sys.argv) - 2:]))
LoadPlugin(plugin, remote=False, ns=globals())
wavelet = Wavelet(WholeExtent=[-extent, extent] * 3)
surface = Contour(Input=wavelet, ContourBy=["POINTS", "RTData"], Isosurfaces=[150.0],
                  ComputeNormals=1)
pieces = RedistributeDataSet(Input=surface)
view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [size, size]
view.UseFXAA = 0
view.OrientationAxesVisibility = 0
display = Show(pieces, view)
display.Representation = "Aniso Surface"
display.AnisoSamples = samples
pieces.UpdatePipeline()
whole = pieces.GetDataInformation().GetNumberOfCells()
local = servermanager.Fetch(pieces).GetNumberOfCells()

start = time.perf_counter()
Render(view)
ResetCamera(view)
Render(view)
first = time.perf_counter() - start
times = []
for _ in range(renders):
    GetActiveCamera().Azimuth(10.0)
    start = time.perf_counter()
    Render(view)
    times.append(time.perf_counter() - start)
ranks = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
print("pv_scaling: ranks %d, triangles %d (rank 0: %d), %dx%d, %d samples: first render %.2f s, "
      "render median %.3f s (of %d)" % (ranks, whole, local, size, size, samples, first,
                                        statistics.median(times), renders))
