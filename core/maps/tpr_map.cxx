#include "core/maps/tpr_map.h"

#include "core/error.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <glm/geometric.hpp>
#include <vector>

namespace aniso
{
namespace
{
constexpr double kPi = 3.14159265358979323846;
constexpr int kMaxSide = 32768;

double radians(double degrees)
{
  return degrees * (kPi / 180.0);
}

std::vector<std::string> split(const std::string& text, char separator)
{
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true)
  {
    const std::size_t end = text.find(separator, start);
    parts.push_back(text.substr(start, end - start));
    if (end == std::string::npos)
    {
      return parts;
    }
    start = end + 1;
  }
}

class PatternParser
{
public:
  explicit PatternParser(const std::string& text) : subject_("TPR pattern '" + text + "'") {}

  [[noreturn]] void fail(const std::string& reason) const { throw errorAbout(subject_, reason); }

  double number(const std::string& field, const char* what) const
  {
    if (field.empty())
    {
      fail(std::string("missing ") + what);
    }
    if (std::isspace(static_cast<unsigned char>(field.front())))
    {
      fail(std::string(what) + " '" + field + "' is not a number");
    }
    errno = 0;
    char* end = nullptr;
    const double value = std::strtod(field.c_str(), &end);
    if (end != field.c_str() + field.size())
    {
      fail(std::string(what) + " '" + field + "' is not a number");
    }
    if (errno == ERANGE || !std::isfinite(value))
    {
      fail(std::string(what) + " '" + field + "' is not a finite number");
    }
    return value;
  }

  glm::dvec2 centre(const std::string& field) const
  {
    const auto uv = split(field, ',');
    if (uv.size() != 2)
    {
      fail("centre '" + field + "' must be U,V");
    }
    return {number(uv[0], "centre u"), number(uv[1], "centre v")};
  }

private:
  std::string subject_;
};
} // namespace

TprParams parseTprPattern(const std::string& text)
{
  const PatternParser parser(text);
  const auto fields = split(text, ':');
  std::string name = fields[0];
  std::transform(name.begin(), name.end(), name.begin(),
                 [](unsigned char ch) { return char(std::tolower(ch)); });

  TprParams params;
  auto expectAtMost = [&](std::size_t count, const char* form)
  {
    if (fields.size() > count)
    {
      parser.fail(std::string("too many fields; expected ") + form);
    }
  };
  if (name == "linear")
  {
    expectAtMost(2, "linear[:ANGLE]");
    params.pattern = TprPattern::Linear;
    if (fields.size() == 2)
    {
      params.angleDegrees = parser.number(fields[1], "angle");
    }
  }
  else if (name == "circular" || name == "radial")
  {
    expectAtMost(2, name == "circular" ? "circular[:U,V]" : "radial[:U,V]");
    params.pattern = name == "circular" ? TprPattern::Circular : TprPattern::Radial;
    if (fields.size() == 2)
    {
      params.centre = parser.centre(fields[1]);
    }
  }
  else if (name == "spiral")
  {
    expectAtMost(3, "spiral[:U,V[:PITCH]]");
    params.pattern = TprPattern::Spiral;
    if (fields.size() >= 2)
    {
      params.centre = parser.centre(fields[1]);
    }
    if (fields.size() == 3)
    {
      params.pitchDegrees = parser.number(fields[2], "pitch");
      if (std::abs(params.pitchDegrees) > 90.0)
      {
        parser.fail("pitch " + fields[2] + " is outside [-90, 90] degrees");
      }
    }
  }
  else if (name == "wave")
  {
    expectAtMost(1, "wave");
    params.pattern = TprPattern::Wave;
  }
  else
  {
    parser.fail("unknown pattern '" + fields[0] +
                "' (expected linear, circular, radial, spiral or wave)");
  }
  return params;
}

glm::dvec2 tprTangentAt(const TprParams& params, const glm::dvec2& uv)
{
  switch (params.pattern)
  {
  case TprPattern::Linear:
  {
    const double angle = radians(params.angleDegrees);
    return {std::cos(angle), std::sin(angle)};
  }
  case TprPattern::Wave:
    return {std::cos(kPi * uv.y), std::sin(kPi * uv.y)};
  case TprPattern::Circular:
  case TprPattern::Radial:
  case TprPattern::Spiral:
    break;
  }
  const glm::dvec2 r = uv - params.centre;
  const double len = std::hypot(r.x, r.y);
  if (!(len > 0.0))
  {
    return {1.0, 0.0};
  }
  const glm::dvec2 radial = r / len;
  const glm::dvec2 circular{-radial.y, radial.x};
  if (params.pattern == TprPattern::Radial)
  {
    return radial;
  }
  if (params.pattern == TprPattern::Circular)
  {
    return circular;
  }
  const double pitch = radians(params.pitchDegrees);
  // Both directions are unit and orthogonal, so the combination is unit as well.
  return std::cos(pitch) * circular + std::sin(pitch) * radial;
}

Image bakeTprMap(const TprParams& params, int width, int height)
{
  if (width < 1 || height < 1 || width > kMaxSide || height > kMaxSide)
  {
    throw errorAbout("TPR map size", std::to_string(width) + "x" + std::to_string(height) +
                                         " is outside 1..32768 per side");
  }
  Image out(width, height, 2);
  for (int row = 0; row < height; ++row)
  {
    const double v = 1.0 - (row + 0.5) / height;
    for (int col = 0; col < width; ++col)
    {
      const double u = (col + 0.5) / width;
      const glm::dvec2 t = tprTangentAt(params, {u, v});
      out.at(col, row, 0) = float(t.x);
      out.at(col, row, 1) = float(t.y);
    }
  }
  return out;
}

Image tprFromAngleImage(const Image& angles)
{
  if (angles.width <= 0 || angles.height <= 0 || angles.channels <= 0 ||
      angles.data.size() != std::size_t(angles.width) * angles.height * angles.channels)
  {
    throw errorAbout("angle image", "empty or inconsistent (" + std::to_string(angles.width) + "x" +
                                        std::to_string(angles.height) + "x" +
                                        std::to_string(angles.channels) + ")");
  }
  Image out(angles.width, angles.height, 2);
  for (int row = 0; row < angles.height; ++row)
  {
    for (int col = 0; col < angles.width; ++col)
    {
      const float a = angles.at(col, row, 0);
      if (!std::isfinite(a))
      {
        throw errorAbout("angle image", "texel (" + std::to_string(col) + ", " +
                                            std::to_string(row) + ") is not finite");
      }
      const double angle = kPi * double(a);
      out.at(col, row, 0) = float(std::cos(angle));
      out.at(col, row, 1) = float(std::sin(angle));
    }
  }
  return out;
}
} // namespace aniso
