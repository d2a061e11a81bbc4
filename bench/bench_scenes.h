#pragma once
// The benchmark's fixed scene set: meshes with their views, environments, and the materials
// (n_u, n_v), plus the VTK physically based material standing for each of them.
#include "bench/render_session.h"
#include "core/brdf/ashikhmin_shirley.h"
#include "core/brdf/ggx.h"
#include "vtkpasses/mesh/TriangleArrays.h"
#include "vtkpasses/render/ViewSettings.h"

#include <cstdint>
#include <string>
#include <vector>
#include <vtkSmartPointer.h>

class vtkPolyData;

namespace aniso::bench
{
struct BenchMesh
{
  std::string name;                     // "sphere", "torus", "flange"
  vtkSmartPointer<vtkPolyData> surface; // prepared: "Normals", "Tangents"
  ViewSettings view;
  TriangleMesh triangles; // the same surface for the CPU rays
};

// "sphere" (the built-in sphere, front view), "torus" (the built-in torus from azimuth 30,
// elevation 35: the application's default view), "flange" (makeFlange with tangents
// around:0,0,1, from azimuth 30, elevation 40). Throws aniso::Error for another name.
BenchMesh makeBenchMesh(const std::string& name);


// Where the Blender CC0 studio-light HDRIs are installed (blender-data).
constexpr const char* kBlenderHdriDirectory = "/usr/share/blender/datafiles/studiolights/world";
// "builtin:studio", then the .exr files of DIRECTORY (sorted), if it exists.
std::vector<std::string> benchEnvironments(const std::string& directory = kBlenderHdriDirectory);
// "builtin:studio" as it is, or a file's stem ("forest"; Blender's own studio.exr is "studio").
std::string environmentName(const std::string& spec);

// The image side of the full run and of the quick one (BenchOptions::size 0).
constexpr int kFullImageSize = 256;
constexpr int kQuickImageSize = 128;
// The references of the HDRI scenes of the full run (the sphere, front view): pixels compared
// (selectPixels), the integrator's relative tolerance and its budget per pixel. The budget
// allows level 8 (2^26 stops at level 7, where the worst pixels of city (20000, 70), interior
// and night (10, 10) and night (100, 10) had not converged: tests/bench/test_reference_image).
constexpr int kHdriReferencePixels = 256;
constexpr double kHdriReferenceTolerance = 3e-3;
constexpr uint64_t kHdriReferenceMaxEvaluations = 1ull << 28;

// What the CPU casts its pixel rays through for MESH's view in a width x height image: the
// inverse of the matrix the mappers draw with (clipToWorld of a renderer holding the surface,
// its camera placed as RenderSession::setSurface places it). Needs no X display: nothing is
// drawn.
glm::dmat4 viewClipToWorld(const BenchMesh& mesh, int width, int height);

// The materials of the benchmark: (10, 10), (100, 10), (1000, 100), (20000, 70).
std::vector<AsLobe> benchLobes();

// VTK's material standing for an Ashikhmin-Shirley lobe: each exponent n taken to the GGX
// roughness alpha = sqrt(2 / (n + 2)) (the Beckmann width of a Phong lobe of exponent n), then
// VTK's roughness r and anisotropy a chosen so that ggxLobeFromVtk(r, a) gives these alphas
// (r^2 their geometric mean, a from their ratio, clamped to VTK's [0, 1]), the anisotropy turned
// to the rougher direction (rotation 0 along t, 0.25 along b).
VtkPbrMaterial vtkPbrFor(const AsLobe& lobe, const glm::dvec3& f0);
// The GGX lobe VTK renders for that material (ggxLobeFromVtk) and its tangent rotation, radians.
GgxLobe vtkGgxLobe(const VtkPbrMaterial& material);
double vtkTangentRotation(const VtkPbrMaterial& material);
} // namespace aniso::bench
