#pragma once
// The GLSL an anisotropic material injects into VTK's polydata shaders, per variant. Each piece
// is inserted after a VTK tag, which it keeps, so VTK's own code and later replacements still
// apply. GL-free: the variant logic can be checked without a context.
#include "vtkpasses/render/MaterialSettings.h"

#include <string>

namespace aniso
{
// The point arrays the material reads (names as the mesh preparation writes them).
inline constexpr const char* kNormalsArray = "Normals";   // float3
inline constexpr const char* kTangentsArray = "Tangents"; // float3, unit, orthogonal to normals
inline constexpr const char* kTCoordsArray = "TCoords";   // float2
// The field's values per point, written by the material from the mesh's data arrays
// (vtkpasses/render/FieldValues.h): float2 (value, 1 where the value is NaN).
inline constexpr const char* kFieldArray = "AnisoFieldValues";

// Everything that changes the compiled shader; nothing else does.
struct MaterialVariant
{
  SpecularMethod method = SpecularMethod::Exact;
  bool filtered = true;
  HalfVectorSource halfVectors = HalfVectorSource::Shader;
  bool environmentMis = false; // environment samples and MIS (exact method only)
  bool environmentSources = false; // the sources split off and sampled (exact method only)
  bool normals = false;        // mesh attributes present
  bool tangents = false;
  bool tcoords = false;
  bool lines = false;     // an illuminated line set (ANISO_LINE: t along the line, n facing v)
  bool normalMap = false; // maps in use (only with tcoords)
  bool quaternionMap = false;
  bool tprMap = false;
  bool heightMap = false;
  bool albedoMap = false;
  bool occlusionMap = false;
  bool metallicMap = false;
  // A data field drives the material (the mesh has its values): ANISO_FIELD with
  // ANISO_FIELD_COLOR_ALBEDO, ANISO_FIELD_COLOR_F0 or ANISO_FIELD_LOBE (roughness and
  // anisotropy, which also computes the half vectors in the shader).
  bool field = false;
  FieldTarget fieldTarget = FieldTarget::Albedo;

  bool operator==(const MaterialVariant& other) const;
  bool operator!=(const MaterialVariant& other) const { return !(*this == other); }
};

// The variant of SETTINGS on a mesh with the given arrays. Maps need texture coordinates;
// without them they are left out (see droppedMaps). SETTINGS' environment sampling is taken as
// resolved (EnvironmentLighting::resolveSampling): Auto draws as Off here.
// A line set (LINES) takes no maps and no normals: its frame is the line's (docs/METHOD.md).
// FIELD: the mesh carries the field's values (kFieldArray); without them, or on a line set, the
// field is left out.
MaterialVariant materialVariant(const MaterialSettings& settings, bool normals, bool tangents,
                                bool tcoords, bool lines = false, bool field = false);
// True when SETTINGS asks for maps that the mesh cannot use (no texture coordinates).
bool droppedMaps(const MaterialSettings& settings, bool tcoords);

// "#define ANISO_..." lines of the variant, one per line.
std::string variantDefines(const MaterialVariant& variant);

struct MaterialShaderCode
{
  // Vertex shader: after //VTK::Normal::Dec and //VTK::CustomEnd::Impl.
  std::string vertexDeclarations;
  std::string vertexImplementation;
  // Fragment shader: after //VTK::Light::Dec, //VTK::UniformFlow::Impl, //VTK::Light::Impl.
  std::string fragmentDeclarations;
  std::string fragmentUniformFlow;
  std::string fragmentImplementation;
};

MaterialShaderCode composeMaterialShaders(const MaterialVariant& variant);
} // namespace aniso
