// Every program the materials draw with is valid GLSL of its #version by the Khronos reference
// compiler (glslangValidator, Debian's glslang-tools, which the set-up installs), not only by the
// driver the suite runs on. Mesa accepts what the specification does not: material_fs_dec.glsl
// continued preprocessor conditions over two lines with a backslash, which GLSL has only from
// 4.20 (the programs are #version 150), and a driver that keeps to the specification would have
// refused the material (vtkAnisoPolyDataMapper.h: the actor then falls back to VTK's shading).
//
// Each variant is drawn once (16 x 16, one frame) through renderOffscreen with its material
// installed by the test, which observes the actor's mapper: the vertex, geometry and fragment
// sources of every program the actor drew with, as the driver received them, are checked. The
// variants: the Ashikhmin-Shirley material's methods, half-vector sources and environment
// sampling (off, mis, sources), every map, the three field targets, line sets (pixels and world
// widths, with the sources); each lit model on a surface, two on lines; LEADR and the
// microstructure. The accumulation pass's full-screen programs are not drawn by a mapper and
// are not among them.
#include "core/image/image.h"
#include "core/leadr/leadr.h"
#include "core/lights/light.h"
#include "core/parameters/parameters.h"
#include "tests/vtkpasses/render/render_test_helpers.h"
#include "vtkpasses/mesh/BuiltinMeshes.h"
#include "vtkpasses/mesh/LineSet.h"
#include "vtkpasses/mesh/MeshValidation.h"
#include "vtkpasses/render/AnisoMaterial.h"
#include "vtkpasses/render/EnvironmentLighting.h"
#include "vtkpasses/render/LitModelMaterial.h"
#include "vtkpasses/render/OffscreenRenderer.h"
#include "vtkpasses/render/SurfaceModelSettings.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iostream>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <unistd.h>
#include <vector>
#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkMapper.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkShader.h>
#include <vtkShaderProgram.h>

namespace aniso
{
namespace
{
// The programs' sources, (stage extension, text), each distinct text once, with the variant
// that first drew it.
struct Sources
{
  std::map<std::pair<std::string, std::string>, std::string> texts;
  std::string variant;

  void add(vtkShaderProgram* program)
  {
    const std::pair<const char*, vtkShader*> stages[] = {{"vert", program->GetVertexShader()},
                                                         {"geom", program->GetGeometryShader()},
                                                         {"frag", program->GetFragmentShader()}};
    for (const auto& [extension, shader] : stages)
    {
      if (shader && !shader->GetSource().empty())
      {
        texts.emplace(std::make_pair(std::string(extension), shader->GetSource()), variant);
      }
    }
  }
};

void onUpdateShader(vtkObject*, unsigned long, void* clientData, void* callData)
{
  if (callData)
  {
    static_cast<Sources*>(clientData)->add(static_cast<vtkShaderProgram*>(callData));
  }
}

// INNER, with the actor's mapper observed for SOURCES.
MaterialInstaller observed(MaterialInstaller inner, Sources* sources)
{
  return [inner, sources](vtkActor* actor, vtkRenderer* renderer,
                          const std::shared_ptr<EnvironmentLighting>& lighting)
  {
    vtkNew<vtkCallbackCommand> command;
    command->SetCallback(onUpdateShader);
    command->SetClientData(sources);
    actor->GetMapper()->AddObserver(vtkCommand::UpdateShaderEvent, command);
    return inner(actor, renderer, lighting);
  };
}

MaterialInstaller asMaterial(const MaterialSettings& settings)
{
  return [settings](vtkActor* actor, vtkRenderer* renderer,
                    const std::shared_ptr<EnvironmentLighting>& lighting) -> std::shared_ptr<void>
  {
    auto material = std::make_shared<AnisoMaterial>(lighting, settings);
    material->apply(actor, renderer);
    return material;
  };
}

std::shared_ptr<const Image> image(int channels, float value)
{
  auto map = std::make_shared<Image>(4, 4, channels);
  for (float& v : map->data)
  {
    v = value;
  }
  return map;
}

// The sphere with a point array "temperature" (its z), for the fields.
vtkSmartPointer<vtkPolyData> sphereWithTemperature()
{
  vtkSmartPointer<vtkPolyData> sphere = makeSphere(32, 16);
  vtkNew<vtkDoubleArray> temperature;
  temperature->SetName("temperature");
  temperature->SetNumberOfTuples(sphere->GetNumberOfPoints());
  for (vtkIdType i = 0; i < sphere->GetNumberOfPoints(); ++i)
  {
    temperature->SetValue(i, sphere->GetPoint(i)[2]);
  }
  sphere->GetPointData()->AddArray(temperature);
  return sphere;
}

// A helix as a line set, through the loader's own sanitising (tangents along it).
vtkSmartPointer<vtkPolyData> helixLines()
{
  vtkNew<vtkPolyData> raw;
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  const int n = 64;
  lines->InsertNextCell(n);
  for (int i = 0; i < n; ++i)
  {
    const double a = 0.3 * i;
    lines->InsertCellPoint(points->InsertNextPoint(std::cos(a), std::sin(a), -1.0 + 2.0 * i / n));
  }
  raw->SetPoints(points);
  raw->SetLines(lines);
  MeshReport report;
  return sanitizeLines(raw, "helix", report);
}

class ShaderPortability : public ::testing::Test
{
protected:
  Sources sources;
  int drawn = 0;

  RenderSettings scene(vtkSmartPointer<vtkPolyData> surface,
                       std::shared_ptr<const Environment> environment)
  {
    RenderSettings s;
    s.surface = std::move(surface);
    s.environment = std::move(environment);
    s.cubeSize = 16;
    s.width = s.height = 16;
    s.frames = 1;
    s.jitter = false;
    s.display.legend = false;
    return s;
  }

  void draw(const std::string& variant, RenderSettings s, const MaterialInstaller& installer)
  {
    sources.variant = variant;
    if (!s.parts.empty())
    {
      for (RenderPart& part : s.parts)
      {
        part.installMaterial = observed(installer, &sources);
      }
    }
    else
    {
      s.installMaterial = observed(installer, &sources);
    }
    const std::size_t before = sources.texts.size();
    try
    {
      renderOffscreen(s);
    }
    catch (const std::exception& e)
    {
      ADD_FAILURE() << variant << ": " << e.what();
      return;
    }
    EXPECT_GT(sources.texts.size(), before) << variant << ": no program of its own was observed";
    ++drawn;
  }

  void drawAs(const std::string& variant, vtkSmartPointer<vtkPolyData> surface,
              std::shared_ptr<const Environment> environment, const MaterialSettings& material)
  {
    draw(variant, scene(std::move(surface), std::move(environment)), asMaterial(material));
  }

  RenderSettings lineScene(std::shared_ptr<const Environment> environment, LineStyle style)
  {
    RenderSettings s = scene(nullptr, std::move(environment));
    RenderPart part;
    part.name = "helix";
    part.surface = helixLines();
    part.lineStyle = style;
    s.parts = {part};
    return s;
  }
};

TEST_F(ShaderPortability, EveryVariantIsValidGlslForTheReferenceCompiler)
{
  ANISO_REQUIRE_DISPLAY();
  ASSERT_EQ(std::system("glslangValidator --version > /dev/null 2>&1"), 0)
      << "glslangValidator (glslang-tools) is missing: scripts/setup.sh installs it";

  const auto studio = openEnvironment("builtin:studio");
  const auto sunsky = openEnvironment("builtin:sunsky");
  const auto sphere = makeSphere(32, 16);

  // The Ashikhmin-Shirley material.
  MaterialSettings m;
  drawAs("exact, filtered, LUT", sphere, studio, m);
  {
    MaterialSettings v = m;
    v.method = SpecularMethod::SplitSum;
    v.filtered = false;
    v.halfVectors = HalfVectorSource::Shader;
    v.albedo = glm::dvec3(0.2);
    drawAs("split sum, unfiltered, half vectors in the shader, diffuse", sphere, studio, v);
  }
  {
    MaterialSettings v = m;
    v.environmentSampling = EnvironmentSampling::Mis;
    drawAs("mis", sphere, studio, v);
    v.filtered = false;
    v.halfVectors = HalfVectorSource::Shader;
    drawAs("mis, unfiltered, half vectors in the shader", sphere, studio, v);
  }
  {
    MaterialSettings v = m;
    v.environmentSampling = EnvironmentSampling::Sources;
    drawAs("sources", sphere, sunsky, v);
    v.sourceSamples = 8;
    v.filtered = false;
    drawAs("sources, counted, unfiltered", sphere, sunsky, v);
  }
  {
    MaterialSettings v = m;
    v.normalMap = image(3, 0.0f);
    v.heightMap = image(1, 0.5f);
    v.albedoMap = image(3, 0.5f);
    v.occlusionMap = image(1, 1.0f);
    v.metallicMap = image(1, 1.0f);
    v.albedo = glm::dvec3(0.3);
    drawAs("normal, height, albedo, occlusion and metallic maps", sphere, studio, v);
    MaterialSettings q = m;
    q.quaternionMap = image(3, 0.0f);
    drawAs("quaternion map", sphere, studio, q);
    MaterialSettings t = m;
    t.tprMap = image(2, 0.5f);
    t.environmentSampling = EnvironmentSampling::Mis;
    drawAs("tpr map, mis", sphere, studio, t);
  }
  for (const FieldTarget target :
       {FieldTarget::Albedo, FieldTarget::F0, FieldTarget::Roughness, FieldTarget::Anisotropy})
  {
    MaterialSettings v = m;
    FieldMapping field;
    field.spec.array = "temperature";
    field.target = target;
    field.range = FieldRange{false, -1.0, 1.0};
    v.field = field;
    v.albedo = glm::dvec3(0.2);
    if (target == FieldTarget::Roughness)
    {
      v.environmentSampling = EnvironmentSampling::Sources;
    }
    drawAs("field, target " + std::to_string(int(target)), sphereWithTemperature(),
           target == FieldTarget::Roughness ? sunsky : studio, v);
  }
  {
    MaterialSettings v = m;
    draw("lines, pixels", lineScene(studio, LineStyle{3.0, LineWidthUnit::Pixels}), asMaterial(v));
    v.environmentSampling = EnvironmentSampling::Sources;
    draw("lines, world width, sources", lineScene(sunsky, LineStyle{0.05, LineWidthUnit::World}),
         asMaterial(v));
  }

  // The lit models, on a surface and on lines.
  for (const LitModel model : {LitModel::AshikhminShirley, LitModel::Banks, LitModel::BlinnPhong,
                               LitModel::Ward, LitModel::HeidrichSeidel})
  {
    LitModelSettings lit;
    lit.model = model;
    lit.lights = {parseLight("dir:-1,-2,1.5:1,1,1")};
    draw("lit model " + std::to_string(int(model)), scene(sphere, studio), litModelInstaller(lit));
    if (model == LitModel::AshikhminShirley || model == LitModel::Banks)
    {
      // The line variant's code is the model's with the line's frame: two models show it.
      draw("lit model " + std::to_string(int(model)) + ", lines",
           lineScene(studio, LineStyle{0.05, LineWidthUnit::World}), litModelInstaller(lit));
    }
  }

  // LEADR and the microstructure, from their declared defaults.
  const ParameterSet defaults;
  const DeclaredValues values = [&defaults](std::string_view key) -> const ParameterValue&
  { return defaults.value(key); };
  SurfaceModelInputs inputs;
  inputs.lights = [] { return std::vector<Light>{parseLight("dir:-1,-2,1.5:1,1,1")}; };
  inputs.tprMap = []() -> std::shared_ptr<const Image> { return nullptr; };
  inputs.leadrMoments = []
  { return std::make_shared<const LeadrMips>(bakeLeadrFromHeight(builtinLeadrRelief(), 1.0)); };
  for (const char* model : {"leadr", "microstructure"})
  {
    draw(model, scene(sphere, studio), surfaceModelInstaller(model, values, inputs));
  }
  ASSERT_EQ(drawn, 24);

  // Each distinct source through the reference compiler, which tells the stage by the file's
  // extension.
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("aniso-shader-portability-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  int index = 0;
  int rejected = 0;
  for (const auto& [key, variant] : sources.texts)
  {
    const std::filesystem::path file = dir / (std::to_string(index++) + "." + key.first);
    std::ofstream(file) << key.second;
    const std::string command = "glslangValidator " + file.string() + " 2>&1";
    std::string output;
    FILE* pipe = ::popen(command.c_str(), "r");
    ASSERT_NE(pipe, nullptr);
    char buffer[512];
    while (std::fgets(buffer, sizeof buffer, pipe))
    {
      output += buffer;
    }
    const int status = ::pclose(pipe);
    if (status != 0)
    {
      ++rejected;
      ADD_FAILURE() << variant << ", " << key.first << " shader (kept as " << file.string()
                    << "):\n"
                    << output;
    }
  }
  EXPECT_EQ(rejected, 0);
  if (rejected == 0)
  {
    std::filesystem::remove_all(dir);
  }
  std::cout << sources.texts.size() << " distinct shader sources of " << drawn
            << " variants checked\n";
}
} // namespace
} // namespace aniso
