#include "core/brdf/ggx.h"

#include "core/brdf/ashikhmin_shirley.h"
#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <sstream>

namespace aniso
{
namespace
{
constexpr double kPi = 3.14159265358979323846;

void checkAlpha(const char* name, double value)
{
  if (!(value >= kGgxMinAlpha && value <= kGgxMaxAlpha))
  {
    std::ostringstream reason;
    reason << "must be in [" << kGgxMinAlpha << ", " << kGgxMaxAlpha << "] (got " << value << ")";
    throw errorAbout(name, reason.str());
  }
}

void checkUnitInterval(const char* name, double value)
{
  if (!(value >= 0.0 && value <= 1.0))
  {
    std::ostringstream reason;
    reason << "must be in [0, 1] (got " << value << ")";
    throw errorAbout(name, reason.str());
  }
}
} // namespace

void validateGgxLobe(const GgxLobe& lobe)
{
  checkAlpha("alpha_x", lobe.alphaX);
  checkAlpha("alpha_y", lobe.alphaY);
}

GgxLobe ggxLobeFromVtk(double roughness, double anisotropy)
{
  checkUnitInterval("roughness", roughness);
  checkUnitInterval("anisotropy", anisotropy);
  const double r2 = roughness * roughness;
  const double aspect = std::sqrt(1.0 - 0.9 * anisotropy);
  return {std::max(r2 / aspect, 0.001), std::max(r2 * aspect, 0.001)};
}

double ggxDistribution(const GgxLobe& lobe, const glm::dvec3& h)
{
  if (!(h.z > 0.0))
    return 0.0;
  const double x = h.x / lobe.alphaX;
  const double y = h.y / lobe.alphaY;
  const double s = x * x + y * y + h.z * h.z;
  return 1.0 / (kPi * lobe.alphaX * lobe.alphaY * s * s);
}

double ggxLambda(const GgxLobe& lobe, const glm::dvec3& w)
{
  if (!(w.z > 0.0))
    return std::numeric_limits<double>::infinity();
  const double x = lobe.alphaX * w.x;
  const double y = lobe.alphaY * w.y;
  const double a2 = (x * x + y * y) / (w.z * w.z);
  // Below 1 the difference sqrt(1 + a2) - 1 would cancel; the rationalised form keeps the
  // relative precision of nearly normal directions. An overflowing a2 gives +infinity.
  if (a2 > 1.0)
    return 0.5 * (std::sqrt(1.0 + a2) - 1.0);
  return a2 / (2.0 * (1.0 + std::sqrt(1.0 + a2)));
}

double ggxMasking(const GgxLobe& lobe, const glm::dvec3& w)
{
  if (!(w.z > 0.0))
    return 0.0;
  return 1.0 / (1.0 + ggxLambda(lobe, w));
}

double ggxMaskingShadowing(const GgxLobe& lobe, const glm::dvec3& v, const glm::dvec3& l)
{
  if (!(v.z > 0.0) || !(l.z > 0.0))
    return 0.0;
  return 1.0 / (1.0 + ggxLambda(lobe, v) + ggxLambda(lobe, l));
}

glm::dvec3 evalSpecular(const GgxLobe& lobe, const glm::dvec3& f0, const glm::dvec3& v,
                        const glm::dvec3& l)
{
  if (!(v.z > 0.0) || !(l.z > 0.0))
    return glm::dvec3(0.0);
  const glm::dvec3 h = glm::normalize(v + l);
  const double vDotH = std::max(glm::dot(v, h), 0.0);
  // Masking falls at grazing angles, so the quotient grows only like
  // 1 / (alpha sqrt((n.v)(n.l))): finite for any n.v, n.l > 0.
  const double g2 = ggxMaskingShadowing(lobe, v, l);
  const double scale = ggxDistribution(lobe, h) * g2 / (4.0 * v.z * l.z);
  return scale * schlickFresnel(f0, vDotH);
}

glm::dvec3 sampleVisibleNormal(const GgxLobe& lobe, const glm::dvec3& v, const glm::dvec2& xi)
{
  if (!(v.z > 0.0))
    return {0.0, 0.0, 1.0};
  // The view in the stretched configuration, where the lobe is the isotropic alpha = 1 one and
  // visible normals are uniform over the projected hemisphere.
  const glm::dvec3 vh = glm::normalize(glm::dvec3(lobe.alphaX * v.x, lobe.alphaY * v.y, v.z));
  const double lengthSquared = vh.x * vh.x + vh.y * vh.y;
  const glm::dvec3 t1 = lengthSquared > 0.0
                            ? glm::dvec3(-vh.y, vh.x, 0.0) / std::sqrt(lengthSquared)
                            : glm::dvec3(1.0, 0.0, 0.0);
  const glm::dvec3 t2 = glm::cross(vh, t1);
  // A uniform point on the unit disc, its second coordinate squeezed onto the part of the disc
  // that the visible half of the hemisphere projects to.
  const double r = std::sqrt(std::clamp(xi.x, 0.0, 1.0));
  const double phi = 2.0 * kPi * xi.y;
  const double p1 = r * std::cos(phi);
  double p2 = r * std::sin(phi);
  const double s = 0.5 * (1.0 + vh.z);
  p2 = (1.0 - s) * std::sqrt(std::max(0.0, 1.0 - p1 * p1)) + s * p2;
  const glm::dvec3 nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0, 1.0 - p1 * p1 - p2 * p2)) * vh;
  // Unstretch back to the lobe's configuration.
  return glm::normalize(glm::dvec3(lobe.alphaX * nh.x, lobe.alphaY * nh.y, std::max(0.0, nh.z)));
}

double pdfVisibleNormal(const GgxLobe& lobe, const glm::dvec3& v, const glm::dvec3& h)
{
  if (!(v.z > 0.0) || !(h.z > 0.0))
    return 0.0;
  const double vDotH = glm::dot(v, h);
  if (!(vDotH > 0.0))
    return 0.0;
  return ggxMasking(lobe, v) * vDotH * ggxDistribution(lobe, h) / v.z;
}

double pdfLight(const GgxLobe& lobe, const glm::dvec3& v, const glm::dvec3& l)
{
  if (!(v.z > 0.0))
    return 0.0;
  const glm::dvec3 sum = v + l;
  const double length = glm::length(sum);
  if (!(length > 0.0))
    return 0.0;
  const glm::dvec3 h = sum / length;
  if (!(glm::dot(v, h) > 0.0))
    return 0.0;
  // The v.h of the visible-normal density cancels against the reflection Jacobian 1 / (4 v.h).
  return ggxMasking(lobe, v) * ggxDistribution(lobe, h) / (4.0 * v.z);
}
} // namespace aniso
