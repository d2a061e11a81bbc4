#include "core/env/env_source_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>

namespace aniso
{
namespace
{
constexpr double kPi = 3.14159265358979323846;

double degrees(double radians)
{
  return radians * 180.0 / kPi;
}

std::string printed(const char* format, double value)
{
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}
} // namespace

SkyAngles skyAnglesOf(const glm::dvec3& d, double rotationDegrees)
{
  const double length = glm::length(d);
  if (!(length > 0.0) || !std::isfinite(length))
  {
    return {};
  }
  // Adding +0 turns a -0 into +0, so straight up and down read azimuth 0, not 180.
  double azimuth = degrees(std::atan2(d.x + 0.0, -d.y + 0.0));
  if (std::isfinite(rotationDegrees))
  {
    azimuth = std::fmod(azimuth + rotationDegrees, 360.0);
  }
  if (azimuth < 0.0)
  {
    azimuth += 360.0;
  }
  if (!(azimuth < 360.0)) // -1e-17 + 360 rounds to 360
  {
    azimuth = 0.0;
  }
  return {azimuth, degrees(std::asin(std::clamp(d.z / length, -1.0, 1.0)))};
}

double equivalentDiameterDegrees(double solidAngle)
{
  const double omega = std::clamp(solidAngle, 0.0, 4.0 * kPi);
  return degrees(2.0 * std::acos(std::clamp(1.0 - omega / (2.0 * kPi), -1.0, 1.0)));
}

std::string percentText(double share)
{
  const double percent = 100.0 * share;
  if (percent < 0.05)
  {
    return "<0.1%";
  }
  return printed(percent < 9.95 ? "%.1f%%" : "%.0f%%", percent);
}

std::string sourceText(const EnvSource& source, double rotationDegrees)
{
  const SkyAngles angles = skyAnglesOf(source.direction, rotationDegrees);
  return std::string(spelling(source.kind)) + " at azimuth " +
         printed("%.1f", angles.azimuthDegrees) + ", elevation " +
         printed("%.1f", angles.elevationDegrees) + " (" + printed("%.2g", source.solidAngle) +
         " sr, " + percentText(source.powerShare) + ")";
}

std::string analysisSummary(const EnvAnalysis& analysis)
{
  const std::string concentration = "concentration " + printed("%.2f", analysis.concentration);
  const std::size_t n = analysis.sources.size();
  if (n == 0)
  {
    return "no concentrated sources; " + concentration;
  }
  double share = 0.0;
  for (const EnvSource& s : analysis.sources)
  {
    share += s.powerShare;
  }
  return std::to_string(n) + (n == 1 ? " source carries " : " sources carry ") +
         percentText(share) + " of the power; " + concentration;
}
} // namespace aniso
