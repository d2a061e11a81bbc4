#include "core/lights/light.h"

#include "core/error.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <glm/geometric.hpp>
#include <limits>
#include <sstream>

namespace aniso
{
namespace
{
bool finite(const glm::dvec3& x)
{
  return std::isfinite(x.x) && std::isfinite(x.y) && std::isfinite(x.z);
}

std::string lower(std::string s)
{
  for (char& c : s)
    c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::vector<std::string> split(const std::string& s, char separator)
{
  std::vector<std::string> parts;
  std::string::size_type start = 0;
  for (;;)
  {
    const std::string::size_type end = s.find(separator, start);
    parts.push_back(s.substr(start, end - start));
    if (end == std::string::npos)
      return parts;
    start = end + 1;
  }
}

std::string trim(const std::string& s)
{
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string::npos)
    return {};
  const auto last = s.find_last_not_of(" \t");
  return s.substr(first, last - first + 1);
}

// A finite number using all of the field; `what` names the field in the error.
double parseNumber(const std::string& field, const std::string& what, const std::string& subject)
{
  const std::string text = trim(field);
  if (text.empty())
    throw errorAbout(subject, what + " has an empty number");
  errno = 0;
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size())
    throw errorAbout(subject, what + ": \"" + text + "\" is not a number");
  // Overflow gives ERANGE with +-HUGE_VAL; underflow (also ERANGE) returns a usable tiny value.
  if (!std::isfinite(value) || (errno == ERANGE && std::abs(value) > 1.0))
    throw errorAbout(subject, what + ": \"" + text + "\" is not a finite number");
  return value;
}

glm::dvec3 parseTriple(const std::string& field, const std::string& what,
                       const std::string& subject)
{
  const std::vector<std::string> parts = split(field, ',');
  if (parts.size() != 3)
    throw errorAbout(subject,
                     what + " needs 3 numbers X,Y,Z (got " + std::to_string(parts.size()) + ")");
  return {parseNumber(parts[0], what, subject), parseNumber(parts[1], what, subject),
          parseNumber(parts[2], what, subject)};
}

std::string formatNumber(double x)
{
  std::ostringstream out;
  out.precision(std::numeric_limits<double>::max_digits10);
  out << x;
  return out.str();
}
} // namespace

void validateLight(const Light& light)
{
  if (light.type == LightType::Directional)
  {
    const double length = glm::length(light.vector);
    if (!(length > 0.0) || !std::isfinite(length))
      throw errorAbout("light", "the direction must be finite and not zero");
  }
  else if (!finite(light.vector))
  {
    throw errorAbout("light", "the position must be finite");
  }
  if (!finite(light.intensity) ||
      !(light.intensity.x >= 0.0 && light.intensity.y >= 0.0 && light.intensity.z >= 0.0))
    throw errorAbout("light", "the intensity must be finite and >= 0");
}

LightArrival arriveAt(const Light& light, const glm::dvec3& position)
{
  LightArrival arrival;
  if (light.type == LightType::Directional)
  {
    arrival.direction = glm::normalize(light.vector);
    arrival.irradiance = light.intensity;
    arrival.distance = std::numeric_limits<double>::infinity();
    return arrival;
  }
  const glm::dvec3 toLight = light.vector - position;
  const double distance = glm::length(toLight);
  arrival.distance = distance;
  if (!(distance > kMinPointLightDistance))
    return arrival; // no light, direction left at +Z
  arrival.direction = toLight / distance;
  arrival.irradiance = light.intensity / (distance * distance);
  return arrival;
}

Light parseLight(const std::string& text)
{
  const std::string subject = "light \"" + text + "\"";
  const std::vector<std::string> fields = split(text, ':');
  if (fields.size() != 3)
    throw errorAbout(subject, "expected dir:X,Y,Z:INTENSITY or point:X,Y,Z:INTENSITY");
  Light light;
  const std::string type = lower(trim(fields[0]));
  if (type == "dir")
    light.type = LightType::Directional;
  else if (type == "point")
    light.type = LightType::Point;
  else
    throw errorAbout(subject, "unknown type \"" + trim(fields[0]) + "\" (use dir or point)");

  const bool directional = light.type == LightType::Directional;
  light.vector = parseTriple(fields[1], directional ? "direction" : "position", subject);
  if (directional)
  {
    const double length = glm::length(light.vector);
    if (!(length > 0.0) || !std::isfinite(length))
      throw errorAbout(subject, "the direction must not be zero");
    light.vector /= length;
  }

  const std::vector<std::string> channels = split(fields[2], ',');
  if (channels.size() == 1)
    light.intensity = glm::dvec3(parseNumber(channels[0], "intensity", subject));
  else if (channels.size() == 3)
    light.intensity = parseTriple(fields[2], "intensity", subject);
  else
    throw errorAbout(subject, "intensity needs 1 number or 3 numbers R,G,B (got " +
                                  std::to_string(channels.size()) + ")");
  if (!(light.intensity.x >= 0.0 && light.intensity.y >= 0.0 && light.intensity.z >= 0.0))
    throw errorAbout(subject, "intensity must be >= 0");
  return light;
}

std::string formatLight(const Light& light)
{
  std::string text = light.type == LightType::Directional ? "dir:" : "point:";
  text += formatNumber(light.vector.x) + "," + formatNumber(light.vector.y) + "," +
          formatNumber(light.vector.z) + ":";
  if (light.intensity.x == light.intensity.y && light.intensity.y == light.intensity.z)
    text += formatNumber(light.intensity.x);
  else
    text += formatNumber(light.intensity.x) + "," + formatNumber(light.intensity.y) + "," +
            formatNumber(light.intensity.z);
  return text;
}
} // namespace aniso
