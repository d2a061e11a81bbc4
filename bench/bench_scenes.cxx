#include "bench/bench_scenes.h"

#include "bench/flange_mesh.h"
#include "core/error.h"
#include "core/frame.h"
#include "vtkpasses/mesh/BrushingModel.h"
#include "vtkpasses/mesh/BuiltinMeshes.h"
#include "vtkpasses/mesh/GeometryAccess.h"
#include "vtkpasses/mesh/MeshValidation.h"
#include "vtkpasses/mesh/SurfacePreparation.h"
#include "vtkpasses/render/RendererMatrices.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <vtkActor.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

namespace aniso::bench
{
BenchMesh makeBenchMesh(const std::string& name)
{
  BenchMesh mesh;
  mesh.name = name;
  if (name == "sphere")
  {
    mesh.surface = makeSphere();
  }
  else if (name == "torus")
  {
    mesh.surface = makeTorus();
    mesh.view.direction = viewDirectionFromAngles(30.0, 35.0);
  }
  else if (name == "flange")
  {
    SurfaceOptions options;
    options.brushing = parseBrushingModel("around:0,0,1");
    MeshReport report;
    const auto clean = sanitizeSurface(makeFlange(), "flange", report);
    mesh.surface = prepareSurface(clean, options, "flange").polyData;
    mesh.view.direction = viewDirectionFromAngles(30.0, 40.0);
  }
  else
  {
    throw errorAbout(name, "unknown benchmark mesh (sphere, torus or flange)");
  }
  mesh.triangles = triangleMesh(mesh.surface);
  return mesh;
}

glm::dmat4 viewClipToWorld(const BenchMesh& mesh, int width, int height)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(mesh.surface);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(width, height);
  window->AddRenderer(renderer);
  glm::dvec3 centre;
  double radius = 0.0;
  boundingSphere(mesh.surface, centre, radius);
  applyCamera(renderer, placeCamera(mesh.view, centre, radius));
  return clipToWorld(renderer);
}

std::vector<std::string> benchEnvironments(const std::string& directory)
{
  std::vector<std::string> specs{"builtin:studio"};
  std::error_code ec;
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(directory, ec))
  {
    if (entry.path().extension() == ".exr")
    {
      files.push_back(entry.path().string());
    }
  }
  std::sort(files.begin(), files.end());
  specs.insert(specs.end(), files.begin(), files.end());
  return specs;
}

std::string environmentName(const std::string& spec)
{
  if (spec.rfind("builtin:", 0) == 0)
  {
    return spec;
  }
  return std::filesystem::path(spec).stem().string();
}

std::vector<AsLobe> benchLobes()
{
  return {{10.0, 10.0}, {100.0, 10.0}, {1000.0, 100.0}, {20000.0, 70.0}};
}

VtkPbrMaterial vtkPbrFor(const AsLobe& lobe, const glm::dvec3& f0)
{
  const double alphaT = std::sqrt(2.0 / (lobe.nu + 2.0));
  const double alphaB = std::sqrt(2.0 / (lobe.nv + 2.0));
  const double rough = std::max(alphaT, alphaB);
  const double sharp = std::min(alphaT, alphaB);
  VtkPbrMaterial m;
  m.baseColor = f0;
  // ggxLobeFromVtk: alpha = r^2 / aspect along the (rotated) tangent, r^2 aspect across it,
  // aspect = sqrt(1 - 0.9 a).
  m.roughness = std::clamp(std::pow(rough * sharp, 0.25), 0.0, 1.0);
  m.anisotropy = std::clamp((1.0 - sharp / rough) / 0.9, 0.0, 1.0);
  m.rotation = alphaT >= alphaB ? 0.0 : 0.25;
  return m;
}

GgxLobe vtkGgxLobe(const VtkPbrMaterial& material)
{
  return ggxLobeFromVtk(material.roughness, material.anisotropy);
}

double vtkTangentRotation(const VtkPbrMaterial& material)
{
  return 2.0 * M_PI * material.rotation;
}
} // namespace aniso::bench
