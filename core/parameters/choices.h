#pragma once
// The choices of the declared Text parameters (core/parameters/parameters.h) as enums, so code
// switches on values instead of comparing spellings. The spellings are stated once, in the
// declaration (parameters.cxx), whose `choices` are built from them. GL-free and Qt-free.
//
// Each parseX reads one of the parameter's choices; any other text throws aniso::Error
// "KEY: 'TEXT' is not one of A, B" (the message checkParameterValue gives). spelling() is the
// inverse: the choice that parses back to the value.
#include "core/fields/field_mapping.h"
#include "core/microstructure/microstructure.h"

#include <string_view>

namespace aniso
{
// "method"
enum class SpecularMethod
{
  SplitSum, // the source method: normalised sum of L (n.l) times F0 s + b from the BRDF LUT
  Exact,    // the same samples weighted by F (n.l) / max(n.l, n.v): no split-sum bias
};
SpecularMethod parseSpecularMethod(std::string_view text);
std::string_view spelling(SpecularMethod value);

// "half-vectors"
enum class HalfVectorSource
{
  Lut,    // fetched from the half-vector LUT (as published)
  Shader, // computed per sample in the shader
};
HalfVectorSource parseHalfVectorSource(std::string_view text);
std::string_view spelling(HalfVectorSource value);

// "env-sampling"
enum class EnvironmentSampling
{
  Auto,    // chosen by the environment: Sources where its analysis finds concentrated sources
           // (core/env/env_sources.h, EnvAnalysis::concentrated), Off elsewhere
  Off,     // lobe samples only (the published method)
  Mis,     // one-sample MIS of lobe and environment samples (exact method only)
  Sources, // the sources split off: the residual by lobe samples, the sources by their own
           // samples and the lobe's, combined by MIS (exact method only)
};
EnvironmentSampling parseEnvironmentSampling(std::string_view text);
std::string_view spelling(EnvironmentSampling value);

// "quality-mode"
enum class QualityMode
{
  Samples, // a still view refines to target-samples
  Error,   // a still view refines to error-target by the error model
};
QualityMode parseQualityMode(std::string_view text);
std::string_view spelling(QualityMode value);

// "bump"
enum class BumpMapping
{
  None,       // the maps leave the shading frame as it is
  Normal,     // the normal map perturbs the normal
  Quaternion, // the quaternion map (baked from the normal map when none is given) turns the frame
};
BumpMapping parseBumpMapping(std::string_view text);
std::string_view spelling(BumpMapping value);

// "background"
enum class BackgroundMode
{
  Environment, // the environment seen along each view ray (a skybox)
  Color,       // a uniform linear radiance (backgroundColor)
  Transparent, // nothing: PNG alpha is the coverage of the surfaces
};
BackgroundMode parseBackgroundMode(std::string_view text);
std::string_view spelling(BackgroundMode value);

// "line-width-unit": what an illuminated line's width (line-width) is measured in.
enum class LineWidthUnit
{
  Pixels, // on screen, the same at every depth
  World,  // the mesh's own length units: a ribbon of that width, thinner farther away
};
LineWidthUnit parseLineWidthUnit(std::string_view text);
std::string_view spelling(LineWidthUnit value);

// "tone-mapping"
enum class ToneMapping
{
  Aces,     // Narkowicz's fit of the ACES filmic curve: x(2.51x+0.03) / (x(2.43x+0.59)+0.14)
  Reinhard, // x / (1 + x)
  Clamp,    // min(x, 1): no compression, exact up to 1
};
ToneMapping parseToneMapping(std::string_view text);
std::string_view spelling(ToneMapping value);

// "leadr-filter"
enum class LeadrFilter
{
  Leadr,         // the slope moments
  NormalMapping, // only their mean (plain normal mapping)
};
LeadrFilter parseLeadrFilter(std::string_view text);
std::string_view spelling(LeadrFilter value);

// "structure", "masking" and "micro-brdf" (the enums of core/microstructure/microstructure.h)
MicroPattern parseMicroPattern(std::string_view text);
std::string_view spelling(MicroPattern value);
MicroMasking parseMicroMasking(std::string_view text);
std::string_view spelling(MicroMasking value);
MicroBrdf parseMicroBrdf(std::string_view text);
std::string_view spelling(MicroBrdf value);

// "field-target" and "field-colormap" (the enums of core/fields/field_mapping.h, color_map.h)
FieldTarget parseFieldTarget(std::string_view text);
std::string_view spelling(FieldTarget value);
ColorMap parseColorMap(std::string_view text);
std::string_view spelling(ColorMap value);

// "filtered", "jitter-grid" and "self-shadow": KEY names the parameter (its choices, in its
// order, make the message).
enum class OnOff
{
  Off,
  On,
};
OnOff parseOnOff(std::string_view key, std::string_view text);
std::string_view spelling(OnOff value);
} // namespace aniso
