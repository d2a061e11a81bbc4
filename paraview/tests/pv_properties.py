# Run by pvbatch: the plugin loads in ParaView's Python, offers "Aniso Surface" wherever Surface
# is offered, exposes every material property with the application's defaults, and reports an
# invalid value as an error naming the property while the previous value stays in force.
#   pvbatch pv_properties.py PLUGIN
import sys

from paraview.simple import (GetActiveViewOrCreate, LoadPlugin, Render, Show, Sphere,
                             Wavelet)

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

if failures:
    raise SystemExit("pv_properties.py:\n  " + "\n  ".join(failures))
print("pv_properties.py: %d properties, errors reported by name" % (len(expected) + 3))
