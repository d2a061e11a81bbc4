// Render tests of the lit models (LitModelMaterial) against the core's CPU evaluation
// (core/models/models.h shadeLitModel, the same functions the core's model tests check).
// The built-in sphere is rendered without jitter (every pixel sampled at its centre); for each
// pixel whose centre ray hits the analytic unit sphere away from the silhouette (n.v >= 0.2) and
// the poles (|n.z| <= 0.95), the reference is the CPU model at the hit point p with the analytic
// frame n = p, t = (-y, x, 0)/|.| (the sphere's UV tangent), perturbed by the material texel
// (svShadingFrame), under the same lights. Metric: relative L2 over those pixels,
// sqrt(sum |gpu - cpu|^2 / sum |cpu|^2) over RGB. The GPU works in float, on a faceted mesh
// with interpolated (renormalised) normals; the bound 3e-3 leaves room for that and nothing
// else (measured: at most 5e-4; a wrong frame, factor or light falloff moves the error to 0.1 or
// more). Heidrich-Seidel's highlight has no n.l factor, so it stops abruptly at the light's
// horizon, and pixels where float and double disagree about l.z > 0 differ by the whole
// highlight: its bound is 2e-2 (measured: 1.1e-2 on the textured material).
// Finiteness: each model over a map holding the extremes of its parameter ranges, under
// grazing, overhead and very close point lights, must give no NaN or Inf.
#include "core/env/environment.h"
#include "core/error.h"
#include "core/models/models.h"
#include "tests/vtkpasses/render/render_test_helpers.h"
#include "vtkpasses/mesh/BuiltinMeshes.h"
#include "vtkpasses/render/EnvironmentLighting.h"
#include "vtkpasses/render/LitModelMaterial.h"
#include "vtkpasses/render/OffscreenRenderer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <iterator>
#include <memory>
#include <string>
#include <vector>
#include <vtkPolyData.h>

namespace aniso::test
{
namespace
{
constexpr int kSize = 96;
constexpr double kBound = 3e-3;
constexpr double kHorizonBound = 2e-2; // Heidrich-Seidel, see above

const LitModel kModels[] = {LitModel::AshikhminShirley, LitModel::Banks, LitModel::BlinnPhong,
                            LitModel::Ward, LitModel::HeidrichSeidel};

std::vector<Light> testLights()
{
  return {parseLight("dir:-1,-2,1.5:1,0.9,0.8"), parseLight("point:1.5,-2,1.5:4")};
}

RenderSettings sphereSettings(const LitModelSettings& lit)
{
  RenderSettings s;
  s.surface = makeSphere(256, 128);
  s.environment = std::make_shared<StudioEnvironment>();
  s.cubeSize = 16; // only the (transparent) background would use it
  s.display.background = BackgroundMode::Transparent;
  s.width = kSize;
  s.height = kSize;
  s.frames = 1;
  s.jitter = false;
  s.installMaterial = litModelInstaller(lit);
  return s;
}

// The sphere's texture coordinates at p (BuiltinMeshes.h): u = longitude / 2 pi in [0, 1),
// v = 1 - polar angle / pi.
glm::dvec2 sphereUv(const glm::dvec3& p)
{
  double u = std::atan2(p.y, p.x) / (2.0 * M_PI);
  u = u < 0.0 ? u + 1.0 : u;
  return {u, 1.0 - std::acos(std::clamp(p.z, -1.0, 1.0)) / M_PI};
}

struct Comparison
{
  double error = 0.0;
  int pixels = 0;
  Image expected;
};

Comparison compare(const Image& rendered, const LitModelSettings& lit)
{
  const CameraPlacement camera = placeCamera(ViewSettings{}, glm::dvec3(0.0), 1.0);
  Comparison c;
  c.expected = Image(kSize, kSize, 4);
  double diff = 0.0;
  double norm = 0.0;
  for (int y = 0; y < kSize; ++y)
  {
    for (int x = 0; x < kSize; ++x)
    {
      const Ray ray = pixelRay(camera, x, y, kSize, kSize);
      const auto hit = hitUnitSphere(ray);
      if (!hit)
      {
        continue;
      }
      const glm::dvec3 n = *hit;
      const glm::dvec3 view = -ray.direction;
      if (glm::dot(n, view) < 0.2 || std::abs(n.z) > 0.95)
      {
        continue;
      }
      const glm::dvec3 t = glm::normalize(glm::dvec3(-n.y, n.x, 0.0));
      const SvTexel texel = sampleSvMaps(*lit.maps, sphereUv(n));
      const Frame frame = svShadingFrame(n, t, texel);
      const glm::dvec3 expected = shadeLitModel(lit.model, texel, frame, n, view, lit.lights);
      for (int k = 0; k < 3; ++k)
      {
        const double d = rendered.at(x, y, k) - expected[k];
        diff += d * d;
        norm += expected[k] * expected[k];
        c.expected.at(x, y, k) = float(expected[k]);
      }
      c.expected.at(x, y, 3) = 1.0f;
      ++c.pixels;
    }
  }
  c.error = norm > 0.0 ? std::sqrt(diff / norm) : INFINITY;
  return c;
}

// Anisotropic, tinted, with the tangent turned 30 degrees and the normal tilted: every part of
// the per-pixel frame and every factor of the models is exercised.
SvTexel tiltedTexel()
{
  SvTexel texel;
  texel.normal = glm::normalize(glm::dvec3(0.2, -0.1, 0.97));
  texel.tangent = {std::cos(M_PI / 6.0), std::sin(M_PI / 6.0)};
  texel.alphaX = 0.15;
  texel.alphaY = 0.4;
  texel.diffuse = {0.3, 0.2, 0.1};
  texel.specular = 0.8;
  return texel;
}

// An 8 x 4 map whose texels vary in every channel, seen magnified on the sphere (bilinear, as
// sampleSvMaps filters).
SvMaps variedMaps()
{
  SvMaps maps;
  maps.tangentAlpha = Image(8, 4, 4);
  maps.albedoSpecular = Image(8, 4, 4);
  maps.normal = Image(8, 4, 3);
  for (int y = 0; y < 4; ++y)
  {
    for (int x = 0; x < 8; ++x)
    {
      const double angle = 0.4 * x + 0.7 * y;
      const float fx = float(x) / 8.0f;
      const float fy = float(y) / 4.0f;
      const float tangentAlpha[4] = {float(std::cos(angle)), float(std::sin(angle)),
                                     0.08f + 0.3f * fx, 0.1f + 0.4f * fy};
      const float albedoSpecular[4] = {0.1f + 0.5f * fx, 0.3f, 0.1f + 0.5f * fy, 0.3f + 0.6f * fx};
      const glm::dvec3 n =
          glm::normalize(glm::dvec3(0.25 * std::sin(angle), 0.2 * std::cos(angle), 1.0));
      for (int c = 0; c < 4; ++c)
      {
        maps.tangentAlpha.at(x, y, c) = tangentAlpha[c];
        maps.albedoSpecular.at(x, y, c) = albedoSpecular[c];
      }
      for (int c = 0; c < 3; ++c)
      {
        maps.normal.at(x, y, c) = float(n[c]);
      }
    }
  }
  return maps;
}

void expectMatchesCpu(const LitModelSettings& lit, const std::string& what)
{
  const RenderResult result = renderOffscreen(sphereSettings(lit));
  EXPECT_EQ(nonFiniteValues(result.linear), 0) << what;
  const Comparison c = compare(result.linear, lit);
  std::printf("%-40s relative L2 %.2e over %d pixels\n", what.c_str(), c.error, c.pixels);
  EXPECT_GT(c.pixels, kSize * kSize / 4) << what;
  const double bound = lit.model == LitModel::HeidrichSeidel ? kHorizonBound : kBound;
  EXPECT_LT(c.error, bound) << what;
  if (!(c.error < bound))
  {
    keepImages("lit_" + what, result.linear, c.expected);
  }
}
} // namespace

TEST(RenderLitModels, UniformTiltedMaterialMatchesCpu)
{
  ANISO_REQUIRE_DISPLAY();
  for (LitModel model : kModels)
  {
    LitModelSettings lit;
    lit.model = model;
    lit.lights = testLights();
    lit.maps = std::make_shared<const SvMaps>(uniformSvMaps(tiltedTexel()));
    expectMatchesCpu(lit, std::string(litModelName(model)) + "_uniform");
  }
}

TEST(RenderLitModels, TexturedMaterialMatchesCpu)
{
  ANISO_REQUIRE_DISPLAY();
  const auto maps = std::make_shared<const SvMaps>(variedMaps());
  for (LitModel model : kModels)
  {
    LitModelSettings lit;
    lit.model = model;
    lit.lights = {parseLight("dir:-1,-1.5,1:2")};
    lit.maps = maps;
    expectMatchesCpu(lit, std::string(litModelName(model)) + "_textured");
  }
}

// A material applied with one model and lights, then detached, applied again and given another
// model, other lights and other maps, renders the new settings (the variant is reinstalled, the
// light uniforms and textures follow).
TEST(RenderLitModels, SettingsChangedAfterApplyAreRendered)
{
  ANISO_REQUIRE_DISPLAY();
  LitModelSettings first;
  first.model = LitModel::Banks;
  first.lights = {parseLight("dir:1,-1,1:2")};
  LitModelSettings second;
  second.model = LitModel::Ward;
  second.lights = testLights();
  second.maps = std::make_shared<const SvMaps>(variedMaps());
  RenderSettings s = sphereSettings(first);
  std::shared_ptr<LitModelMaterial> material;
  s.installMaterial = [&](vtkActor* actor, vtkRenderer* renderer,
                          const std::shared_ptr<EnvironmentLighting>&) -> std::shared_ptr<void>
  {
    material = std::make_shared<LitModelMaterial>(first);
    material->apply(actor, renderer);
    material->detach();
    material->apply(actor, renderer);
    material->setSettings(second);
    return material;
  };
  const RenderResult result = renderOffscreen(s);
  ASSERT_TRUE(material);
  EXPECT_EQ(material->settings().model, LitModel::Ward);
  const Comparison c = compare(result.linear, second);
  std::printf("%-40s relative L2 %.2e over %d pixels\n", "ward after a change", c.error, c.pixels);
  EXPECT_LT(c.error, kBound);
}

TEST(RenderLitModels, ExtremeParametersStayFinite)
{
  ANISO_REQUIRE_DISPLAY();
  // Alphas at both ends of [kSvMinAlpha, kSvMaxAlpha], reflectances 0 and 1, the tangent
  // along both axes, a normal tilted to 60 degrees; lights overhead, grazing, and a point
  // light 1e-3 above the sphere: all eight light slots in use.
  SvMaps maps;
  maps.tangentAlpha = Image(2, 2, 4);
  maps.albedoSpecular = Image(2, 2, 4);
  maps.normal = Image(2, 2, 3);
  const float alphas[2] = {float(kSvMinAlpha), float(kSvMaxAlpha)};
  for (int y = 0; y < 2; ++y)
  {
    for (int x = 0; x < 2; ++x)
    {
      const float ta[4] = {float(1 - y), float(y), alphas[x], alphas[1 - x]};
      const float as[4] = {float(x), float(y), 1.0f, float(x ^ y)};
      const float n[3] = {x ? 0.866f : 0.0f, 0.0f, x ? 0.5f : 1.0f};
      for (int c = 0; c < 4; ++c)
      {
        maps.tangentAlpha.at(x, y, c) = ta[c];
        maps.albedoSpecular.at(x, y, c) = as[c];
      }
      for (int c = 0; c < 3; ++c)
      {
        maps.normal.at(x, y, c) = n[c];
      }
    }
  }
  const auto shared = std::make_shared<const SvMaps>(maps);
  const std::vector<Light> lights = {
      parseLight("dir:0,0,1:1"),           parseLight("dir:1,0,1e-4:10"),
      parseLight("dir:0,-1,1e-6:10"),      parseLight("point:0,-1.001,0:1"),
      parseLight("point:0.7,-0.7,0.2:5"),  parseLight("dir:-1,-1,0.1:1000"),
      parseLight("point:0,0,1.0001:1e-3"), parseLight("dir:0,-1,0:1")};
  ASSERT_EQ(lights.size(), std::size_t(LitModelMaterial::kMaxLights));
  for (LitModel model : kModels)
  {
    LitModelSettings lit;
    lit.model = model;
    lit.lights = lights;
    lit.maps = shared;
    const RenderResult result = renderOffscreen(sphereSettings(lit));
    EXPECT_EQ(nonFiniteValues(result.linear), 0) << litModelName(model);
    EXPECT_EQ(nonFiniteValues(result.display), 0) << litModelName(model);
    EXPECT_GT(result.coveredPixels, kSize * kSize / 2) << litModelName(model);
  }
}

// The compiled variant: exactly one model define, the light array size, and a define per mesh
// array present (GL-free).
TEST(RenderLitModels, VariantDefinesFollowTheVariant)
{
  const char* const modelDefines[] = {"LIT_MODEL_ASHIKHMIN_SHIRLEY", "LIT_MODEL_BANKS",
                                      "LIT_MODEL_BLINN_PHONG", "LIT_MODEL_WARD",
                                      "LIT_MODEL_HEIDRICH_SEIDEL"};
  for (std::size_t i = 0; i < std::size(kModels); ++i)
  {
    const std::string d = litVariantDefines({kModels[i], true, false, true});
    for (std::size_t j = 0; j < std::size(kModels); ++j)
    {
      EXPECT_EQ(d.find(std::string("#define ") + modelDefines[j] + "\n") != std::string::npos,
                i == j)
          << d;
    }
    EXPECT_NE(d.find("#define LIT_MAX_LIGHTS " + std::to_string(LitModelMaterial::kMaxLights)),
              std::string::npos);
    EXPECT_NE(d.find("#define LIT_HAVE_NORMALS\n"), std::string::npos);
    EXPECT_EQ(d.find("LIT_HAVE_TANGENTS"), std::string::npos);
    EXPECT_NE(d.find("#define LIT_HAVE_TCOORDS\n"), std::string::npos);
  }
}

// More lights than the shader's arrays hold, and invalid lights, are refused before rendering.
TEST(RenderLitModels, InvalidSettingsThrow)
{
  LitModelSettings lit;
  lit.lights.assign(std::size_t(LitModelMaterial::kMaxLights) + 1, Light{});
  EXPECT_THROW(LitModelMaterial::validate(lit), Error);
  lit.lights = {Light{}};
  lit.lights[0].intensity = glm::dvec3(-1.0);
  EXPECT_THROW(LitModelMaterial::validate(lit), Error);
  lit.lights[0].intensity = glm::dvec3(1.0);
  SvMaps empty;
  lit.maps = std::make_shared<const SvMaps>(empty);
  EXPECT_THROW(LitModelMaterial::validate(lit), Error);
  lit.maps.reset();
  EXPECT_NO_THROW(LitModelMaterial::validate(lit));
}
} // namespace aniso::test
