#include "core/parameters/parameters.h"

#include "core/error.h"
#include "core/fields/field_mapping.h"
#include "core/leadr/leadr.h"
#include "core/lut/lut.h"
#include "core/microstructure/microstructure.h"
#include "core/parameters/choices.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <initializer_list>
#include <stdexcept>
#include <utility>

namespace aniso
{
namespace
{
ParameterSpec number(std::string_view name, std::string_view label, ParameterType type,
                     double defaultValue, double minimum, double maximum, double step,
                     ParameterScale scale, std::string_view unit, std::string_view help)
{
  ParameterSpec s;
  s.name = name;
  s.label = label;
  s.type = type;
  s.defaultValue = {defaultValue, defaultValue, defaultValue};
  s.minimum = minimum;
  s.maximum = maximum;
  s.step = step;
  s.scale = scale;
  s.unit = unit;
  s.help = help;
  return s;
}

ParameterSpec color(std::string_view name, std::string_view label, std::array<double, 3> value,
                    double step, std::string_view help)
{
  ParameterSpec s = number(name, label, ParameterType::Color, 0.0, 0.0, 1.0, step,
                           ParameterScale::Linear, {}, help);
  s.defaultValue = value;
  return s;
}

ParameterSpec text(std::string_view name, std::string_view label, std::string_view value,
                   std::string_view help)
{
  ParameterSpec s;
  s.name = name;
  s.label = label;
  s.type = ParameterType::Text;
  s.defaultText = value;
  s.help = help;
  return s;
}

// The choices of an enum-backed parameter, in ORDER, and its default VALUE, spelt by spelling().
template <typename E>
ParameterSpec choice(std::string_view name, std::string_view label, std::initializer_list<E> order,
                     E value, std::string_view help)
{
  ParameterSpec s = text(name, label, spelling(value), help);
  for (E e : order)
  {
    s.choices.push_back(spelling(e));
  }
  return s;
}

ParameterSpec powerOfTwo(ParameterSpec s)
{
  s.powerOfTwo = true;
  return s;
}

ParameterSpec affecting(Affects roles, ParameterSpec s)
{
  s.roles = roles;
  return s;
}

ParameterSpec ofMaterial(ParameterSpec s)
{
  s.scope = ParameterScope::Material;
  return s;
}

// The spelling of each value of an enum-backed choice: the only place these words are written.
template <typename E>
struct Spelling
{
  E value;
  std::string_view text;
};

constexpr Spelling<SpecularMethod> kSpecularMethods[] = {{SpecularMethod::Exact, "exact"},
                                                         {SpecularMethod::SplitSum, "split-sum"}};
constexpr Spelling<HalfVectorSource> kHalfVectorSources[] = {{HalfVectorSource::Shader, "shader"},
                                                             {HalfVectorSource::Lut, "lut"}};
constexpr Spelling<EnvironmentSampling> kEnvironmentSamplings[] = {
    {EnvironmentSampling::Auto, "auto"},
    {EnvironmentSampling::Off, "off"},
    {EnvironmentSampling::Mis, "mis"},
    {EnvironmentSampling::Sources, "sources"}};
constexpr Spelling<QualityMode> kQualityModes[] = {{QualityMode::Samples, "samples"},
                                                   {QualityMode::Error, "error"}};
constexpr Spelling<BumpMapping> kBumpMappings[] = {{BumpMapping::None, "none"},
                                                   {BumpMapping::Normal, "normal"},
                                                   {BumpMapping::Quaternion, "quaternion"}};
constexpr Spelling<BackgroundMode> kBackgroundModes[] = {{BackgroundMode::Environment, "env"},
                                                         {BackgroundMode::Color, "color"},
                                                         {BackgroundMode::Transparent, "none"}};
constexpr Spelling<LineWidthUnit> kLineWidthUnits[] = {{LineWidthUnit::Pixels, "pixels"},
                                                       {LineWidthUnit::World, "world"}};
constexpr Spelling<ToneMapping> kToneMappings[] = {{ToneMapping::Aces, "aces"},
                                                   {ToneMapping::Reinhard, "reinhard"},
                                                   {ToneMapping::Clamp, "clamp"}};
constexpr Spelling<LeadrFilter> kLeadrFilters[] = {{LeadrFilter::Leadr, "leadr"},
                                                   {LeadrFilter::NormalMapping, "normal-mapping"}};
constexpr Spelling<MicroPattern> kMicroPatterns[] = {
    {MicroPattern::Pyramids, "pyramids"},
    {MicroPattern::InvertedPyramids, "inverted-pyramids"},
    {MicroPattern::Grooves, "grooves"},
    {MicroPattern::Silk, "silk"}};
constexpr Spelling<MicroMasking> kMicroMaskings[] = {{MicroMasking::ParallaxOcclusion, "pom"},
                                                     {MicroMasking::Parallax, "parallax"},
                                                     {MicroMasking::Normal, "normal"}};
constexpr Spelling<MicroBrdf> kMicroBrdfs[] = {{MicroBrdf::GgxSmithSchlick, "ggx"},
                                               {MicroBrdf::BlinnPhong, "blinn-phong"}};
constexpr Spelling<FieldTarget> kFieldTargets[] = {{FieldTarget::Albedo, "albedo"},
                                                  {FieldTarget::F0, "f0"},
                                                  {FieldTarget::Roughness, "roughness"},
                                                  {FieldTarget::Anisotropy, "anisotropy"}};
constexpr Spelling<ColorMap> kColorMaps[] = {{ColorMap::Viridis, "viridis"},
                                             {ColorMap::Cividis, "cividis"},
                                             {ColorMap::CoolToWarm, "cool-to-warm"},
                                             {ColorMap::Grayscale, "grayscale"}};
constexpr Spelling<OnOff> kOnOff[] = {{OnOff::Off, "off"}, {OnOff::On, "on"}};

template <typename E, std::size_t N>
std::string_view spellingIn(const Spelling<E> (&table)[N], E value)
{
  const auto* s = std::find_if(std::begin(table), std::end(table),
                               [&](const Spelling<E>& e) { return e.value == value; });
  if (s == std::end(table))
  {
    throw std::logic_error("a choice without a spelling");
  }
  return s->text;
}

// The value TEXT spells among the choices of parameter KEY, checked as every value is (so the
// message is checkParameterValue's).
template <typename E, std::size_t N>
E parseIn(const Spelling<E> (&table)[N], std::string_view key, std::string_view text)
{
  ParameterValue value;
  value.text = std::string(text);
  checkParameterValue(parameterSpec(key), value, std::string(key));
  const auto* s = std::find_if(std::begin(table), std::end(table),
                               [&](const Spelling<E>& e) { return e.text == text; });
  if (s == std::end(table))
  {
    throw std::logic_error(std::string(key) + ": its choices are not of this enum");
  }
  return s->value;
}

std::vector<ParameterSpec> declare()
{
  using T = ParameterType;
  using S = ParameterScale;
  using A = Affects;
  // The default material is brushed aluminium: sharp across the brushing (n_u, along t) and
  // broad along it (n_v), so highlights stretch along b as on a brushed plate.
  return {
      ofMaterial(affecting(A::Uniforms | A::Luts | A::LitModels,
                number("nu", "n_u", T::Real, 1000.0, 0.0, kMaxExponent, 1.0, S::Logarithmic, {},
                       "Ashikhmin-Shirley exponent along the tangent t; higher is sharper"))),
      ofMaterial(affecting(A::Uniforms | A::Luts | A::LitModels,
                number("nv", "n_v", T::Real, 50.0, 0.0, kMaxExponent, 1.0, S::Logarithmic, {},
                       "Ashikhmin-Shirley exponent along the bitangent b; higher is sharper"))),
      ofMaterial(affecting(A::Uniforms | A::LitModels | A::SurfaceModels,
                color("f0", "F0", {0.913, 0.922, 0.924}, 0.001,
                      "Fresnel reflectance at normal incidence, linear RGB; the default is "
                      "aluminium"))),
      ofMaterial(affecting(A::Uniforms | A::LitModels | A::SurfaceModels,
                color("albedo", "Albedo", {0.0, 0.0, 0.0}, 0.01,
                      "diffuse Lambert albedo, linear RGB; metals have none"))),
      affecting(A::Uniforms, number("samples", "Samples", T::Integer, 16.0, 1.0, 1024.0, 1.0,
                                    S::Logarithmic, {}, "importance samples per pixel and frame")),
      affecting(A::Luts, number("lut-size", "LUT size", T::Integer, 64.0, kMinLutSize, kMaxLutSize,
                                1.0, S::Logarithmic, "texels",
                                "width and height of the half-vector and BRDF lookup tables")),
      affecting(A::Luts, number("lut-samples", "LUT samples", T::Integer, 1024.0, 1.0,
                                kMaxLutSamples, 1.0, S::Logarithmic, {},
                                "importance samples per texel of the BRDF lookup table")),
      affecting(A::FrameCost,
                text("env", "Environment", "builtin:studio",
                     "environment: an equirectangular HDR/EXR file, builtin:studio, builtin:white "
                     "or builtin:sunsky")),
      // The lit models' lights from the environment's sources turn with it.
      affecting(A::LitModels,
                number("env-rotation", "Rotation", T::Real, 0.0, -180.0, 180.0, 1.0, S::Linear,
                       "deg", "rotation of the environment about the world Z axis")),
      affecting(A::Display, number("exposure", "Exposure", T::Real, 0.0, -16.0, 16.0, 0.1,
                                   S::Linear, "EV", "exposure applied before tone mapping")),
      affecting(A::FrameCost, powerOfTwo(number("cube-size", "Cube size", T::Integer, 256.0, 1.0,
                                                2048.0, 1.0, S::Logarithmic, "texels",
                                                "edge of a level-0 environment cubemap face"))),
      // How a material is shaded and a scene shown (the application's docks and sessions).
      affecting(A::Variant | A::FrameCost,
                choice("method", "Specular method",
                       {SpecularMethod::Exact, SpecularMethod::SplitSum}, SpecularMethod::Exact,
                       "specular integration: exact per-sample AS weights, or the split sum with "
                       "the BRDF lookup table")),
      affecting(A::Variant | A::FrameCost,
                choice("filtered", "Filtered sampling", {OnOff::On, OnOff::Off}, OnOff::On,
                       "read each sample at the environment mip level its pdf and the sample "
                       "count call for")),
      affecting(A::Variant | A::FrameCost,
                choice("env-sampling", "Environment sampling",
                       {EnvironmentSampling::Auto, EnvironmentSampling::Off,
                        EnvironmentSampling::Mis, EnvironmentSampling::Sources},
                       EnvironmentSampling::Auto,
                       "exact method: how the environment's bright sources are found. auto: "
                       "sources when the environment's analysis finds concentrated ones, off "
                       "otherwise; off: lobe samples only; mis: also sample the whole "
                       "environment by its luminance (one-sample MIS); sources: split the "
                       "sources off, sample them and the smooth rest separately")),
      // The environment's analysis' sources (core/lights/env_lights.h) as directional lights of
      // the lit models and LEADR (which then reads the residual: the sources are not counted
      // twice) beside the scene's own lights.
      affecting(A::FrameCost | A::LitModels | A::SurfaceModels,
                choice("env-lights", "Environment lights", {OnOff::On, OnOff::Off}, OnOff::On,
                       "light the lit models and LEADR by the environment's sun, lamps and "
                       "windows too (its analysis' sources as directional lights, beside the "
                       "scene's lights, up to 8 in all)")),
      // The LUT is the default: equally accurate, and 1.7x faster than computing the half
      // vectors at 64 samples on llvmpipe (docs/BENCHMARKS.md, "Frame time").
      affecting(A::Variant | A::FrameCost,
                choice("half-vectors", "Half vectors",
                       {HalfVectorSource::Shader, HalfVectorSource::Lut}, HalfVectorSource::Lut,
                       "where the importance-sampled half vectors come from: computed in the "
                       "shader or fetched from the half-vector lookup table")),
      number("target-samples", "Quality", T::Integer, 4096.0, 1.0, 65536.0, 1.0, S::Logarithmic,
             {},
             "samples per pixel a still view accumulates by progressive refinement; with "
             "quality-mode error the most it accumulates"),
      // The quality as an error target (core/quality/error_estimate.h): the still view stops
      // once the error estimated from its own frames is at the target, as renderers with a noise
      // threshold do, so a scene that converges fast stops early and one under a sun or lamps
      // refines as long as it needs, up to target-samples.
      choice("quality-mode", "Quality by", {QualityMode::Samples, QualityMode::Error},
             QualityMode::Error,
             "what stops a still view: target-samples reached, or (error) the error estimated "
             "from its own frames at error-target, target-samples then the most"),
      number("error-target", "Error target", T::Real, 0.01, 1e-4, 1.0, 1e-4, S::Logarithmic, {},
             "relative L2 error at which a still view stops with quality-mode error (0.01 = 1%), "
             "as estimated from its own frames; also 'aniso render --converge' and, by the "
             "error model of one frame, 'aniso render --quality'"),
      ofMaterial(affecting(A::Variant | A::FrameCost,
                choice("bump", "Bump mapping",
                       {BumpMapping::None, BumpMapping::Normal, BumpMapping::Quaternion},
                       BumpMapping::None,
                       "how the maps perturb the shading frame: not at all, by the normal map, or "
                       "by the quaternion map (baked from the normal map when none is given)"))),
      ofMaterial(affecting(A::Uniforms,
                number("height-scale", "Height scale", T::Real, 0.02, 0.0, 0.5, 0.001, S::Linear,
                       "uv",
                       "relief depth of parallax occlusion mapping, in texture-coordinate "
                       "units"))),
      ofMaterial(affecting(A::FrameCost | A::LitModels | A::SurfaceModels,
                text("tangents", "Tangents", "auto",
                     "tangent field: auto (the mesh's, else from UVs, else face-u on a STEP or "
                     "IGES part, else axis:1,0,0), uv, axis:X,Y,Z, around:X,Y,Z, radial:X,Y,Z, "
                     "face-u, face-v: along a CAD face's own u or v (a turned face: round "
                     "or along its axis), or array:NAME: along the mesh's vector array NAME"))),
      // A data field of the mesh that drives the material (core/fields/field_mapping.h): its
      // values reach the shader as a vertex attribute, the range and the target's values as
      // uniforms, so dragging them never recompiles nor re-uploads the mesh.
      ofMaterial(affecting(A::Uniforms | A::Variant | A::FrameCost,
                text("field", "Field",  "none",
                     "a data array that drives the material, none or NAME (a point or cell "
                     "array; a vector's magnitude), NAME:magnitude, NAME:x|y|z or NAME:N "
                     "(one component, from 0); cell values are averaged to the points"))),
      ofMaterial(affecting(A::Uniforms | A::Variant | A::FrameCost,
                choice("field-target", "Field drives",
                       {FieldTarget::Albedo, FieldTarget::F0, FieldTarget::Roughness,
                        FieldTarget::Anisotropy},
                       FieldTarget::Albedo,
                       "what the field sets, albedo or f0 (through field-colormap), roughness "
                       "(n_u and n_v times field-low to field-high) or anisotropy (strength "
                       "field-low to field-high, 0 isotropic, 1 the material's lobe)"))),
      ofMaterial(affecting(A::Uniforms,
                choice("field-colormap", "Colour map",
                       {ColorMap::Viridis, ColorMap::Cividis, ColorMap::CoolToWarm,
                        ColorMap::Grayscale},
                       ColorMap::Viridis,
                       "colour map of the field, one of ParaView's presets (Viridis "
                       "(matplotlib), Cividis, Cool to Warm, Grayscale) with its NaN colour"))),
      ofMaterial(affecting(A::Uniforms,
                text("field-range", "Field range", "auto",
                     "the field's values mapped to the colour map's ends, auto (the finite "
                     "range over the parts that show the field) or MIN,MAX"))),
      ofMaterial(affecting(A::Uniforms,
                number("field-low", "Field low", T::Real, 0.0, 0.0, 1000.0, 0.01, S::Linear, {},
                       "for roughness the exponents' scale at the range's minimum, for "
                       "anisotropy the strength there (clamped to [0, 1])"))),
      ofMaterial(affecting(A::Uniforms,
                number("field-high", "Field high", T::Real, 1.0, 0.0, 1000.0, 0.01, S::Linear, {},
                       "for roughness the exponents' scale at the range's maximum, for "
                       "anisotropy the strength there (clamped to [0, 1])"))),
      // Illuminated lines (a file's polylines, vtkpasses/mesh/LineSet.h): their width, per
      // material, so that each line part has its own.
      ofMaterial(affecting(A::Uniforms | A::FrameCost | A::LitModels,
                           number("line-width", "Line width", T::Real, 2.0, 1e-4, 1e4, 0.1,
                                  S::Logarithmic, {},
                                  "illuminated lines (a file's polylines): their width, in "
                                  "line-width-unit"))),
      ofMaterial(affecting(A::Uniforms | A::FrameCost | A::LitModels,
                           choice("line-width-unit", "Line width unit",
                                  {LineWidthUnit::Pixels, LineWidthUnit::World},
                                  LineWidthUnit::Pixels,
                                  "what line-width is in: pixels on screen, or world (the "
                                  "mesh's length units: thinner farther away)"))),
      // How STEP and IGES parts are tessellated (vtkpasses/mesh/CadReader.h). 0.001 of a part's
      // diagonal keeps a turned part's outline and highlight smooth at a full-window view; the
      // command line also takes an absolute length ("--cad-deflection 0.05mm").
      affecting(A::Meshes | A::FrameCost | A::LitModels | A::SurfaceModels,
                number("cad-deflection", "CAD deflection", T::Real, 0.001, 1e-6, 0.5, 1e-4,
                       S::Logarithmic, {},
                       "STEP and IGES: the largest distance of a triangle from its face, as a "
                       "fraction of the part's bounding-box diagonal (smaller: finer)")),
      affecting(A::Meshes | A::FrameCost | A::LitModels | A::SurfaceModels,
                number("cad-angle", "CAD angle", T::Real, 20.0, 0.5, 90.0, 0.5, S::Logarithmic,
                       "deg",
                       "STEP and IGES: the largest angle between the normals along a triangle's "
                       "edge (smaller: finer on small radii)")),
      affecting(
          A::Display,
          choice("background", "Background",
                 {BackgroundMode::Environment, BackgroundMode::Color, BackgroundMode::Transparent},
                 BackgroundMode::Environment,
                 "what lies behind the surfaces: the environment, background-color, or "
                 "nothing (transparent)")),
      affecting(A::Display, color("background-color", "Background colour", {0.18, 0.18, 0.18}, 0.01,
                                  "linear radiance of a plain background")),
      affecting(A::Display,
                choice("legend", "Field legend", {OnOff::On, OnOff::Off}, OnOff::On,
                       "a colour legend of each field shown through a colour map (field), at "
                       "the right of the view, in screenshots and PNG files (not in EXR)")),
      affecting(A::Display,
                choice("tone-mapping", "Tone mapping",
                       {ToneMapping::Aces, ToneMapping::Reinhard, ToneMapping::Clamp},
                       ToneMapping::Aces,
                       "display transform from linear radiance for the screen and PNG files")),
      // The LEADR and microstructure models (core/leadr, core/microstructure; model key).
      affecting(A::FrameCost, number("leadr-scale", "Relief scale", T::Real, 1.0, 0.0, 1e6, 0.01,
                                     S::Linear, {}, "leadr: heights of the relief times this")),
      affecting(A::FrameCost,
                number("leadr-tiles", "Relief tiles", T::Real, 8.0, 1e-3, 1e6, 1.0, S::Logarithmic,
                       {}, "leadr: repeats of the relief per unit of texture coordinate")),
      affecting(A::FrameCost, number("leadr-roughness", "Base roughness", T::Real, 0.15,
                                     kLeadrMinAlpha, kLeadrMaxAlpha, 0.01, S::Linear, {},
                                     "leadr: base Beckmann roughness added to every texel")),
      affecting(A::FrameCost,
                number("leadr-grid", "Slope grid", T::Integer, 4.0, 1.0, 16.0, 1.0, S::Linear, {},
                       "leadr: slope-space grid N x N for the environment and diffuse")),
      affecting(A::FrameCost,
                choice("leadr-filter", "Filtering",
                       {LeadrFilter::Leadr, LeadrFilter::NormalMapping}, LeadrFilter::Leadr,
                       "leadr: the slope moments, or only their mean (plain normal mapping)")),
      affecting(A::FrameCost,
                choice("structure", "Structure",
                       {MicroPattern::Pyramids, MicroPattern::InvertedPyramids,
                        MicroPattern::Grooves, MicroPattern::Silk},
                       MicroPattern::Pyramids,
                       "microstructure: the repeating structure (it turns with the TPR map)")),
      affecting(A::FrameCost, number("micro-grid", "Grid", T::Integer, 4.0, 1.0, 64.0, 1.0,
                                     S::Linear, {}, "microstructure: K x K samples per pixel")),
      affecting(A::FrameCost, choice("jitter-grid", "Jittered grid", {OnOff::Off, OnOff::On},
                                     OnOff::Off, "microstructure: one random point per grid cell")),
      affecting(
          A::FrameCost,
          choice("masking", "Masking",
                 {MicroMasking::ParallaxOcclusion, MicroMasking::Parallax, MicroMasking::Normal},
                 MicroMasking::ParallaxOcclusion,
                 "microstructure: parallax occlusion, parallax or normal mapping")),
      affecting(A::FrameCost,
                choice("self-shadow", "Self-shadowing", {OnOff::Off, OnOff::On}, OnOff::Off,
                       "microstructure: shadows of the structure per light")),
      affecting(A::FrameCost,
                choice("micro-brdf", "BRDF", {MicroBrdf::GgxSmithSchlick, MicroBrdf::BlinnPhong},
                       MicroBrdf::GgxSmithSchlick,
                       "microstructure: GGX with Smith-Schlick or normalised Blinn-Phong")),
      affecting(A::FrameCost, number("micro-roughness", "Roughness", T::Real, 0.3, 1e-3, 1.0, 0.01,
                                     S::Linear, {}, "microstructure: GGX alpha")),
      affecting(A::FrameCost, number("blinn-exponent", "Exponent", T::Real, 100.0, 0.0, 1e6, 1.0,
                                     S::Logarithmic, {}, "microstructure: Blinn-Phong exponent")),
      affecting(A::FrameCost,
                number("structure-depth", "Depth", T::Real, 0.1, 1e-3, kMicroMaxDepth, 0.01,
                       S::Linear, "tiles", "microstructure: relief depth in tile widths")),
      affecting(A::FrameCost,
                number("structure-tiles", "Tiles", T::Real, 64.0, 1e-3, 1e6, 1.0, S::Logarithmic,
                       {}, "microstructure: tiles per unit of texture coordinate")),
  };
}

std::size_t indexOf(std::string_view name)
{
  const auto& specs = parameterSpecs();
  for (std::size_t i = 0; i < specs.size(); ++i)
  {
    if (specs[i].name == name)
    {
      return i;
    }
  }
  throw errorAbout(std::string(name), "unknown parameter");
}

std::string quoted(std::string_view text)
{
  return "'" + std::string(text) + "'";
}

bool startsWithSpace(std::string_view text)
{
  return !text.empty() && (text.front() == ' ' || text.front() == '\t' || text.front() == '\n');
}

// The whole of TEXT as an integer (decimal digits, optional sign) or as a finite real.
double parseNumber(std::string_view text, bool integer, const std::string& subject)
{
  const std::string s(text);
  const std::string notA = quoted(text) + (integer ? " is not an integer" : " is not a number");
  if (s.empty() || startsWithSpace(s))
  {
    throw errorAbout(subject, notA);
  }
  char* end = nullptr;
  errno = 0;
  const double v = integer ? static_cast<double>(std::strtoll(s.c_str(), &end, 10))
                           : std::strtod(s.c_str(), &end);
  if (end != s.c_str() + s.size())
  {
    throw errorAbout(subject, notA);
  }
  if (integer && errno == ERANGE)
  {
    throw errorAbout(subject, quoted(text) + " is too large");
  }
  // ERANGE also flags underflow to a tiny or zero value, which is a fine number.
  if (!std::isfinite(v) || (errno == ERANGE && std::abs(v) > 1.0))
  {
    throw errorAbout(subject, quoted(text) + " is not a finite number");
  }
  return v;
}
} // namespace

const std::vector<ParameterSpec>& parameterSpecs()
{
  static const std::vector<ParameterSpec> specs = declare();
  return specs;
}

const ParameterSpec& parameterSpec(std::string_view name)
{
  return parameterSpecs()[indexOf(name)];
}

ParameterValue defaultParameterValue(const ParameterSpec& spec)
{
  ParameterValue v;
  v.number = spec.defaultValue;
  v.text = std::string(spec.defaultText);
  return v;
}

std::string formatNumber(double value)
{
  // Scientific: the fewest digits that read back exactly, exponent without "+" or leading
  // zeros (1e+06 -> 1e6, 1.5e-05 -> 1.5e-5).
  char buffer[512];
  for (int digits = 0; digits <= 17; ++digits)
  {
    std::snprintf(buffer, sizeof buffer, "%.*e", digits, value);
    if (std::strtod(buffer, nullptr) == value)
    {
      break;
    }
  }
  std::string scientific(buffer);
  const std::size_t e = scientific.find('e');
  std::string exponent = scientific.substr(e + 1);
  const bool negative = exponent[0] == '-';
  exponent.erase(0, 1);
  exponent.erase(0, std::min(exponent.find_first_not_of('0'), exponent.size() - 1));
  scientific = scientific.substr(0, e) + "e" + (negative ? "-" : "") + exponent;

  // Fixed: the fewest decimals that read back exactly, if that is not much longer, since
  // "1000" and "-180" read better than "1e3" and "-1.8e2".
  if (std::abs(value) < 1e17)
  {
    for (int decimals = 0; decimals <= 20; ++decimals)
    {
      std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
      if (std::strtod(buffer, nullptr) == value)
      {
        const std::string fixed(buffer);
        return fixed.size() < scientific.size() + 3 ? fixed : scientific;
      }
    }
  }
  return scientific;
}

void checkParameterValue(const ParameterSpec& spec, const ParameterValue& value,
                         const std::string& subject)
{
  if (spec.type == ParameterType::Text)
  {
    if (value.text.empty())
    {
      throw errorAbout(subject, "empty value");
    }
    if (!spec.choices.empty() &&
        std::find(spec.choices.begin(), spec.choices.end(), value.text) == spec.choices.end())
    {
      std::string allowed;
      for (std::size_t i = 0; i < spec.choices.size(); ++i)
      {
        allowed += (i ? ", " : "") + std::string(spec.choices[i]);
      }
      throw errorAbout(subject, quoted(value.text) + " is not one of " + allowed);
    }
    // Texts with a grammar of their own are read here, so every way in checks them alike.
    if (spec.name == "field")
    {
      parseFieldSpec(value.text, subject);
    }
    else if (spec.name == "field-range")
    {
      parseFieldRange(value.text, subject);
    }
    return;
  }
  const int n = spec.components();
  for (int i = 0; i < n; ++i)
  {
    const double v = value.number[static_cast<std::size_t>(i)];
    const std::string shown = formatNumber(v);
    if (!std::isfinite(v))
    {
      throw errorAbout(subject, shown + " is not a finite number");
    }
    if (spec.type == ParameterType::Integer && v != std::floor(v))
    {
      throw errorAbout(subject, shown + " is not an integer");
    }
    if (v < spec.minimum || v > spec.maximum)
    {
      throw errorAbout(subject, shown + " is out of range [" + formatNumber(spec.minimum) + ", " +
                                    formatNumber(spec.maximum) + "]");
    }
    if (spec.powerOfTwo && (v < 1.0 || std::exp2(std::round(std::log2(v))) != v))
    {
      throw errorAbout(subject, shown + " is not a power of two");
    }
  }
}

ParameterValue parseParameterValue(const ParameterSpec& spec, std::string_view text,
                                   const std::string& subject)
{
  ParameterValue v;
  switch (spec.type)
  {
  case ParameterType::Text:
    v.text = std::string(text);
    break;
  case ParameterType::Integer:
    v.number.fill(parseNumber(text, true, subject));
    break;
  case ParameterType::Real:
    v.number.fill(parseNumber(text, false, subject));
    break;
  case ParameterType::Color:
  {
    std::vector<std::string_view> parts;
    std::size_t start = 0;
    while (true)
    {
      const std::size_t comma = text.find(',', start);
      parts.push_back(text.substr(start, comma == std::string_view::npos ? comma : comma - start));
      if (comma == std::string_view::npos)
      {
        break;
      }
      start = comma + 1;
    }
    if (parts.size() != 1 && parts.size() != 3)
    {
      throw errorAbout(subject, quoted(text) + " is not a colour (R,G,B or one grey value)");
    }
    for (std::size_t i = 0; i < 3; ++i)
    {
      v.number[i] = parseNumber(parts[parts.size() == 1 ? 0 : i], false, subject);
    }
    break;
  }
  }
  checkParameterValue(spec, v, subject);
  return v;
}

std::string formatParameterValue(const ParameterSpec& spec, const ParameterValue& value)
{
  switch (spec.type)
  {
  case ParameterType::Text:
    return value.text;
  case ParameterType::Integer:
    // Every digit: the shortest form ("2e5") is no integer to parseParameterValue.
    return std::to_string(static_cast<long long>(value.number[0]));
  case ParameterType::Real:
    return formatNumber(value.number[0]);
  case ParameterType::Color:
    break;
  }
  return formatNumber(value.number[0]) + "," + formatNumber(value.number[1]) + "," +
         formatNumber(value.number[2]);
}

ParameterSet::ParameterSet()
{
  for (const auto& spec : parameterSpecs())
  {
    values_.push_back(defaultParameterValue(spec));
  }
}

const ParameterValue& ParameterSet::value(std::string_view name) const
{
  return values_[indexOf(name)];
}

void ParameterSet::setValue(std::string_view name, const ParameterValue& value)
{
  const std::size_t i = indexOf(name);
  checkParameterValue(parameterSpecs()[i], value, std::string(name));
  values_[i] = value;
}

void ParameterSet::setText(std::string_view name, std::string_view text)
{
  const std::size_t i = indexOf(name);
  values_[i] = parseParameterValue(parameterSpecs()[i], text, std::string(name));
}

double ParameterSet::real(std::string_view name) const
{
  return value(name).number[0];
}

int ParameterSet::integer(std::string_view name) const
{
  return static_cast<int>(value(name).number[0]);
}

glm::dvec3 ParameterSet::color(std::string_view name) const
{
  const auto& n = value(name).number;
  return {n[0], n[1], n[2]};
}

const std::string& ParameterSet::text(std::string_view name) const
{
  return value(name).text;
}

AsLobe ParameterSet::lobe() const
{
  AsLobe lobe;
  lobe.nu = real("nu");
  lobe.nv = real("nv");
  return lobe;
}

ParameterValue numberValue(double value)
{
  ParameterValue v;
  v.number.fill(value);
  return v;
}

ParameterValue colorValue(double r, double g, double b)
{
  ParameterValue v;
  v.number = {r, g, b};
  return v;
}

ParameterValue textValue(std::string text)
{
  ParameterValue v;
  v.text = std::move(text);
  return v;
}

SpecularMethod parseSpecularMethod(std::string_view text)
{
  return parseIn(kSpecularMethods, "method", text);
}

std::string_view spelling(SpecularMethod value)
{
  return spellingIn(kSpecularMethods, value);
}

HalfVectorSource parseHalfVectorSource(std::string_view text)
{
  return parseIn(kHalfVectorSources, "half-vectors", text);
}

std::string_view spelling(HalfVectorSource value)
{
  return spellingIn(kHalfVectorSources, value);
}

EnvironmentSampling parseEnvironmentSampling(std::string_view text)
{
  return parseIn(kEnvironmentSamplings, "env-sampling", text);
}

std::string_view spelling(EnvironmentSampling value)
{
  return spellingIn(kEnvironmentSamplings, value);
}

QualityMode parseQualityMode(std::string_view text)
{
  return parseIn(kQualityModes, "quality-mode", text);
}

std::string_view spelling(QualityMode value)
{
  return spellingIn(kQualityModes, value);
}

BumpMapping parseBumpMapping(std::string_view text)
{
  return parseIn(kBumpMappings, "bump", text);
}

std::string_view spelling(BumpMapping value)
{
  return spellingIn(kBumpMappings, value);
}

LineWidthUnit parseLineWidthUnit(std::string_view text)
{
  return parseIn(kLineWidthUnits, "line-width-unit", text);
}

std::string_view spelling(LineWidthUnit value)
{
  return spellingIn(kLineWidthUnits, value);
}

BackgroundMode parseBackgroundMode(std::string_view text)
{
  return parseIn(kBackgroundModes, "background", text);
}

std::string_view spelling(BackgroundMode value)
{
  return spellingIn(kBackgroundModes, value);
}

ToneMapping parseToneMapping(std::string_view text)
{
  return parseIn(kToneMappings, "tone-mapping", text);
}

std::string_view spelling(ToneMapping value)
{
  return spellingIn(kToneMappings, value);
}

LeadrFilter parseLeadrFilter(std::string_view text)
{
  return parseIn(kLeadrFilters, "leadr-filter", text);
}

std::string_view spelling(LeadrFilter value)
{
  return spellingIn(kLeadrFilters, value);
}

MicroPattern parseMicroPattern(std::string_view text)
{
  return parseIn(kMicroPatterns, "structure", text);
}

std::string_view spelling(MicroPattern value)
{
  return spellingIn(kMicroPatterns, value);
}

MicroMasking parseMicroMasking(std::string_view text)
{
  return parseIn(kMicroMaskings, "masking", text);
}

std::string_view spelling(MicroMasking value)
{
  return spellingIn(kMicroMaskings, value);
}

MicroBrdf parseMicroBrdf(std::string_view text)
{
  return parseIn(kMicroBrdfs, "micro-brdf", text);
}

std::string_view spelling(MicroBrdf value)
{
  return spellingIn(kMicroBrdfs, value);
}

FieldTarget parseFieldTarget(std::string_view text)
{
  return parseIn(kFieldTargets, "field-target", text);
}

std::string_view spelling(FieldTarget value)
{
  return spellingIn(kFieldTargets, value);
}

ColorMap parseColorMap(std::string_view text)
{
  return parseIn(kColorMaps, "field-colormap", text);
}

std::string_view spelling(ColorMap value)
{
  return spellingIn(kColorMaps, value);
}

OnOff parseOnOff(std::string_view key, std::string_view text)
{
  return parseIn(kOnOff, key, text);
}

std::string_view spelling(OnOff value)
{
  return spellingIn(kOnOff, value);
}
} // namespace aniso
