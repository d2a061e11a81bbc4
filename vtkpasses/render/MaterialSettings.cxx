#include "vtkpasses/render/MaterialSettings.h"

#include "core/parameters/parameters.h"

namespace aniso
{
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
