#include "MaterialSettings.h"

#include "material/parameters.h"

#include <algorithm>
#include <cmath>

namespace aniso
{
double misLobeFraction(const AsLobe& lobe)
{
  // The lobe's solid angle falls as 1 / sqrt((n_u + 1)(n_v + 1)); from a width of 16 (broad,
  // (10, 10) is 11) to 1024 (sharp, (20000, 70) is 1183) the share moves in log2 of it.
  const double width = std::sqrt((lobe.nu + 1.0) * (lobe.nv + 1.0));
  const double t = std::clamp((std::log2(width) - 4.0) / 6.0, 0.0, 1.0);
  return 0.5 + (15.0 / 16.0 - 0.5) * t * t * (3.0 - 2.0 * t);
}

MaterialSettings materialFromParameters(const ParameterSet& parameters, MaterialSettings base)
{
  base.lobe = parameters.lobe();
  base.f0 = parameters.color("f0");
  base.albedo = parameters.color("albedo");
  base.samples = parameters.integer("samples");
  base.lutSize = parameters.integer("lut-size");
  base.brdfLutSamples = parameters.integer("lut-samples");
  base.method =
      parameters.text("method") == "split-sum" ? SpecularMethod::SplitSum : SpecularMethod::Exact;
  base.filtered = parameters.text("filtered") == "on";
  base.halfVectors =
      parameters.text("half-vectors") == "lut" ? HalfVectorSource::Lut : HalfVectorSource::Shader;
  base.environmentSampling = parameters.text("env-sampling") == "mis" ? EnvironmentSampling::Mis
                                                                      : EnvironmentSampling::Off;
  base.heightScale = parameters.real("height-scale");
  return base;
}
} // namespace aniso
