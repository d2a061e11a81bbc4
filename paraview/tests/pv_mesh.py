# Run by pvbatch: writes a mesh with ParaView's own sources and its XML writer (an independent
# writer of the file both ParaView and `aniso render` then draw).
#   pvbatch pv_mesh.py sphere|sphere-uv|sphere-tangents|contour OUT.vtp
import sys

from paraview.simple import (Contour, ExtractSurface, GenerateSurfaceNormals,
                             ProgrammableFilter, SaveData, Sphere, TextureMaptoSphere, Wavelet)

# Tangents of its own for the sphere: along the meridians (across the UVs' u), except in a patch
# of the corner x, y > 0.2, z > 0.1, where they lie along the normal (invalid). `auto` then
# brushes the whole sphere from the UVs (one invalid tangent discards the field); a partition
# away from the patch brushes as the whole does only if the ranks agree.
TANGENTS = """
import numpy as np
from vtkmodules.util import numpy_support
data = self.GetPolyDataInput()
out = self.GetPolyDataOutput()
out.ShallowCopy(data)
p = numpy_support.vtk_to_numpy(data.GetPoints().GetData()).astype(np.float64)
n = p / np.linalg.norm(p, axis=1, keepdims=True)
t = np.array([0.0, 0.0, 1.0]) - n * n[:, 2:3]
length = np.linalg.norm(t, axis=1, keepdims=True)
t = np.where(length > 1e-6, t / np.maximum(length, 1e-12), np.array([1.0, 0.0, 0.0]))
patch = (p[:, 0] > 0.2) & (p[:, 1] > 0.2) & (p[:, 2] > 0.1)
t[patch] = n[patch]
tangents = numpy_support.numpy_to_vtk(t.astype(np.float32), deep=1)
tangents.SetName("Tangents")
out.GetPointData().SetTangents(tangents)
"""

kind, out = sys.argv[1], sys.argv[2]
if kind == "sphere":
    # The sphere source's own analytic normals.
    source = Sphere(Radius=0.5, ThetaResolution=96, PhiResolution=48)
elif kind == "sphere-uv":
    # With texture coordinates, for maps: ParaView's spherical mapping (its seam kept out).
    source = TextureMaptoSphere(Input=Sphere(Radius=0.5, ThetaResolution=96, PhiResolution=48),
                                PreventSeam=1)
elif kind == "sphere-tangents":
    mapped = TextureMaptoSphere(Input=Sphere(Radius=0.5, ThetaResolution=96, PhiResolution=48),
                                PreventSeam=1)
    source = ProgrammableFilter(Input=mapped, Script=TANGENTS)
elif kind == "contour":
    # A larger surface: an isosurface of the wavelet, its normals by ParaView's filter.
    wavelet = Wavelet(WholeExtent=[-40, 40, -40, 40, -40, 40])
    contour = Contour(Input=wavelet, ContourBy=["POINTS", "RTData"], Isosurfaces=[150.0],
                      ComputeNormals=0)
    source = GenerateSurfaceNormals(Input=ExtractSurface(Input=contour))
else:
    raise SystemExit("pv_mesh.py: unknown mesh kind " + kind)
SaveData(out, proxy=source, DataMode="Binary")
