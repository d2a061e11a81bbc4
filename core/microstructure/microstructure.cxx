#include "core/microstructure/microstructure.h"

#include "core/brdf/ashikhmin_shirley.h"
#include "core/brdf/blinn_phong_aniso.h"
#include "core/brdf/ggx.h"
#include "core/brdf/sv_common.h"
#include "core/error.h"
#include "core/models/height_field.h"
#include "core/models/texture_sampling.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <sstream>
#include <string>

namespace aniso
{
namespace
{
constexpr double kPi = 3.14159265358979323846;

struct Profile
{
  double height = 0.0;
  glm::dvec3 albedo{0.0};
};

// Distance from a to the nearest of the centres c0 + k spacing (k integer).
double distanceToNearest(double a, double c0, double spacing)
{
  const double t = (a - c0) / spacing;
  return std::abs(t - std::round(t)) * spacing;
}

Profile silk(double x, double y)
{
  constexpr double radius = 0.22;
  const glm::dvec3 gap(0.05);
  const glm::dvec3 warp(0.85, 0.72, 0.45); // golden, along x
  const glm::dvec3 weft(0.65, 0.08, 0.16); // crimson, along y
  // Warp j (centre y = 0.25 + 0.5 j) passes over weft i (centre x = 0.25 + 0.5 i) when i + j is
  // even, so its centre line is highest at x = 0.25 + 0.5 j; the weft is the complement.
  const int j = y < 0.5 ? 0 : 1;
  const int i = x < 0.5 ? 0 : 1;
  const double warpT = distanceToNearest(y, 0.25, 0.5) / radius;
  const double weftT = distanceToNearest(x, 0.25, 0.5) / radius;
  Profile p{0.0, gap};
  if (warpT < 1.0)
  {
    const double centre = 0.55 + 0.2 * std::cos(2.0 * kPi * (x - 0.25 - 0.5 * j));
    const double h = centre + 0.25 * std::sqrt(1.0 - warpT * warpT);
    if (h > p.height)
      p = {h, warp};
  }
  if (weftT < 1.0)
  {
    const double centre = 0.55 + 0.2 * std::cos(2.0 * kPi * (y - 0.75 + 0.5 * i));
    const double h = centre + 0.25 * std::sqrt(1.0 - weftT * weftT);
    if (h > p.height)
      p = {h, weft};
  }
  return p;
}

Profile profileAt(MicroPattern pattern, double x, double y)
{
  const double r = std::max(std::abs(x - 0.5), std::abs(y - 0.5)); // square "radius"
  switch (pattern)
  {
  case MicroPattern::Pyramids:
    return {1.0 - 2.0 * r, glm::dvec3(0.62, 0.62, 0.65)};
  case MicroPattern::InvertedPyramids:
  {
    constexpr double bottom = 0.15;
    if (r < bottom)
      return {0.0, glm::dvec3(0.75, 0.1, 0.08)};
    return {(r - bottom) / (0.5 - bottom), glm::dvec3(0.55, 0.55, 0.58)};
  }
  case MicroPattern::Grooves:
    return {2.0 * std::abs(x - 0.5), glm::dvec3(0.6)};
  case MicroPattern::Silk:
    return silk(x, y);
  }
  return {};
}

void checkDepth(double depth)
{
  if (!(depth > 0.0 && depth <= kMicroMaxDepth))
  {
    std::ostringstream reason;
    reason << "depth must be in (0, " << kMicroMaxDepth << "] (got " << depth << ")";
    throw errorAbout("microstructure", reason.str());
  }
}

void finishNormals(Microstructure& s)
{
  s.normal = normalsFromSlopes(slopesFromHeight(s.height, s.depth));
}

double heightAt(const Microstructure& s, const glm::dvec2& p)
{
  const BilinearTaps f = bilinearTaps(s.height.width, s.height.height, p);
  double h = 0.0;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i)
      h += f.wx[i] * f.wy[j] * s.height.at(f.x[i], f.y[j], 0);
  return h;
}

// Depth below the top of the surface at p.
double surfaceDepth(const Microstructure& s, const glm::dvec2& p)
{
  return s.depth * (1.0 - heightAt(s, p));
}

double schlickMasking(double cosine, double k)
{
  return cosine / (cosine * (1.0 - k) + k);
}

// Specular f in the sample's frame (v, l unit, z up).
glm::dvec3 specular(const MicroShadingOptions& o, const glm::dvec3& v, const glm::dvec3& l)
{
  if (!(v.z > 0.0) || !(l.z > 0.0))
    return glm::dvec3(0.0);
  if (o.brdf == MicroBrdf::BlinnPhong)
  {
    BlinnPhongAnisoMaterial m;
    const double alpha = 1.0 / std::sqrt(std::max(o.blinnExponent, 1e-12));
    m.alphaX = m.alphaY = std::min(alpha, 1e6);
    m.diffuse = glm::dvec3(0.0);
    m.specular = o.f0;
    return evalBlinnPhongAniso(m, v, l);
  }
  const glm::dvec3 h = sv::normalizeScaled(v + l);
  const double k = 0.5 * o.roughness;
  const double g = schlickMasking(v.z, k) * schlickMasking(l.z, k);
  const double d = ggxDistribution(GgxLobe{o.roughness, o.roughness}, h);
  // G1 ~ n.w / k cancels the cosines at grazing angles; the floor only avoids 0 / 0 where both
  // underflow.
  return schlickFresnel(o.f0, glm::dot(v, h)) * (d * g / std::max(4.0 * v.z * l.z, 1e-300));
}
} // namespace

Microstructure makeMicrostructure(MicroPattern pattern, int size, double depth)
{
  if (!(size >= 4 && size <= 1024))
    throw errorAbout("microstructure",
                     "size must be in [4, 1024] (got " + std::to_string(size) + ")");
  checkDepth(depth);
  Microstructure s;
  s.depth = depth;
  s.albedo = Image(size, size, 3);
  s.height = Image(size, size, 1);
  for (int y = 0; y < size; ++y)
  {
    for (int x = 0; x < size; ++x)
    {
      const Profile p = profileAt(pattern, (x + 0.5) / size, 1.0 - (y + 0.5) / size);
      s.height.at(x, y, 0) = float(std::clamp(p.height, 0.0, 1.0));
      for (int c = 0; c < 3; ++c)
        s.albedo.at(x, y, c) = float(p.albedo[c]);
    }
  }
  finishNormals(s);
  return s;
}

Microstructure microstructureFromImages(const Image& height, const Image& albedo, double depth)
{
  checkDepth(depth);
  auto valid = [](const Image& i)
  {
    return i.width > 0 && i.height > 0 && i.channels > 0 &&
           i.data.size() == std::size_t(i.width) * i.height * i.channels;
  };
  if (!valid(height) || !valid(albedo))
    throw errorAbout("microstructure", "height and albedo must be non-empty images");
  if (height.width != albedo.width || height.height != albedo.height)
    throw errorAbout("microstructure", "height and albedo must have the same size");
  Microstructure s;
  s.depth = depth;
  s.height = Image(height.width, height.height, 1);
  s.albedo = Image(height.width, height.height, 3);
  for (int y = 0; y < height.height; ++y)
  {
    for (int x = 0; x < height.width; ++x)
    {
      const float h = height.at(x, y, 0);
      if (!std::isfinite(h))
        throw errorAbout("microstructure", "height texel (" + std::to_string(x) + ", " +
                                               std::to_string(y) + ") is not finite");
      s.height.at(x, y, 0) = std::clamp(h, 0.0f, 1.0f);
      for (int c = 0; c < 3; ++c)
        s.albedo.at(x, y, c) =
            std::clamp(albedo.at(x, y, std::min(c, albedo.channels - 1)), 0.0f, 1.0f);
    }
  }
  finishNormals(s);
  return s;
}

MicroTexel sampleMicrostructure(const Microstructure& s, const glm::dvec2& p)
{
  MicroTexel t;
  t.albedo = glm::dvec3(0.0);
  t.normal = glm::dvec3(0.0);
  t.height = 0.0;
  const BilinearTaps f = bilinearTaps(s.height.width, s.height.height, p);
  for (int j = 0; j < 2; ++j)
  {
    for (int i = 0; i < 2; ++i)
    {
      const double w = f.wx[i] * f.wy[j];
      const int x = f.x[i];
      const int y = f.y[j];
      t.height += w * s.height.at(x, y, 0);
      t.albedo += w * glm::dvec3(s.albedo.at(x, y, 0), s.albedo.at(x, y, 1), s.albedo.at(x, y, 2));
      t.normal += w * glm::dvec3(s.normal.at(x, y, 0), s.normal.at(x, y, 1), s.normal.at(x, y, 2));
    }
  }
  const double len = glm::length(t.normal);
  t.normal = len > 1e-12 ? t.normal / len : glm::dvec3(0.0, 0.0, 1.0);
  return t;
}

MicroHit marchParallaxOcclusion(const Microstructure& s, const glm::dvec2& p, const glm::dvec3& v,
                                int steps)
{
  const glm::dvec2 drift = -glm::dvec2(v.x, v.y) / std::max(v.z, 1e-6);    // per unit of depth
  auto gap = [&](double d) { return d - surfaceDepth(s, p + drift * d); }; // >= 0: at or below
  steps = std::max(steps, 1);
  double previous = 0.0;
  double previousGap = gap(0.0);
  if (previousGap >= 0.0)
    return {p, 0.0};
  for (int i = 1; i <= steps; ++i)
  {
    const double d = s.depth * i / steps;
    const double g = gap(d);
    if (g >= 0.0)
    {
      // Regula falsi between the last point above the surface and the first below it.
      double a = previous;
      double ga = previousGap;
      double b = d;
      double gb = g;
      for (int k = 0; k < 8 && gb - ga > 0.0; ++k)
      {
        const double c = a - ga * (b - a) / (gb - ga);
        const double gc = gap(c);
        if (gc >= 0.0)
        {
          b = c;
          gb = gc;
        }
        else
        {
          a = c;
          ga = gc;
        }
        if (std::abs(gc) < 1e-12 * s.depth)
          break;
      }
      const double hit = gb - ga > 0.0 ? a - ga * (b - a) / (gb - ga) : b;
      return {p + drift * hit, hit};
    }
    previous = d;
    previousGap = g;
  }
  return {p + drift * s.depth, s.depth};
}

bool shadowedTowards(const Microstructure& s, const glm::dvec2& q, double depth,
                     const glm::dvec3& l, int steps)
{
  if (!(l.z > 0.0) || !(depth > 0.0))
    return false;
  const glm::dvec2 drift = glm::dvec2(l.x, l.y) / l.z; // per unit of rise
  const int n = std::max(1, int(std::ceil(std::max(steps, 1) * depth / s.depth)));
  const double bias = 1e-4 * s.depth; // the start point lies on the surface itself
  for (int i = 1; i <= n; ++i)
  {
    const double rise = depth * i / n;
    const double rayDepth = depth - rise;
    if (surfaceDepth(s, q + drift * rise) < rayDepth - bias)
      return true;
  }
  return false;
}

void validateMicroOptions(const MicroShadingOptions& o)
{
  auto fail = [](const char* name, const std::string& reason) { throw errorAbout(name, reason); };
  if (!(o.samplesPerAxis >= 1 && o.samplesPerAxis <= 64))
    fail("samples per axis", "must be in [1, 64] (got " + std::to_string(o.samplesPerAxis) + ")");
  if (!(o.roughness >= 1e-3 && o.roughness <= 1.0))
    fail("roughness", "must be in [0.001, 1] (got " + std::to_string(o.roughness) + ")");
  if (!(o.blinnExponent >= 0.0 && o.blinnExponent <= 1e6))
    fail("Blinn-Phong exponent",
         "must be in [0, 1e6] (got " + std::to_string(o.blinnExponent) + ")");
  for (int c = 0; c < 3; ++c)
    if (!(o.f0[c] >= 0.0 && o.f0[c] <= 1.0))
      fail("F0", "every channel must be in [0, 1]");
  if (!(o.marchSteps >= 1 && o.marchSteps <= 1024))
    fail("march steps", "must be in [1, 1024] (got " + std::to_string(o.marchSteps) + ")");
}

glm::dvec2 sampleTprDirection(const Image& tprMap, const glm::dvec2& uv)
{
  const glm::dvec2 none(0.0, 1.0);
  if (tprMap.width <= 0 || tprMap.height <= 0 || tprMap.channels < 2)
    return none;
  const BilinearTaps f = bilinearTaps(tprMap.width, tprMap.height, uv);
  glm::dvec2 r(0.0);
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i)
      r += f.wx[i] * f.wy[j] *
           glm::dvec2(tprMap.at(f.x[i], f.y[j], 0), tprMap.at(f.x[i], f.y[j], 1));
  const double len = glm::length(r);
  return std::isfinite(len) && len > 1e-12 ? r / len : none;
}

TurnedPixel turnMicroPixel(const Frame& frame, const PixelFootprint& footprint, const glm::dvec2& r)
{
  auto turn = [&r](const glm::dvec2& p)
  { return glm::dvec2(r.y * p.x - r.x * p.y, r.x * p.x + r.y * p.y); };
  TurnedPixel turned;
  turned.frame.t = r.y * frame.t - r.x * frame.b;
  turned.frame.b = r.x * frame.t + r.y * frame.b;
  turned.frame.n = frame.n;
  turned.footprint.centre = turn(footprint.centre);
  turned.footprint.axisU = turn(footprint.axisU);
  turned.footprint.axisV = turn(footprint.axisV);
  return turned;
}

glm::dvec3 shadeMicroPixel(const Microstructure& s, const MicroShadingOptions& o,
                           const PixelFootprint& footprint, const Frame& frame,
                           const glm::dvec3& position, const glm::dvec3& viewWorld,
                           const std::vector<Light>& lights)
{
  const glm::dvec3 v = frame.toLocal(viewWorld);
  if (!(v.z > 0.0))
    return glm::dvec3(0.0);
  // Arrivals are per pixel: the structure is far smaller than the distance to any light.
  std::vector<LightArrival> arrivals;
  std::vector<glm::dvec3> lightsLocal;
  for (const Light& light : lights)
  {
    const LightArrival a = arriveAt(light, position);
    const glm::dvec3 l = frame.toLocal(a.direction);
    if (l.z > 0.0)
    {
      arrivals.push_back(a);
      lightsLocal.push_back(l);
    }
  }
  const int k = std::max(o.samplesPerAxis, 1);
  glm::dvec3 sum(0.0);
  for (int j = 0; j < k; ++j)
  {
    for (int i = 0; i < k; ++i)
    {
      const auto index = std::uint32_t(j * k + i);
      const double a = o.jittered ? hashedUniform(o.seed, 2 * index) : 0.5;
      const double b = o.jittered ? hashedUniform(o.seed, 2 * index + 1) : 0.5;
      const glm::dvec2 p = footprint.centre + ((i + a) / k - 0.5) * footprint.axisU +
                           ((j + b) / k - 0.5) * footprint.axisV;
      glm::dvec2 q = p;
      double depth = 0.0;
      if (o.masking == MicroMasking::ParallaxOcclusion)
      {
        const MicroHit hit = marchParallaxOcclusion(s, p, v, o.marchSteps);
        q = hit.point;
        depth = hit.depth;
      }
      else
      {
        depth = surfaceDepth(s, p);
        if (o.masking == MicroMasking::Parallax)
        {
          q = p - glm::dvec2(v.x, v.y) / v.z * depth;
          depth = surfaceDepth(s, q);
        }
      }
      const MicroTexel texel = sampleMicrostructure(s, q);
      const Frame micro = Frame::fromNormalTangent(texel.normal, glm::dvec3(1.0, 0.0, 0.0));
      const glm::dvec3 vm = micro.toLocal(v);
      if (!(vm.z > 0.0))
        continue;
      for (std::size_t n = 0; n < arrivals.size(); ++n)
      {
        const glm::dvec3 lm = micro.toLocal(lightsLocal[n]);
        if (!(lm.z > 0.0))
          continue;
        if (o.selfShadowing && shadowedTowards(s, q, depth, lightsLocal[n], o.marchSteps))
          continue;
        const glm::dvec3 f = texel.albedo / kPi + specular(o, vm, lm);
        sum += f * lm.z * arrivals[n].irradiance;
      }
    }
  }
  return sum / double(k * k);
}
} // namespace aniso
