# Run by pvpython (or pvbatch): the plugin loads in ParaView's Python, offers "Aniso Surface"
# wherever Surface is offered, exposes every material property with the application's defaults,
# and reports an invalid value as an error naming the property while the previous value stays in
# force.
#   pvpython pv_properties.py PLUGIN
import json
import os
import sys
import tempfile

# pvpython (python3-paraview, unpacked beside the build where python3-vtk9 is installed) puts
# the system's dist-packages, with VTK 9.1's vtkmodules, before PYTHONPATH: ParaView's modules
# first.
sys.path[:0] = [p for p in os.environ.get("PYTHONPATH", "").split(os.pathsep) if p]

from paraview.simple import (GetActiveViewOrCreate, LoadPlugin, Render, Show, Sphere,
                             Wavelet)
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOImage import vtkPNGWriter

LoadPlugin(sys.argv[1], remote=False, ns=globals())
failures = []

view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [64, 64]
for source in (Sphere(), Wavelet()):
    display = Show(source, view)
    if "Aniso Surface" not in display.GetProperty("Representation").Available:
        failures.append("%s: no Aniso Surface representation" % source.GetXMLName())

display = Show(Sphere(), view)
display.Representation = "Aniso Surface"
expected = {
    "AnisoRoughnessU": 1000.0, "AnisoRoughnessV": 50.0, "AnisoSamples": 16,
    "AnisoTangents": "auto", "AnisoMethod": "exact", "AnisoEnvironmentSampling": "auto",
    "AnisoEnvironment": "builtin:studio", "AnisoEnvironmentRotation": 0.0, "AnisoExposure": 0.0,
    "AnisoToneMapping": "aces", "AnisoMaterialLibrary": "", "AnisoMaterialName": "",
}
for name, value in expected.items():
    got = display.GetPropertyValue(name)
    if got != value:
        failures.append("%s: %r, expected %r" % (name, got, value))
for name in ("AnisoReflectance", "AnisoAlbedo"):
    if len(display.GetPropertyValue(name)) != 3:
        failures.append("%s: not an RGB triple" % name)

Render(view)
display.UpdatePropertyInformation()
if display.GetPropertyValue("AnisoStatus"):
    failures.append("valid defaults report: %s" % display.GetPropertyValue("AnisoStatus"))

# Out of range, an unknown word, a file that does not exist: each named in the status.
for name, value, word in (("AnisoRoughnessU", -5.0, "AnisoRoughnessU"),
                          ("AnisoToneMapping", "sepia", "AnisoToneMapping"),
                          ("AnisoTangents", "around:0,0,0", "AnisoTangents"),
                          ("AnisoEnvironment", "/nonexistent/sky.exr", "/nonexistent/sky.exr")):
    before = display.GetPropertyValue(name)
    setattr(display, name, value)
    Render(view)
    display.UpdatePropertyInformation()
    status = display.GetPropertyValue("AnisoStatus")
    print("pv_properties.py: %s = %r: %s" % (name, value, status))
    if word not in status:
        failures.append("%s = %r: the status '%s' does not name %s" % (name, value, status, word))
    setattr(display, name, before)
    Render(view)
    display.UpdatePropertyInformation()
    if display.GetPropertyValue("AnisoStatus"):
        failures.append("%s restored: still reports '%s'" % (name,
                                                             display.GetPropertyValue("AnisoStatus")))

# A library material whose map file is missing: the status names the file. One whose map reads,
# on a sphere without texture coordinates: drawn without it, and the status says why.
with tempfile.TemporaryDirectory() as directory:
    flat = vtkImageData()
    flat.SetDimensions(2, 2, 1)
    flat.AllocateScalars(3, 3)  # VTK_UNSIGNED_CHAR, RGB
    flat.GetPointData().GetScalars().Fill(128)
    writer = vtkPNGWriter()
    writer.SetFileName(os.path.join(directory, "grey.png"))
    writer.SetInputData(flat)
    writer.Write()
    library = os.path.join(directory, "library.json")
    with open(library, "w", encoding="utf-8") as f:
        json.dump({"format": "aniso-materials", "version": 1, "materials": {
            "lost": {"albedo-map": "missing.png"}, "greyed": {"albedo-map": "grey.png"}}}, f)
    for name, word in (("lost", "missing.png"), ("greyed", "texture coordinates")):
        display.AnisoMaterialLibrary = library
        display.AnisoMaterialName = name
        Render(view)
        display.UpdatePropertyInformation()
        status = display.GetPropertyValue("AnisoStatus")
        print("pv_properties.py: material '%s': %s" % (name, status))
        if word not in status:
            failures.append("material '%s': the status '%s' does not say %s" % (name, status, word))
    display.AnisoMaterialLibrary = ""
    display.AnisoMaterialName = ""
    Render(view)
    display.UpdatePropertyInformation()
    if display.GetPropertyValue("AnisoStatus"):
        failures.append("no library: still reports '%s'" % display.GetPropertyValue("AnisoStatus"))

if failures:
    raise SystemExit("pv_properties.py:\n  " + "\n  ".join(failures))
print("pv_properties.py: %d properties, errors reported by name" % (len(expected) + 3))
