// The material's shader variants and how it installs them, without an OpenGL context:
//  - a material without maps defines none of the map variants (it pays nothing for them), and
//    maps are left out, and reported, on a mesh without texture coordinates;
//  - every replacement starts with the VTK tag it replaces, so VTK's own code still goes there;
//  - slider values (n_u, n_v, F0, albedo, samples, height scale) leave the shader source as it
//    is, features (method, filtering, half-vector source, maps) change it;
//  - invalid settings are refused with the parameter's name and the previous ones kept.
#include "core/env/environment.h"
#include "core/error.h"
#include "vtkpasses/mesh/BuiltinMeshes.h"
#include "vtkpasses/render/AnisoMaterial.h"
#include "vtkpasses/render/EnvironmentLighting.h"
#include "vtkpasses/render/MaterialShaderSource.h"

#include <gtest/gtest.h>
#include <memory>
#include <string>
#include <utility>
#include <vector>
#include <vtkActor.h>
#include <vtkNew.h>
#include <vtkOpenGLPolyDataMapper.h>
#include <vtkOpenGLShaderProperty.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>

namespace aniso
{
namespace
{
bool defines(const MaterialVariant& v, const std::string& name)
{
  return variantDefines(v).find("#define " + name + "\n") != std::string::npos;
}

TEST(MaterialShaderSource, MapFreeMaterialsCompileNoMapCode)
{
  const MaterialVariant v = materialVariant(MaterialSettings{}, true, true, true);
  for (const char* map :
       {"ANISO_NORMAL_MAP", "ANISO_QUATERNION_MAP", "ANISO_TPR_MAP", "ANISO_HEIGHT_MAP",
        "ANISO_ALBEDO_MAP", "ANISO_OCCLUSION_MAP", "ANISO_METALLIC_MAP"})
  {
    EXPECT_FALSE(defines(v, map)) << map;
  }
  EXPECT_TRUE(defines(v, "ANISO_HAVE_TANGENTS"));
  EXPECT_TRUE(defines(v, "ANISO_METHOD_EXACT"));
  EXPECT_FALSE(defines(v, "ANISO_METHOD_SPLIT_SUM"));
}

TEST(MaterialShaderSource, MapsNeedTextureCoordinates)
{
  MaterialSettings s;
  s.tprMap = std::make_shared<const Image>(4, 4, 2);
  EXPECT_TRUE(defines(materialVariant(s, true, true, true), "ANISO_TPR_MAP"));
  EXPECT_FALSE(defines(materialVariant(s, true, true, false), "ANISO_TPR_MAP"));
  EXPECT_TRUE(droppedMaps(s, false));
  EXPECT_FALSE(droppedMaps(s, true));
  EXPECT_FALSE(droppedMaps(MaterialSettings{}, false));
}

// A line set (LineSet.h) is the line variant: its frame is the line's and the view's, so
// normals and texture coordinates are not read and its maps are left out; without tangents
// (no line direction) it stays a surface variant.
TEST(MaterialShaderSource, LineSetsAreTheLineVariantWithoutMaps)
{
  MaterialSettings s;
  s.tprMap = std::make_shared<const Image>(4, 4, 2);
  const MaterialVariant v = materialVariant(s, true, true, true, true);
  EXPECT_TRUE(v.lines);
  EXPECT_TRUE(defines(v, "ANISO_LINE"));
  EXPECT_TRUE(defines(v, "ANISO_HAVE_TANGENTS"));
  EXPECT_FALSE(defines(v, "ANISO_HAVE_NORMALS"));
  EXPECT_FALSE(defines(v, "ANISO_HAVE_TCOORDS"));
  EXPECT_FALSE(defines(v, "ANISO_TPR_MAP"));
  EXPECT_NE(v, materialVariant(s, false, true, false, false));
  EXPECT_FALSE(materialVariant(s, false, false, false, true).lines);
  // The line variant's varyings carry VTK's VSOut suffix in both stages (ShaderHook.h).
  const MaterialShaderCode code = composeMaterialShaders(v);
  EXPECT_NE(code.vertexDeclarations.find("#define anisoTangentWC anisoTangentWCVSOut"),
            std::string::npos);
  EXPECT_NE(code.fragmentDeclarations.find("#define anisoClipPosition anisoClipPositionVSOut"),
            std::string::npos);
}

TEST(MaterialShaderSource, EachFeatureIsItsOwnDefine)
{
  MaterialSettings s;
  s.method = SpecularMethod::SplitSum;
  s.filtered = false;
  s.halfVectors = HalfVectorSource::Lut;
  const MaterialVariant v = materialVariant(s, true, false, false);
  EXPECT_TRUE(defines(v, "ANISO_METHOD_SPLIT_SUM"));
  EXPECT_FALSE(defines(v, "ANISO_FILTERED"));
  EXPECT_TRUE(defines(v, "ANISO_HALF_VECTORS_FROM_LUT"));
  EXPECT_FALSE(defines(v, "ANISO_HAVE_TANGENTS"));
  const MaterialShaderCode code = composeMaterialShaders(v);
  EXPECT_EQ(code.fragmentDeclarations.rfind(variantDefines(v), 0), 0u);
  EXPECT_EQ(code.vertexDeclarations.rfind(variantDefines(v), 0), 0u);
}

// An actor with the material applied; no window, so nothing is compiled.
struct Applied
{
  vtkNew<vtkOpenGLPolyDataMapper> mapper;
  vtkNew<vtkActor> actor;
  vtkNew<vtkRenderer> renderer;
  std::unique_ptr<AnisoMaterial> material;

  explicit Applied(const MaterialSettings& settings)
  {
    mapper->SetInputData(makeSphere(16, 8));
    actor->SetMapper(mapper);
    auto lighting = std::make_shared<EnvironmentLighting>(
        std::make_shared<UniformEnvironment>(glm::dvec3(1.0)), 4);
    material = std::make_unique<AnisoMaterial>(lighting, settings);
    material->apply(actor, renderer);
  }

  vtkOpenGLShaderProperty::ReplacementMap replacements()
  {
    return vtkOpenGLShaderProperty::SafeDownCast(actor->GetShaderProperty())
        ->GetAllShaderReplacements();
  }

  // Tag and text of every replacement, comparable.
  std::vector<std::pair<std::string, std::string>> source()
  {
    std::vector<std::pair<std::string, std::string>> all;
    for (const auto& [spec, value] : replacements())
    {
      all.emplace_back(spec.OriginalValue, value.Replacement);
    }
    return all;
  }
};

TEST(AnisoMaterial, ReplacementsKeepTheirTags)
{
  Applied a(MaterialSettings{});
  const auto replacements = a.replacements();
  EXPECT_EQ(replacements.size(), 5u);
  for (const auto& [spec, value] : replacements)
  {
    EXPECT_TRUE(spec.ReplaceFirst);
    EXPECT_EQ(value.Replacement.rfind(spec.OriginalValue + "\n", 0), 0u) << spec.OriginalValue;
  }
  const MaterialVariant v = a.material->variant();
  EXPECT_TRUE(v.normals && v.tangents && v.tcoords) << "the built-in sphere has all three";
}

TEST(AnisoMaterial, SliderValuesKeepTheSourceFeaturesChangeIt)
{
  Applied a(MaterialSettings{});
  const auto before = a.source();
  MaterialSettings s = a.material->settings();
  s.lobe = {20000.0, 70.0};
  s.f0 = {0.1, 0.2, 0.3};
  s.albedo = {0.5, 0.5, 0.5};
  s.samples = 256;
  s.heightScale = 0.3;
  a.material->setSettings(s);
  EXPECT_EQ(a.source(), before);

  s.filtered = !s.filtered;
  a.material->setSettings(s);
  EXPECT_NE(a.source(), before);

  a.material->detach();
  EXPECT_TRUE(a.replacements().empty());
}

TEST(AnisoMaterial, InvalidSettingsNameTheParameterAndKeepThePrevious)
{
  Applied a(MaterialSettings{});
  MaterialSettings s = a.material->settings();
  auto refused = [&](MaterialSettings bad, const std::string& subject)
  {
    try
    {
      a.material->setSettings(bad);
      ADD_FAILURE() << subject << " accepted";
    }
    catch (const Error& e)
    {
      EXPECT_EQ(std::string(e.what()).rfind(subject + ":", 0), 0u) << e.what();
    }
  };
  MaterialSettings bad = s;
  bad.samples = 0;
  refused(bad, "samples");
  bad = s;
  bad.f0 = {1.5, 0.0, 0.0};
  refused(bad, "f0");
  bad = s;
  bad.lobe.nu = -1.0;
  refused(bad, "n_u");
  bad = s;
  bad.normalMap = std::make_shared<const Image>(2, 2, 3);
  bad.quaternionMap = std::make_shared<const Image>(2, 2, 3);
  refused(bad, "normal map");
  bad = s;
  bad.tprMap = std::make_shared<const Image>(2, 2, 1);
  refused(bad, "TPR map");
  EXPECT_EQ(a.material->settings().samples, s.samples);
}
} // namespace
} // namespace aniso
