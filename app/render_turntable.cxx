#include "app/render_turntable.h"

#include "core/image/image.h"
#include "vtkpasses/render/ViewSettings.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <glm/geometric.hpp>
#include <iomanip>
#include <sstream>

namespace aniso::cli
{
int turntableDigits(int frames)
{
  int digits = 4;
  for (long long n = 10000; frames > n; n *= 10)
  {
    ++digits;
  }
  return digits;
}

std::string turntableFramePath(const std::string& output, int frame, int frames)
{
  const std::filesystem::path path(output);
  std::ostringstream name;
  name << path.stem().string() << '_' << std::setw(turntableDigits(frames)) << std::setfill('0')
       << frame << path.extension().string();
  return (path.parent_path() / name.str()).string();
}

void writeRendered(const std::string& output, const RenderResult& result, bool transparent)
{
  std::string extension = std::filesystem::path(output).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".exr")
  {
    writeImage(output, result.linear);
  }
  else if (transparent)
  {
    writeImage(output, result.display);
  }
  else
  {
    Image rgb(result.display.width, result.display.height, 3);
    for (std::size_t i = 0, n = std::size_t(rgb.width) * rgb.height; i < n; ++i)
    {
      std::copy_n(&result.display.data[i * 4], 3, &rgb.data[i * 3]);
    }
    writeImage(output, rgb);
  }
}

std::vector<double> renderTurntable(RenderSettings settings, int frames, const std::string& output,
                                    std::ostream& out)
{
  // The view's azimuth and elevation as viewDirectionFromAngles takes them.
  const glm::dvec3 d = glm::normalize(settings.view.direction);
  const double azimuth = std::atan2(d.x, -d.y) * 180.0 / M_PI;
  const double elevation = std::asin(std::clamp(d.z, -1.0, 1.0)) * 180.0 / M_PI;
  const bool transparent = settings.display.background == BackgroundMode::Transparent;
  std::vector<double> seconds;
  for (int k = 0; k < frames; ++k)
  {
    const double turned = azimuth + 360.0 * k / frames;
    settings.view.direction = viewDirectionFromAngles(turned, elevation);
    const RenderResult result = renderOffscreen(settings);
    const std::string path = turntableFramePath(output, k, frames);
    writeRendered(path, result, transparent);
    seconds.insert(seconds.end(), result.frameSeconds.begin(), result.frameSeconds.end());
    out << "render: wrote " << path << " (azimuth " << std::fmod(turned + 360.0, 360.0)
        << ", elevation " << elevation << ")\n";
  }
  return seconds;
}
} // namespace aniso::cli
