#include "vtkpasses/render/MaterialShaderSource.h"

#include "aniso_shaders.h"

namespace aniso
{
bool MaterialVariant::operator==(const MaterialVariant& o) const
{
  return method == o.method && filtered == o.filtered && halfVectors == o.halfVectors &&
         environmentMis == o.environmentMis && environmentSources == o.environmentSources &&
         normals == o.normals && tangents == o.tangents &&
         tcoords == o.tcoords && lines == o.lines && normalMap == o.normalMap && quaternionMap == o.quaternionMap &&
         tprMap == o.tprMap && heightMap == o.heightMap && albedoMap == o.albedoMap &&
         occlusionMap == o.occlusionMap && metallicMap == o.metallicMap && field == o.field &&
         (!field || fieldTarget == o.fieldTarget);
}

MaterialVariant materialVariant(const MaterialSettings& settings, bool normals, bool tangents,
                                bool tcoords, bool lines, bool field)
{
  if (lines && tangents)
  {
    // A line's frame is its tangent and the view (ANISO_LINE); it has no surface to map.
    normals = false;
    tcoords = false;
  }
  MaterialVariant v;
  v.method = settings.method;
  v.filtered = settings.filtered;
  v.halfVectors = settings.halfVectors;
  v.environmentMis = settings.method == SpecularMethod::Exact &&
                     settings.environmentSampling == EnvironmentSampling::Mis;
  v.environmentSources = settings.method == SpecularMethod::Exact &&
                         settings.environmentSampling == EnvironmentSampling::Sources;
  v.normals = normals;
  v.tangents = tangents;
  v.tcoords = tcoords;
  v.lines = lines && tangents;
  v.normalMap = tcoords && settings.normalMap;
  v.quaternionMap = tcoords && settings.quaternionMap;
  v.tprMap = tcoords && settings.tprMap;
  v.heightMap = tcoords && settings.heightMap;
  v.albedoMap = tcoords && settings.albedoMap;
  v.occlusionMap = tcoords && settings.occlusionMap;
  v.metallicMap = tcoords && settings.metallicMap;
  v.field = field && settings.field && !v.lines;
  if (v.field)
  {
    v.fieldTarget = settings.field->target;
    if (!settings.field->colors())
    {
      v.halfVectors = HalfVectorSource::Shader; // the table holds the material's lobe only
    }
  }
  return v;
}

bool droppedMaps(const MaterialSettings& settings, bool tcoords)
{
  return !tcoords && settings.usesMaps();
}

std::string variantDefines(const MaterialVariant& v)
{
  std::string d;
  auto define = [&d](bool on, const char* name)
  {
    if (on)
    {
      d += std::string("#define ") + name + "\n";
    }
  };
  define(v.method == SpecularMethod::SplitSum, "ANISO_METHOD_SPLIT_SUM");
  define(v.method == SpecularMethod::Exact, "ANISO_METHOD_EXACT");
  define(v.filtered, "ANISO_FILTERED");
  define(v.halfVectors == HalfVectorSource::Lut, "ANISO_HALF_VECTORS_FROM_LUT");
  define(v.environmentMis, "ANISO_ENVIRONMENT_MIS");
  define(v.environmentSources, "ANISO_ENVIRONMENT_SOURCES");
  define(v.normals, "ANISO_HAVE_NORMALS");
  define(v.tangents, "ANISO_HAVE_TANGENTS");
  define(v.tcoords, "ANISO_HAVE_TCOORDS");
  define(v.lines, "ANISO_LINE");
  define(v.normalMap, "ANISO_NORMAL_MAP");
  define(v.quaternionMap, "ANISO_QUATERNION_MAP");
  define(v.tprMap, "ANISO_TPR_MAP");
  define(v.heightMap, "ANISO_HEIGHT_MAP");
  define(v.albedoMap, "ANISO_ALBEDO_MAP");
  define(v.occlusionMap, "ANISO_OCCLUSION_MAP");
  define(v.metallicMap, "ANISO_METALLIC_MAP");
  define(v.field, "ANISO_FIELD");
  define(v.field && v.fieldTarget == FieldTarget::Albedo, "ANISO_FIELD_COLOR_ALBEDO");
  define(v.field && v.fieldTarget == FieldTarget::F0, "ANISO_FIELD_COLOR_F0");
  define(v.field && (v.fieldTarget == FieldTarget::Roughness ||
                     v.fieldTarget == FieldTarget::Anisotropy),
         "ANISO_FIELD_LOBE");
  define(v.field && v.fieldTarget == FieldTarget::Anisotropy, "ANISO_FIELD_ANISOTROPY");
  return d;
}

MaterialShaderCode composeMaterialShaders(const MaterialVariant& variant)
{
  // The defines open both declaration blocks; the implementation blocks come later in the
  // same shader, so they see them too.
  const std::string defines = variantDefines(variant);
  MaterialShaderCode code;
  code.vertexDeclarations = defines + shaders::kMaterialVsDec;
  code.vertexImplementation = shaders::kMaterialVsImpl;
  code.fragmentDeclarations = defines + shaders::kMaterialFsDec;
  code.fragmentUniformFlow = shaders::kMaterialFsUniformFlow;
  code.fragmentImplementation = shaders::kMaterialFsImpl;
  return code;
}
} // namespace aniso
