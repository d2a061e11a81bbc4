#include "core/models/sv_material.h"

#include "core/brdf/shading_frame.h"
#include "core/error.h"
#include "core/models/texture_sampling.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>

namespace aniso
{
namespace
{
constexpr double kPi = 3.14159265358979323846;

void checkMap(const Image& image, int channels, const char* name)
{
  if (image.width <= 0 || image.height <= 0 || image.channels < channels ||
      image.data.size() != std::size_t(image.width) * image.height * image.channels)
    throw errorAbout("material maps", std::string(name) +
                                          " must be a non-empty image with at least " +
                                          std::to_string(channels) + " channels");
}

// Bilinear, wrapping; texel centres at ((x + 0.5) / W, 1 - (y + 0.5) / H).
// Bilinear, wrapping lookup of up to 4 channels.
std::array<double, 4> bilinear(const Image& image, const glm::dvec2& uv)
{
  const BilinearTaps taps = bilinearTaps(image.width, image.height, uv);
  std::array<double, 4> out{0.0, 0.0, 0.0, 0.0};
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i)
      for (int c = 0; c < std::min(image.channels, 4); ++c)
        out[std::size_t(c)] += taps.wx[i] * taps.wy[j] * image.at(taps.x[i], taps.y[j], c);
  return out;
}

double fibreExponent(double alphaX)
{
  return std::min(1.0 / (2.0 * alphaX * alphaX), kFibreMaxExponent);
}

double fibreSpecular(double ks, double e)
{
  return std::min(ks * std::sqrt(e / (2.0 * kPi)) / kPi, kFibreMaxSpecular);
}
} // namespace

SvTexel sampleSvMaps(const SvMaps& maps, const glm::dvec2& uv)
{
  checkMap(maps.tangentAlpha, 4, "tangentAlpha");
  checkMap(maps.albedoSpecular, 4, "albedoSpecular");
  checkMap(maps.normal, 3, "normal");
  SvTexel texel;
  const auto ta = bilinear(maps.tangentAlpha, uv);
  const glm::dvec2 tangent(ta[0], ta[1]);
  const double len = glm::length(tangent);
  texel.tangent = len > 1e-12 && std::isfinite(len) ? tangent / len : glm::dvec2(1.0, 0.0);
  texel.alphaX = std::clamp(ta[2], kSvMinAlpha, kSvMaxAlpha);
  texel.alphaY = std::clamp(ta[3], kSvMinAlpha, kSvMaxAlpha);
  const auto as = bilinear(maps.albedoSpecular, uv);
  texel.diffuse = glm::clamp(glm::dvec3(as[0], as[1], as[2]), 0.0, 1.0);
  texel.specular = std::clamp(as[3], 0.0, 1.0);
  const auto n = bilinear(maps.normal, uv);
  const glm::dvec3 normal(n[0], n[1], n[2]);
  const double nlen = glm::length(normal);
  texel.normal = nlen > 1e-12 && std::isfinite(nlen) ? normal / nlen : glm::dvec3(0.0, 0.0, 1.0);
  return texel;
}

SvMaps uniformSvMaps(const SvTexel& texel)
{
  SvMaps maps;
  maps.tangentAlpha = Image(1, 1, 4);
  maps.tangentAlpha.data = {float(texel.tangent.x), float(texel.tangent.y), float(texel.alphaX),
                            float(texel.alphaY)};
  maps.albedoSpecular = Image(1, 1, 4);
  maps.albedoSpecular.data = {float(texel.diffuse.x), float(texel.diffuse.y),
                              float(texel.diffuse.z), float(texel.specular)};
  maps.normal = Image(1, 1, 3);
  maps.normal.data = {float(texel.normal.x), float(texel.normal.y), float(texel.normal.z)};
  return maps;
}

Frame svShadingFrame(const glm::dvec3& interpolatedNormal, const glm::dvec3& interpolatedTangent,
                     const SvTexel& texel)
{
  return perturbedFrame(interpolatedNormal, interpolatedTangent, texel.normal, texel.tangent);
}

BlinnPhongAnisoMaterial toBlinnPhong(const SvTexel& texel)
{
  BlinnPhongAnisoMaterial m;
  m.alphaX = texel.alphaX;
  m.alphaY = texel.alphaY;
  m.diffuse = texel.diffuse;
  m.specular = glm::dvec3(texel.specular);
  return m;
}

WardMaterial toWard(const SvTexel& texel, WardForm form)
{
  WardMaterial m;
  m.alphaX = texel.alphaX;
  m.alphaY = texel.alphaY;
  m.diffuse = texel.diffuse;
  m.specular = glm::dvec3(texel.specular);
  m.form = form;
  return m;
}

AsMaterial toAshikhminShirley(const SvTexel& texel)
{
  AsMaterial m;
  m.lobe.nu = exponentFromRoughness(texel.alphaX);
  m.lobe.nv = exponentFromRoughness(texel.alphaY);
  m.f0 = glm::dvec3(texel.specular);
  m.diffuse = texel.diffuse;
  return m;
}

namespace
{
// Banks and Heidrich-Seidel take the same fibre parameters.
template <class FibreMaterial>
FibreMaterial toFibreMaterial(const SvTexel& texel)
{
  FibreMaterial m;
  m.exponent = fibreExponent(texel.alphaX);
  m.diffuse = texel.diffuse;
  m.specular = glm::dvec3(fibreSpecular(texel.specular, m.exponent));
  return m;
}
} // namespace

BanksMaterial toBanks(const SvTexel& texel)
{
  return toFibreMaterial<BanksMaterial>(texel);
}

HeidrichSeidelMaterial toHeidrichSeidel(const SvTexel& texel)
{
  return toFibreMaterial<HeidrichSeidelMaterial>(texel);
}
} // namespace aniso
