// What the environment analysis (core/env/env_sources.h) finds: per environment its threshold,
// concentration and source share, then each listed source. Arguments: environment specs
// (openEnvironment's); none: Blender's eight HDRIs and the built-ins. For a sun-sky also the
// whole sun's power as the analysis sees it (the largest source's excess + (T - sky) x its
// solid angle) against the analytic radiance x 2 pi (1 - cos r), and the direction's error.
#include "core/env/env_sources.h"
#include "core/env/sun_sky.h"
#include "core/error.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <string>
#include <vector>

int main(int argc, char** argv)
{
  std::vector<std::string> specs(argv + 1, argv + argc);
  if (specs.empty())
  {
    for (const char* name :
         {"city", "courtyard", "forest", "interior", "night", "studio", "sunrise", "sunset"})
      specs.push_back(std::string("/usr/share/blender/datafiles/studiolights/world/") + name +
                      ".exr");
    specs.insert(specs.end(), {"builtin:studio", "builtin:sunsky", "builtin:white"});
  }
  constexpr double kDegrees = 180.0 / 3.14159265358979323846;
  for (const std::string& spec : specs)
  {
    try
    {
      const auto env = aniso::openEnvironment(spec);
      const auto start = std::chrono::steady_clock::now();
      const aniso::EnvAnalysis a = aniso::analyzeEnvironment(*env);
      const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const std::size_t slash = spec.find_last_of('/');
      std::printf("%s: %dx%d, median %.4g, mean %.4g, T %.4g, concentration %.3f, source share "
                  "%.3f, concentrated %s, %zu listed (%.2f s)\n",
                  slash == std::string::npos ? spec.c_str() : spec.c_str() + slash + 1, a.width,
                  a.height, a.medianLuminance, a.meanLuminance, a.threshold, a.concentration,
                  a.sourcePowerShare, a.concentrated() ? "yes" : "no", a.sources.size(), seconds);
      for (const aniso::EnvSource& s : a.sources)
        std::printf("  %-6s share %.4f  solid angle %.3e sr  radius %6.2f deg  texels %6d  "
                    "peak %.4g  elevation %6.2f deg  azimuth %7.2f deg\n",
                    aniso::spelling(s.kind), s.powerShare, s.solidAngle, s.angularRadius * kDegrees,
                    s.texels, s.peakLuminance, std::asin(s.direction.z) * kDegrees,
                    std::atan2(s.direction.y, s.direction.x) * kDegrees);
      const auto* sunSky = dynamic_cast<const aniso::SunSkyEnvironment*>(env.get());
      if (sunSky && !a.sources.empty())
      {
        const aniso::EnvSource& s = a.sources[0];
        const double analytic = sunSky->sun().radiance.x * sunSky->sunSolidAngle();
        const double seen = s.power.x + (a.threshold - sunSky->sky().x) * s.solidAngle;
        std::printf("  whole sun %.6g against %.6g analytic (%+.3f%%), direction off by %.4f deg\n",
                    seen, analytic, 100.0 * (seen / analytic - 1.0),
                    std::acos(std::min(1.0, glm::dot(s.direction, sunSky->sun().direction))) *
                        kDegrees);
      }
    }
    catch (const aniso::Error& error)
    {
      std::printf("%s\n", error.what());
      return 1;
    }
  }
  return 0;
}
