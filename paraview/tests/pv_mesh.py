# Run by pvbatch: writes a mesh with ParaView's own sources and its XML writer (an independent
# writer of the file both ParaView and `aniso render` then draw).
#   pvbatch pv_mesh.py sphere|sphere-uv|contour OUT.vtp
import sys

from paraview.simple import (Contour, ExtractSurface, GenerateSurfaceNormals, SaveData, Sphere,
                             TextureMaptoSphere, Wavelet)

kind, out = sys.argv[1], sys.argv[2]
if kind == "sphere":
    # The sphere source's own analytic normals.
    source = Sphere(Radius=0.5, ThetaResolution=96, PhiResolution=48)
elif kind == "sphere-uv":
    # With texture coordinates, for maps: ParaView's spherical mapping (its seam kept out).
    source = TextureMaptoSphere(Input=Sphere(Radius=0.5, ThetaResolution=96, PhiResolution=48),
                                PreventSeam=1)
elif kind == "contour":
    # A larger surface: an isosurface of the wavelet, its normals by ParaView's filter.
    wavelet = Wavelet(WholeExtent=[-40, 40, -40, 40, -40, 40])
    contour = Contour(Input=wavelet, ContourBy=["POINTS", "RTData"], Isosurfaces=[150.0],
                      ComputeNormals=0)
    source = GenerateSurfaceNormals(Input=ExtractSurface(Input=contour))
else:
    raise SystemExit("pv_mesh.py: unknown mesh kind " + kind)
SaveData(out, proxy=source, DataMode="Binary")
