// Feature images against the CPU reference integrator. Each renders a small image with one
// feature of the material and compares every other pixel with the reference radiance for the
// frame the feature should produce there, computed on the CPU from the analytic geometry and the
// core's own definitions (frameFromQuaternion, tprTangentAt, the brushing models), never from
// an earlier rendering:
//  - diffuse with a rotated environment: specular reference plus (1 - F(n.v)) albedo / pi E(n)
//    with E from the core's SH9 of the rotated environment;
//  - plate maps: a constant normal map (n perturbed, t re-orthogonalised), a constant quaternion
//    map (the whole frame rotated), TPR patterns (linear and an off-centre circular one, read
//    through the UVs), parallax occlusion over a flat height field at full depth (the UVs shift
//    by v.xy / v.z times the height scale);
//  - tangent generators on the sphere: along an axis, around an axis, radial from a point;
//  - albedo, occlusion and metallic maps (constant): the albedo scaled, F0 blended towards the
//    dielectric 0.04 and the diffuse removed by the metalness, everything scaled by occlusion.
// Metric: relative L2 over the compared pixels (RGB). The bound, 2%, is ten times the error
// measured for the sphere at 512 samples per pixel, where the quasi-Monte-Carlo error and the
// cube's interpolation dominate; a frame built the wrong way round (b for t, a mirrored map, a
// rotation in the wrong sense) gives tens of percent. On failure the rendered, expected and
// difference images are kept.
#include "core/env/cubemap.h"
#include "core/env/environment.h"
#include "core/frame.h"
#include "core/maps/quaternion_map.h"
#include "core/maps/tpr_map.h"
#include "core/reference/reference_integrator.h"
#include "tests/vtkpasses/render/render_test_helpers.h"
#include "vtkpasses/mesh/BuiltinMeshes.h"
#include "vtkpasses/mesh/SurfacePreparation.h"

#include <cmath>
#include <cstdio>
#include <functional>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <optional>
#include <vector>
#include <vtkPointData.h>
#include <vtkPolyData.h>

namespace aniso::test
{
namespace
{
constexpr int kSize = 48;
constexpr double kBound = 0.02;
const AsLobe kLobe{1000.0, 100.0};

// What the reference needs at one pixel.
struct PixelShading
{
  Frame frame;
  glm::dvec3 view;   // towards the camera
  glm::dvec3 normal; // geometric, for the diffuse term
};

using PixelFunction = std::function<std::optional<PixelShading>(const Ray&)>;

RenderSettings baseSettings(vtkSmartPointer<vtkPolyData> surface)
{
  RenderSettings s;
  s.surface = std::move(surface);
  s.environment = std::make_shared<StudioEnvironment>();
  s.cubeSize = 256;
  s.material.lobe = kLobe;
  s.material.f0 = glm::dvec3(1.0);
  s.material.albedo = glm::dvec3(0.0);
  s.material.method = SpecularMethod::Exact;
  s.material.filtered = false;
  s.material.samples = 16;
  s.display.background = BackgroundMode::Transparent;
  s.width = kSize;
  s.height = kSize;
  s.frames = 32;
  s.jitter = false;
  return s;
}

// Reference radiance at every other pixel that PIXEL accepts; ADD adds non-specular terms.
Image referenceImage(const RenderSettings& s, const Environment& env, const glm::dvec3& centre,
                     double radius, const PixelFunction& pixel,
                     const std::function<glm::dvec3(const PixelShading&)>& add = {})
{
  const CameraPlacement camera = placeCamera(s.view, centre, radius);
  Image expected(s.width, s.height, 4);
  ReferenceOptions options;
  options.relativeTolerance = 2e-3;
  for (int y = 0; y < s.height; y += 2)
  {
    for (int x = 0; x < s.width; x += 2)
    {
      const auto shading = pixel(pixelRay(camera, x, y, s.width, s.height));
      if (!shading)
      {
        continue;
      }
      glm::dvec3 value = integrateSpecular(s.material.lobe, s.material.f0, shading->frame,
                                           shading->view, env, options)
                             .value;
      if (add)
      {
        value += add(*shading);
      }
      for (int c = 0; c < 3; ++c)
      {
        expected.at(x, y, c) = static_cast<float>(value[c]);
      }
      expected.at(x, y, 3) = 1.0f;
    }
  }
  return expected;
}

// Renders, compares where EXPECTED has alpha 1, keeps the images on failure.
void compare(const char* name, const RenderSettings& s, const Image& expected)
{
  const RenderResult r = renderOffscreen(s);
  EXPECT_EQ(nonFiniteValues(r.linear), 0) << name;
  EXPECT_EQ(nonFiniteValues(r.display), 0) << name;
  EXPECT_FALSE(r.mapsDropped) << name;
  double error = 0.0;
  double norm = 0.0;
  int pixels = 0;
  for (int y = 0; y < s.height; ++y)
  {
    for (int x = 0; x < s.width; ++x)
    {
      if (expected.at(x, y, 3) != 1.0f)
      {
        continue;
      }
      ++pixels;
      for (int c = 0; c < 3; ++c)
      {
        error += std::pow(double(r.linear.at(x, y, c)) - expected.at(x, y, c), 2);
        norm += std::pow(double(expected.at(x, y, c)), 2);
      }
    }
  }
  const double relative = std::sqrt(error / norm);
  std::printf("%s: relative L2 %.4f over %d pixels\n", name, relative, pixels);
  EXPECT_GT(pixels, 100) << name;
  EXPECT_LT(relative, kBound) << name;
  if (!(relative < kBound))
  {
    Image masked = r.linear;
    for (int y = 0; y < s.height; ++y)
    {
      for (int x = 0; x < s.width; ++x)
      {
        if (expected.at(x, y, 3) != 1.0f)
        {
          for (int c = 0; c < 4; ++c)
          {
            masked.at(x, y, c) = 0.0f;
          }
        }
      }
    }
    keepImages(std::string("render_feature_") + name, masked, expected);
  }
}

// ---------------------------------------------------------------- the plate

// The plate [-1, 1]^2 in z = 0 seen from the front and above; UV = ((x + 1) / 2, (y + 1) / 2),
// t = +X, b = +Y, n = +Z.
RenderSettings plateSettings()
{
  RenderSettings s = baseSettings(makePlate(8));
  s.view.direction = viewDirectionFromAngles(15.0, 55.0);
  return s;
}

struct PlateHit
{
  glm::dvec2 uv;
  glm::dvec3 view;
};

std::optional<PlateHit> hitPlate(const Ray& ray)
{
  if (ray.direction.z >= 0.0)
  {
    return std::nullopt;
  }
  const glm::dvec3 p = ray.origin - ray.origin.z / ray.direction.z * ray.direction;
  if (std::abs(p.x) > 0.9 || std::abs(p.y) > 0.9)
  {
    return std::nullopt; // edges: the faceted rendering and the analytic hit may differ
  }
  return PlateHit{{(p.x + 1.0) / 2.0, (p.y + 1.0) / 2.0}, -ray.direction};
}

// A WIDTH x HEIGHT image of one value (maps that are the same everywhere).
std::shared_ptr<const Image> constantMap(const glm::dvec3& value, int channels)
{
  auto image = std::make_shared<Image>(8, 8, channels);
  for (int y = 0; y < 8; ++y)
  {
    for (int x = 0; x < 8; ++x)
    {
      for (int c = 0; c < channels; ++c)
      {
        image->at(x, y, c) = static_cast<float>(value[c]);
      }
    }
  }
  return image;
}

const glm::dvec3 kTiltedNormal = glm::normalize(glm::dvec3(0.35, -0.25, 1.0));

TEST(RenderFeatures, NormalMapPerturbsTheNormalAndKeepsTheTangentInPlane)
{
  ANISO_REQUIRE_DISPLAY();
  RenderSettings s = plateSettings();
  s.material.normalMap = constantMap(kTiltedNormal, 3);
  const StudioEnvironment env;
  const Image expected =
      referenceImage(s, env, glm::dvec3(0.0), std::sqrt(2.0),
                     [](const Ray& ray) -> std::optional<PixelShading>
                     {
                       const auto hit = hitPlate(ray);
                       if (!hit)
                       {
                         return std::nullopt;
                       }
                       return PixelShading{Frame::fromNormalTangent(kTiltedNormal, {1.0, 0.0, 0.0}),
                                           hit->view, kTiltedNormal};
                     });
  compare("normal_map", s, expected);
}

TEST(RenderFeatures, QuaternionMapRotatesTheWholeFrame)
{
  ANISO_REQUIRE_DISPLAY();
  RenderSettings s = plateSettings();
  const glm::dvec3 abc = quaternionFromNormal(kTiltedNormal);
  s.material.quaternionMap = constantMap(abc, 3);
  const Frame rotated = frameFromQuaternion(abc);
  const StudioEnvironment env;
  const Image expected = referenceImage(s, env, glm::dvec3(0.0), std::sqrt(2.0),
                                        [&](const Ray& ray) -> std::optional<PixelShading>
                                        {
                                          const auto hit = hitPlate(ray);
                                          if (!hit)
                                          {
                                            return std::nullopt;
                                          }
                                          return PixelShading{rotated, hit->view, rotated.n};
                                        });
  compare("quaternion_map", s, expected);
}

// TPR: the tangent of the pattern at the (possibly shifted) UV, in the plate's plane.
void compareTpr(const char* name, const std::string& pattern, double heightScale)
{
  RenderSettings s = plateSettings();
  const TprParams params = parseTprPattern(pattern);
  s.material.tprMap = std::make_shared<const Image>(bakeTprMap(params, 256, 256));
  if (heightScale > 0.0)
  {
    s.material.heightMap = constantMap(glm::dvec3(0.0), 1); // the floor: full depth everywhere
    s.material.heightScale = heightScale;
  }
  const StudioEnvironment env;
  const Image expected = referenceImage(
      s, env, glm::dvec3(0.0), std::sqrt(2.0),
      [&](const Ray& ray) -> std::optional<PixelShading>
      {
        const auto hit = hitPlate(ray);
        if (!hit)
        {
          return std::nullopt;
        }
        glm::dvec2 uv = hit->uv;
        if (heightScale > 0.0)
        {
          // Parallax at full depth: the view ray meets the floor v.xy / v.z * scale away.
          const glm::dvec3 v = hit->view;
          uv -= glm::dvec2(v.x, v.y) / std::max(v.z, 0.05) * heightScale;
        }
        // Near a pattern's centre the field turns faster than the map resolves.
        if (glm::length(uv - params.centre) < 0.08 || uv.x < 0.02 || uv.y < 0.02 || uv.x > 0.98 ||
            uv.y > 0.98)
        {
          return std::nullopt;
        }
        const glm::dvec2 t = tprTangentAt(params, uv);
        return PixelShading{
            Frame::fromNormalTangent({0.0, 0.0, 1.0}, {t.x, t.y, 0.0}), hit->view, {0.0, 0.0, 1.0}};
      });
  compare(name, s, expected);
}

TEST(RenderFeatures, LinearTprRotatesTheTangent)
{
  ANISO_REQUIRE_DISPLAY();
  compareTpr("tpr_linear", "linear:30", 0.0);
}

TEST(RenderFeatures, CircularTprFollowsTheUVs)
{
  ANISO_REQUIRE_DISPLAY();
  compareTpr("tpr_circular", "circular:0.35,0.6", 0.0);
}

TEST(RenderFeatures, ParallaxOcclusionShiftsTheUVs)
{
  ANISO_REQUIRE_DISPLAY();
  compareTpr("parallax_occlusion", "circular:0.35,0.6", 0.08);
}

// ---------------------------------------------------------------- the sphere

std::optional<PixelShading> sphereShading(const Ray& ray, const glm::dvec3& tangentHint)
{
  const auto hit = hitUnitSphere(ray);
  if (!hit)
  {
    return std::nullopt;
  }
  const glm::dvec3 n = *hit;
  const glm::dvec3 v = -ray.direction;
  const glm::dvec3 projected = tangentHint - glm::dot(tangentHint, n) * n;
  // Silhouette (faceting), and where the model gives no direction (fallback tangents).
  if (glm::dot(n, v) < 0.2 || glm::length(projected) < 0.3 * glm::length(tangentHint))
  {
    return std::nullopt;
  }
  return PixelShading{Frame::fromNormalTangent(n, tangentHint), v, n};
}

void compareBrushing(const char* name, const std::string& model,
                     const std::function<glm::dvec3(const glm::dvec3&)>& hint)
{
  SurfaceOptions options;
  options.brushing = parseBrushingModel(model);
  RenderSettings s = baseSettings(prepareSurface(makeSphere(128, 64), options, name).polyData);
  s.view.direction = viewDirectionFromAngles(20.0, 15.0);
  const StudioEnvironment env;
  const Image expected =
      referenceImage(s, env, glm::dvec3(0.0), 1.0,
                     [&](const Ray& ray) -> std::optional<PixelShading>
                     {
                       const auto hit = hitUnitSphere(ray);
                       return hit ? sphereShading(ray, hint(*hit)) : std::nullopt;
                     });
  compare(name, s, expected);
}

TEST(RenderFeatures, TangentsAlongAnAxis)
{
  ANISO_REQUIRE_DISPLAY();
  compareBrushing("tangents_axis", "axis:0,0,1",
                  [](const glm::dvec3&) { return glm::dvec3(0, 0, 1); });
}

TEST(RenderFeatures, TangentsAroundAnAxis)
{
  ANISO_REQUIRE_DISPLAY();
  compareBrushing("tangents_around", "around:1,0,0",
                  [](const glm::dvec3& p) { return glm::cross(glm::dvec3(1, 0, 0), p); });
}

TEST(RenderFeatures, TangentsRadialFromAPoint)
{
  ANISO_REQUIRE_DISPLAY();
  const glm::dvec3 point(0.5, -2.0, 0.3);
  compareBrushing("tangents_radial", "radial:0.5,-2,0.3",
                  [&](const glm::dvec3& p) { return p - point; });
}

// ---------------------------------------------------------------- diffuse

// The environment turned about +Z, as the renderer documents its rotation.
class RotatedEnvironment : public Environment
{
public:
  RotatedEnvironment(const Environment& inner, double degrees)
      : inner_(inner), angle_(-degrees * M_PI / 180.0)
  {
  }
  glm::dvec3 radiance(const glm::dvec3& d) const override
  {
    const double c = std::cos(angle_);
    const double s = std::sin(angle_);
    return inner_.radiance({c * d.x - s * d.y, s * d.x + c * d.y, d.z});
  }
  std::string key() const override { return "rotated " + inner_.key(); }

private:
  const Environment& inner_;
  double angle_;
};

TEST(RenderFeatures, DiffuseAndSpecularUnderARotatedEnvironment)
{
  ANISO_REQUIRE_DISPLAY();
  RenderSettings s = baseSettings(makeSphere(128, 64));
  s.environmentRotationDegrees = 60.0;
  s.material.f0 = {0.04, 0.05, 0.06};
  s.material.albedo = {0.8, 0.5, 0.2};
  const StudioEnvironment studio;
  const RotatedEnvironment env(studio, s.environmentRotationDegrees);
  const Sh9 sh = projectSh9(env);
  double shError = 0.0;
  double shNorm = 0.0;
  const Image expected = referenceImage(
      s, env, glm::dvec3(0.0), 1.0,
      [](const Ray& ray) -> std::optional<PixelShading>
      {
        const auto hit = hitUnitSphere(ray);
        return hit ? sphereShading(ray, {-hit->y, hit->x, 0.0}) : std::nullopt;
      },
      [&](const PixelShading& p)
      {
        // k_d = 1 - F(n.v) with Schlick's F, per channel.
        const double m = 1.0 - std::clamp(glm::dot(p.normal, p.view), 0.0, 1.0);
        const glm::dvec3 f = s.material.f0 + (1.0 - s.material.f0) * std::pow(m, 5.0);
        const glm::dvec3 irradiance = irradianceSh9(sh, p.normal);
        // How far SH9 (by design) is from the true irradiance here, for the record.
        const glm::dvec3 exact = integrateIrradiance(p.normal, env).value;
        shError += glm::dot(irradiance - exact, irradiance - exact);
        shNorm += glm::dot(exact, exact);
        return (1.0 - f) * s.material.albedo / M_PI * irradiance;
      });
  std::printf("SH9 irradiance against the integral: relative L2 %.4f\n",
              std::sqrt(shError / shNorm));
  compare("diffuse_rotated", s, expected);
}
TEST(RenderFeatures, AlbedoOcclusionAndMetallicMaps)
{
  ANISO_REQUIRE_DISPLAY();
  RenderSettings s = baseSettings(makeSphere(128, 64));
  s.material.f0 = {0.9, 0.6, 0.3};
  s.material.albedo = {0.8, 0.5, 0.2};
  const double albedoScale = 0.5;
  const double occlusion = 0.6;
  const double metallic = 0.25;
  s.material.albedoMap = constantMap(glm::dvec3(albedoScale), 1);
  s.material.occlusionMap = constantMap(glm::dvec3(occlusion), 1);
  s.material.metallicMap = constantMap(glm::dvec3(metallic), 1);
  // What the maps make of the material: the reference sees these values directly.
  RenderSettings expectedMaterial = s;
  expectedMaterial.material.f0 = glm::mix(glm::dvec3(0.04), s.material.f0, metallic);
  const glm::dvec3 albedo = s.material.albedo * albedoScale * (1.0 - metallic);
  const StudioEnvironment env;
  const Sh9 sh = projectSh9(env);
  Image expected = referenceImage(
      expectedMaterial, env, glm::dvec3(0.0), 1.0,
      [](const Ray& ray) -> std::optional<PixelShading>
      {
        const auto hit = hitUnitSphere(ray);
        return hit ? sphereShading(ray, {-hit->y, hit->x, 0.0}) : std::nullopt;
      },
      [&](const PixelShading& p)
      {
        const double m = 1.0 - std::clamp(glm::dot(p.normal, p.view), 0.0, 1.0);
        const glm::dvec3 f0 = expectedMaterial.material.f0;
        const glm::dvec3 f = f0 + (1.0 - f0) * std::pow(m, 5.0);
        return (1.0 - f) * albedo / M_PI * irradianceSh9(sh, p.normal);
      });
  for (float& value : expected.data)
  {
    value *= static_cast<float>(occlusion);
  }
  // Alpha marks the compared pixels; occlusion scales radiance only.
  for (int y = 0; y < expected.height; ++y)
  {
    for (int x = 0; x < expected.width; ++x)
    {
      if (expected.at(x, y, 3) != 0.0f)
      {
        expected.at(x, y, 3) = 1.0f;
      }
    }
  }
  compare("albedo_occlusion_metallic", s, expected);
}
} // namespace
} // namespace aniso::test
