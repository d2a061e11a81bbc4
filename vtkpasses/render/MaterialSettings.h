#pragma once
// What an anisotropic material is made of, as plain values: the ones sliders move (uniforms:
// moving them never recompiles a shader) and the features it uses (each a shader variant,
// compiled only when a material uses it).
#include "core/brdf/ashikhmin_shirley.h"
#include "core/fields/field_mapping.h"
#include "core/image/image.h"
#include "core/parameters/choices.h" // SpecularMethod, HalfVectorSource, EnvironmentSampling
#include "core/reference/reference_image.h"

#include <glm/vec3.hpp>
#include <memory>
#include <optional>
#include <string>

namespace aniso
{
class ParameterSet;
struct Material;

struct MaterialSettings
{
  // Uniforms.
  AsLobe lobe;                        // n_u, n_v (a new LUT bake in the LUT variant)
  glm::dvec3 f0{0.913, 0.922, 0.924}; // linear RGB
  glm::dvec3 albedo{0.0, 0.0, 0.0};   // linear RGB; 0 = no diffuse
  int samples = 16;                   // N per fragment and frame
  double heightScale = 0.02;          // relief depth, texture-coordinate units
  // Each pixel rotates its sample set by a hash of its position: the error of few samples turns
  // from bands into noise that progressive frames average out. Off by default: a single
  // frame's error against the reference is as large or larger (docs/BENCHMARKS.md).
  bool pixelDecorrelation = false;
  // Share of the lobe technique in environment MIS: 0 = chosen from the lobe and the
  // environment (misLobeFraction, core/env/env_sampling.h); a value in (0, 1) is used as it is
  // (benchmarks compare rules with it).
  double misLobeShare = 0.0;
  // With environment sampling `sources`: the source technique is the points a frame's pixels
  // share (sourcePointCount of the sample count, core/env/env_source_groups.h), or, with
  // sharedSourcePoints off or sourceSamples set, each pixel's own source samples: sourceSamples
  // a frame, 0 = chosen from the sample count, max(1, samples / 4), doubled up to twice where
  // the pixel's lobe sees sources smaller than itself (benchmarks compare the two).
  bool sharedSourcePoints = true;
  int sourceSamples = 0;

  // Variants.
  SpecularMethod method = SpecularMethod::Exact;
  bool filtered = true; // filtered importance sampling (mip level per sample)
  HalfVectorSource halfVectors = HalfVectorSource::Lut; // as fast or faster, as accurate
  int lutSize = 64;                                     // half-vector and BRDF LUTs
  int brdfLutSamples = 1024;                            // importance samples per BRDF LUT texel
  // Environment importance sampling combined with the lobe samples (bright small sources
  // next to rough lobes); needs the exact method. Off costs nothing. Auto (the parameter's
  // default) is resolved by the lighting (EnvironmentLighting::resolveSampling).
  EnvironmentSampling environmentSampling = EnvironmentSampling::Off;

  // Maps, read through the mesh's texture coordinates; null = not used. Images have row 0 at
  // the top (v = 1), as files store them.
  // Bump mapping: a normal map perturbs n only (t follows by Gram-Schmidt); a quaternion map
  // rotates the whole frame (the source's method). At most one of the two.
  std::shared_ptr<const Image> normalMap;     // RGB = tangent-space normal, signed (decoded)
  std::shared_ptr<const Image> quaternionMap; // RGB = (a, b, c) as bakeQuaternionMap writes
  std::shared_ptr<const Image> tprMap;        // RG = rotated tangent (x, y)
  std::shared_ptr<const Image> heightMap;     // R = height in [0, 1]
  std::shared_ptr<const Image> albedoMap;     // RGB, linear, multiplies albedo
  std::shared_ptr<const Image> occlusionMap;  // R = ambient occlusion
  std::shared_ptr<const Image> metallicMap;   // R = metalness (1: F0, no diffuse; 0: F0 = 0.04)

  // A data field of the mesh that drives albedo, F0, the roughness or the anisotropy
  // (core/fields/field_mapping.h); none = not used. Its range is used as it is when set, else
  // the field's own finite range on the drawn mesh (a scene resolves it over its parts:
  // vtkpasses/render/FieldValues.h). A lobe-changing target draws with half vectors computed
  // in the shader (the lookup table holds one lobe only) and needs the exact method.
  std::optional<FieldMapping> field;

  // Every field equal, maps by identity (the same images).
  bool operator==(const MaterialSettings& o) const
  {
    return lobe.nu == o.lobe.nu && lobe.nv == o.lobe.nv && f0 == o.f0 && albedo == o.albedo &&
           samples == o.samples && heightScale == o.heightScale &&
           pixelDecorrelation == o.pixelDecorrelation && misLobeShare == o.misLobeShare &&
           sharedSourcePoints == o.sharedSourcePoints && sourceSamples == o.sourceSamples &&
           method == o.method && filtered == o.filtered && halfVectors == o.halfVectors &&
           lutSize == o.lutSize && brdfLutSamples == o.brdfLutSamples &&
           environmentSampling == o.environmentSampling && normalMap == o.normalMap &&
           quaternionMap == o.quaternionMap && tprMap == o.tprMap && heightMap == o.heightMap &&
           albedoMap == o.albedoMap && occlusionMap == o.occlusionMap &&
           metallicMap == o.metallicMap && field == o.field;
  }
  bool operator!=(const MaterialSettings& o) const { return !(*this == o); }

  bool usesMaps() const
  {
    return normalMap || quaternionMap || tprMap || heightMap || albedoMap || occlusionMap ||
           metallicMap;
  }
};

// The declared parameters (core/parameters/parameters.h) that a material takes: n_u, n_v, F0,
// albedo, samples, LUT size and samples, method, filtered, half-vectors, env-sampling,
// height scale, the field mapping.
// Everything else (the maps) keeps its value in BASE.
MaterialSettings materialFromParameters(const ParameterSet& parameters, MaterialSettings base = {});

// The maps a library material names, read from their files into SETTINGS: the normal or the
// quaternion map its bump mapping uses (a quaternion map baked from a normal map when it names
// only that), the TPR, height, albedo, occlusion and metallic maps; a map it does not name is
// left as SETTINGS has it. Throws, naming the file and the reason, when one cannot be read.
void readMaterialMaps(const Material& material, MaterialSettings& settings);

// What the CPU reference shades for SETTINGS (its lobe, F0 and albedo: what every method, filter
// and sampling of the material converges to), or nullopt with WHY set when the reference does
// not cover what the material draws: maps or a data field.
std::optional<ReferenceMaterial> referenceMaterialOf(const MaterialSettings& settings,
                                                     std::string& why);
} // namespace aniso
