#include "vtkpasses/render/AnisoMaterial.h"

#include "core/env/env_source_groups.h"
#include "core/error.h"
#include "core/fields/color_map.h"
#include "core/lut/lut.h"
#include "core/lut/lut_cache.h"
#include "core/sampling/hammersley.h"
#include "vtkpasses/render/EnvironmentLighting.h"
#include "vtkpasses/render/FieldValues.h"
#include "vtkpasses/render/RendererMatrices.h"
#include "vtkpasses/render/ShaderHook.h"
#include "vtkpasses/render/TextureUpload.h"
#include "vtkpasses/render/vtkAnisoAccumulationPass.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <functional>
#include <glm/gtc/type_ptr.hpp>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <vtkCellData.h>
#include <vtkInformation.h>
#include <vtkInformationDoubleVectorKey.h>
#include <vtkInformationIntegerKey.h>
#include <vtkInformationObjectBaseKey.h>
#include <vtkMapper.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLState.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>
#include <vtkShaderProgram.h>
#include <vtkSmartPointer.h>
#include <vtkTextureObject.h>
#include <vtkWeakPointer.h>
#include <vtk_glew.h>

namespace aniso
{
namespace
{
constexpr int kMaxSamples = 1 << 16;

// Filtered importance sampling: the level from the sample's footprint along the lobe's sharp
// axis (the anisotropy term is 0.5 log2 of the width ratio sqrt((n_max + 1) / (n_min + 1))) and
// no bias. Measured against the reference, it beats unfiltered lookups at N = 4, 16, 64 for
// (10, 10), (1000, 100) and (20000, 70), where the isotropic footprint with a bias of +1 lost
// to them at every N (docs/BENCHMARKS.md, "Filtered importance sampling and MIS in the shader").
constexpr double kLodAnisotropyWeight = 0.25;
constexpr double kLodBias = 0.0;

// Share of a pixel's choice between the source groups kept in proportion to their power
// (core/env/env_source_groups.h, lobeAwareSelection): a group whose cap the lobe's bound misses
// keeps at least this part of the samples power alone gives it.
constexpr double kSourceDefensive = 0.1;

// Which points a set of COUNT samples takes in progressive frame FRAME: COUNT_NAME is the count
// when the set is a block of the sequence (0: the rotated Hammersley set), BLOCK_NAME the bits
// of the block's first point (core/sampling/hammersley.h sequenceBlock), COLUMNS_NAME (ivec4)
// the first four columns of COUNT's sequence (sequenceColumns).
void setSequenceUniforms(vtkShaderProgram* program, const std::string& countName,
                         const std::string& blockName, const std::string& columnsName,
                         uint32_t frame, uint32_t count)
{
  const bool sequence = takesSequence(frame, count);
  const SequenceBlock block = sequence ? sequenceBlock(frame, count) : SequenceBlock{};
  const int bits[2] = {static_cast<int>(block.x), static_cast<int>(block.y)};
  program->SetUniform2i(blockName.c_str(), bits);
  const SequenceColumns& columns = sequenceColumns(count);
  // (vtkShaderProgram has no ivec4 setter; the program is bound while the shader callback runs.)
  const int location = program->FindUniform(columnsName.c_str());
  if (location >= 0)
  {
    glUniform4i(location, static_cast<int>(columns[0]), static_cast<int>(columns[1]),
                static_cast<int>(columns[2]), static_cast<int>(columns[3]));
  }
  program->SetUniformi(countName.c_str(), sequence ? static_cast<int>(count) : 0);
}

void setVector(vtkShaderProgram* program, const char* name, const glm::dvec3& v)
{
  const glm::vec3 f(v);
  program->SetUniform3f(name, glm::value_ptr(f));
}

void checkColor(const glm::dvec3& c, const char* name)
{
  for (int i = 0; i < 3; ++i)
  {
    if (!std::isfinite(c[i]) || c[i] < 0.0 || c[i] > 1.0)
    {
      throw errorAbout(name, "components must be in [0, 1]");
    }
  }
}

void checkMap(const std::shared_ptr<const Image>& map, int minChannels, const char* name)
{
  if (!map)
  {
    return;
  }
  if (map->empty() || map->width <= 0 || map->height <= 0 ||
      map->data.size() != std::size_t(map->width) * map->height * map->channels)
  {
    throw errorAbout(name, "empty or inconsistent image");
  }
  if (map->channels < minChannels)
  {
    throw errorAbout(name, std::to_string(map->channels) + " channel(s), at least " +
                               std::to_string(minChannels) + " needed");
  }
}

// Entries of a field's colour-map texture: t = i / (count - 1) at texel i's centre.
constexpr int kFieldColorCount = 256;

// The colour map's table as linear RGB, made once per map for the process (materials of one map
// share its texture in a window).
std::shared_ptr<const std::vector<float>> fieldColorTable(ColorMap map)
{
  static const std::array<std::shared_ptr<const std::vector<float>>, 4> tables = []
  {
    std::array<std::shared_ptr<const std::vector<float>>, 4> t;
    for (ColorMap m : {ColorMap::Viridis, ColorMap::Cividis, ColorMap::CoolToWarm,
                       ColorMap::Grayscale})
    {
      t[static_cast<std::size_t>(m)] =
          std::make_shared<const std::vector<float>>(colorMapTableLinear(m, kFieldColorCount));
    }
    return t;
  }();
  return tables[static_cast<std::size_t>(map)];
}

// A grey image as RGB (albedo maps may be single-channel).
Image asRgb(const Image& image)
{
  if (image.channels >= 3)
  {
    return image;
  }
  Image rgb(image.width, image.height, 3);
  for (int y = 0; y < image.height; ++y)
  {
    for (int x = 0; x < image.width; ++x)
    {
      for (int c = 0; c < 3; ++c)
      {
        rgb.at(x, y, c) = image.at(x, y, 0);
      }
    }
  }
  return rgb;
}
} // namespace

// Textures made from the same data in the same window, shared by every material that draws
// with them: the parts of a scene that share a lobe share its lookup tables' textures, and maps
// read once are uploaded once. Weak: a texture lives while a material uses it.
class SharedTextures
{
public:
  using Make = std::function<vtkSmartPointer<vtkTextureObject>()>;
  // The texture of SOURCE's data as KIND (a material uploads a map as one kind only) in WINDOW:
  // one alive already, else MAKE's (counted in UPLOADS).
  vtkSmartPointer<vtkTextureObject> get(vtkOpenGLRenderWindow* window,
                                        const std::shared_ptr<const void>& source,
                                        const char* kind, const Make& make, int& uploads)
  {
    const Key key{window, source.get(), kind};
    auto it = textures_.find(key);
    // The data must be the same object, not a new one at the address of a freed one: the
    // entry's source is still alive.
    if (it != textures_.end() && !it->second.source.expired())
    {
      vtkSmartPointer<vtkTextureObject> alive = it->second.texture.Get();
      if (alive && alive->GetHandle() != 0)
      {
        return alive;
      }
    }
    vtkSmartPointer<vtkTextureObject> made = make();
    ++uploads;
    textures_[key] = Entry{made.Get(), source};
    // Entries whose texture or data died go, so the map stays as small as what is in use.
    for (auto e = textures_.begin(); e != textures_.end();)
    {
      e = e->second.texture && !e->second.source.expired() ? std::next(e) : textures_.erase(e);
    }
    return made;
  }

  static SharedTextures& instance()
  {
    static SharedTextures shared;
    return shared;
  }

private:
  using Key = std::tuple<const void*, const void*, std::string>;
  struct Entry
  {
    vtkWeakPointer<vtkTextureObject> texture;
    std::weak_ptr<const void> source;
  };
  std::map<Key, Entry> textures_;
};

class AnisoMaterial::Impl
{
public:
  // A texture and the data it was made from (re-uploaded when that changes). The data is held,
  // so a new table can never be mistaken for an old one that lived at the same address.
  struct Texture
  {
    vtkSmartPointer<vtkTextureObject> object;
    std::shared_ptr<const void> source;
  };

  MaterialSettings settings;
  std::shared_ptr<EnvironmentLighting> lighting;
  MaterialVariant installed; // while hook.installed()
  MeshArrays mesh;
  bool dropped = false;
  bool adopted = false; // settings taken at least once
  Counters counters;

  std::shared_ptr<const HalfVectorLut> halfVectorLut;
  std::shared_ptr<const BrdfLut> brdfLut;
  vtkWeakPointer<vtkOpenGLRenderWindow> textureWindow;
  Texture halfVectorTexture;
  Texture brdfTexture;
  Texture normalTexture;
  Texture quaternionTexture;
  Texture tprTexture;
  Texture heightTexture;
  Texture albedoTexture;
  Texture occlusionTexture;
  Texture metallicTexture;
  Texture fieldColorTexture;
  // The field's values on the drawn mesh (writeFieldValues): a point array of this material's
  // own name, so materials of other fields may draw the same surface.
  const std::string fieldArrayName = std::string(kFieldArray) + "#" + std::to_string(nextId());
  vtkWeakPointer<vtkPolyData> meshPoly; // the mesh last drawn
  vtkWeakPointer<vtkPolyData> fieldPoly; // where the values were written, and of which field
  std::optional<FieldSpec> fieldWritten;
  vtkMTimeType fieldSourceTime = 0;
  double fieldOffset = 0.0;
  FieldRange fieldOwnRange; // the field's finite range on the mesh, for an automatic range
  bool fieldPresent = false;
  // Last, so it lets go of the actor (and the textures it activated) before the rest goes.
  ShaderHook hook{"anisotropic material"};

  static int nextId()
  {
    static std::atomic<int> id{0};
    return ++id;
  }

  ~Impl() { removeFieldValues(); }

  void removeFieldValues()
  {
    if (fieldPoly && fieldPoly->GetPointData()->GetArray(fieldArrayName.c_str()))
    {
      fieldPoly->GetPointData()->RemoveArray(fieldArrayName.c_str());
    }
    fieldPoly = nullptr;
    fieldWritten.reset();
    fieldPresent = false;
  }

  // The array the field's values come from, for its modification time.
  static vtkDataArray* fieldSource(vtkPolyData* poly, const FieldSpec& spec)
  {
    vtkDataArray* a = poly->GetPointData()->GetArray(spec.array.c_str());
    return a ? a : poly->GetCellData()->GetArray(spec.array.c_str());
  }

  // Writes the field's values onto POLY when the field, the mesh or its array changed.
  void refreshField(vtkPolyData* poly)
  {
    if (!settings.field || !poly)
    {
      removeFieldValues();
      return;
    }
    const FieldSpec& spec = settings.field->spec;
    vtkDataArray* source = fieldSource(poly, spec);
    const vtkMTimeType sourceTime = source ? source->GetMTime() : 0;
    if (fieldPoly == poly && fieldWritten && *fieldWritten == spec &&
        fieldSourceTime == sourceTime &&
        (!fieldPresent || poly->GetPointData()->GetArray(fieldArrayName.c_str())))
    {
      return;
    }
    removeFieldValues();
    const std::optional<double> offset = writeFieldValues(poly, spec, fieldArrayName.c_str());
    fieldPoly = poly;
    fieldWritten = spec;
    fieldSourceTime = sourceTime;
    fieldPresent = offset.has_value();
    fieldOffset = offset.value_or(0.0);
    const auto statistics = fieldStatistics(poly, spec);
    const auto range = statistics ? jointFieldRange({*statistics}) : std::nullopt;
    fieldOwnRange = range.value_or(FieldRange{false, 0.0, 1.0});
  }

  static bool matches(const std::shared_ptr<const HalfVectorLut>& lut, const MaterialSettings& s)
  {
    return lut && lut->size == s.lutSize && lut->lobe.nu == s.lobe.nu && lut->lobe.nv == s.lobe.nv;
  }
  static bool matches(const std::shared_ptr<const BrdfLut>& lut, const MaterialSettings& s)
  {
    return lut && lut->size == s.lutSize && lut->samples == s.brdfLutSamples &&
           lut->lobe.nu == s.lobe.nu && lut->lobe.nv == s.lobe.nv;
  }

  // Takes new settings: their LUTs first (which may throw), then everything at once. Tables
  // given or held already are not asked of the cache again (which may have dropped them from
  // memory and would read their files).
  void adopt(const MaterialSettings& s, const std::shared_ptr<const HalfVectorLut>& givenHalf = {},
             const std::shared_ptr<const BrdfLut>& givenBrdf = {})
  {
    // Only what the variant reads: the in-shader variant of `exact` needs no table at all.
    std::shared_ptr<const HalfVectorLut> halfVectors;
    const bool fieldLobe = s.field && !s.field->colors(); // half vectors in the shader
    if (s.halfVectors == HalfVectorSource::Lut && !fieldLobe)
    {
      halfVectors = matches(givenHalf, s)       ? givenHalf
                    : matches(halfVectorLut, s) ? halfVectorLut
                                                : LutCache::shared().halfVector(s.lobe, s.lutSize);
    }
    std::shared_ptr<const BrdfLut> brdf;
    if (s.method == SpecularMethod::SplitSum)
    {
      brdf = matches(givenBrdf, s) ? givenBrdf
             : matches(brdfLut, s) ? brdfLut
                                   : LutCache::shared().brdf(s.lobe, s.lutSize, s.brdfLutSamples);
    }
    halfVectorLut = std::move(halfVectors);
    brdfLut = std::move(brdf);
    settings = s;
    adopted = true;
  }

  // The settings with their environment sampling as the lighting resolves it (Auto: by the
  // environment's analysis).
  MaterialSettings resolved() const
  {
    MaterialSettings s = settings;
    s.environmentSampling = lighting ? lighting->resolveSampling(s.environmentSampling)
                                     : (s.environmentSampling == EnvironmentSampling::Auto
                                          ? EnvironmentSampling::Off
                                          : s.environmentSampling);
    return s;
  }

  // The mesh the mapper is about to draw chooses the variant.
  void onMesh(vtkPolyData* poly)
  {
    meshPoly = poly;
    refreshField(poly);
    mesh = meshArraysOf(poly);
    updateVariant();
  }

  void updateVariant()
  {
    dropped = droppedMaps(settings, mesh.tcoords && !mesh.lines);
    const MaterialVariant v =
        materialVariant(resolved(), mesh.normals, mesh.tangents, mesh.tcoords, mesh.lines,
                        fieldPresent);
    if (!hook.installed() || installed != v)
    {
      install(v);
    }
  }

  void install(const MaterialVariant& v)
  {
    const MaterialShaderCode code = composeMaterialShaders(v);
    ShaderCode hooked;
    hooked.vertex = {{tags::kVertexDec, code.vertexDeclarations},
                     {tags::kVertexImpl, code.vertexImplementation}};
    hooked.fragment = {{tags::kFragmentDec, code.fragmentDeclarations},
                       {tags::kFragmentUniformFlow, code.fragmentUniformFlow},
                       {tags::kFragmentImpl, code.fragmentImplementation}};
    if (v.lines)
    {
      hooked.geometry = lineGeometryCode("aniso");
    }
    hooked.attributes = meshAttributes("aniso", {v.normals, v.tangents, v.tcoords});
    if (v.field)
    {
      hooked.attributes.emplace_back("anisoFieldMC", fieldArrayName);
    }
    hooked.uniform = "anisoSampleCount";
    hooked.discardFrozenPixels = true;
    hook.install(hooked);
    installed = v;
    ++counters.shaderInstalls;
  }

  // (Re)creates the textures whose source changed, in WINDOW's context.
  void updateTextures(vtkOpenGLRenderWindow* window)
  {
    if (textureWindow != window)
    {
      for (Texture* t : allTextures())
      {
        *t = Texture{};
      }
      textureWindow = window;
    }
    const char* kind = nullptr;
    auto refresh = [this, window, &kind](Texture& texture, std::shared_ptr<const void> source,
                                         auto&& make)
    {
      if (!source)
      {
        texture = Texture{};
      }
      else if (texture.source != source || !texture.object || texture.object->GetHandle() == 0)
      {
        // A handle of 0: released with the window's context (QVTKOpenGLNativeWidget makes a
        // new one when it is shown or moved), so the window is the same object but the texture
        // is gone; binding it would bind target 0 (GL_INVALID_ENUM) and leave it active.
        texture.object =
            SharedTextures::instance().get(window, source, kind, make, counters.textureUploads);
        texture.source = source;
      }
    };
    kind = "half-vector LUT";
    refresh(halfVectorTexture, halfVectorLut,
            [&]
            {
              return uploadFloatTexture(window, halfVectorLut->size, halfVectorLut->size, 4,
                                        halfVectorLut->rgba.data(), TextureFiltering::Nearest,
                                        TextureWrap::Clamp, "half-vector LUT");
            });
    kind = "BRDF LUT";
    refresh(brdfTexture, brdfLut,
            [&]
            {
              return uploadFloatTexture(window, brdfLut->size, brdfLut->size, 2, brdfLut->rg.data(),
                                        TextureFiltering::Linear, TextureWrap::Clamp, "BRDF LUT");
            });
    const MaterialVariant& v = installed;
    auto mapTexture = [&](Texture& texture, bool used, const std::shared_ptr<const Image>& image,
                          int channels, const char* name)
    {
      kind = name;
      refresh(texture, used ? image : nullptr,
              [&] { return uploadMapTexture(window, *image, channels, name); });
    };
    mapTexture(normalTexture, v.normalMap, settings.normalMap, 3, "normal map");
    mapTexture(quaternionTexture, v.quaternionMap, settings.quaternionMap, 3, "quaternion map");
    mapTexture(tprTexture, v.tprMap, settings.tprMap, 2, "TPR map");
    mapTexture(heightTexture, v.heightMap, settings.heightMap, 1, "height map");
    mapTexture(occlusionTexture, v.occlusionMap, settings.occlusionMap, 1, "occlusion map");
    mapTexture(metallicTexture, v.metallicMap, settings.metallicMap, 1, "metallic map");
    kind = "field colours";
    const bool fieldColors = v.field && settings.field && settings.field->colors();
    const auto table = fieldColors ? fieldColorTable(settings.field->colorMap) : nullptr;
    refresh(fieldColorTexture, table,
            [&]
            {
              return uploadFloatTexture(window, kFieldColorCount, 1, 3, table->data(),
                                        TextureFiltering::Linear, TextureWrap::Clamp,
                                        "field colours");
            });
    kind = "albedo map";
    refresh(albedoTexture, v.albedoMap ? settings.albedoMap : nullptr,
            [&] { return uploadMapTexture(window, asRgb(*settings.albedoMap), 3, "albedo map"); });
  }

  std::array<Texture*, 10> allTextures()
  {
    return {&halfVectorTexture, &brdfTexture,      &normalTexture, &quaternionTexture,
            &tprTexture,        &heightTexture,    &albedoTexture, &occlusionTexture,
            &metallicTexture,   &fieldColorTexture};
  }

  // Uniforms and textures, every time the mapper draws: no value here changes the shader.
  void onShader(vtkShaderProgram* program, vtkOpenGLRenderWindow* window)
  {
    if (lighting)
    {
      updateTextures(window);
      setUniforms(program, window);
    }
  }

  void setUniforms(vtkShaderProgram* program, vtkOpenGLRenderWindow* window)
  {
    hook.setTransforms(program, "aniso");

    setVector(program, "anisoF0", settings.f0);
    setVector(program, "anisoAlbedo", settings.albedo);
    program->SetUniformi("anisoSampleCount", settings.samples);
    // The progressive frame picks the sample set (core/sampling/hammersley.h progressivePoint):
    // the Hammersley set rotated by the frame's shift, or a block of a (0,2)-sequence, which the
    // shader takes as its points XOR the bits of the block's first point.
    vtkInformation* info = hook.renderer()->GetInformation();
    const int frameIndex = vtkAnisoAccumulationPass::GetFrameIndex(hook.renderer());
    program->SetUniformf("anisoLog2FrameCount", static_cast<float>(std::log2(frameIndex + 1.0)));
    double shift[2] = {0.0, 0.0};
    if (info && info->Has(vtkAnisoAccumulationPass::FRAME_SHIFT()))
    {
      info->Get(vtkAnisoAccumulationPass::FRAME_SHIFT(), shift);
    }
    const float frameShift[2] = {static_cast<float>(shift[0]), static_cast<float>(shift[1])};
    program->SetUniform2f("anisoFrameShift", frameShift);
    const auto frame = static_cast<uint32_t>(frameIndex);
    setSequenceUniforms(program, "anisoSequenceCount", "anisoSequenceBlock", "anisoSequenceColumns",
                        frame, static_cast<uint32_t>(std::max(settings.samples, 1)));

    // The environment: cube with seamless filtering across faces (VTK enables it only for
    // its own image-based lighting).
    window->GetState()->vtkglEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    // With the sources split off, the lobe samples read the residual.
    hook.bindTexture(program, "anisoEnvironment",
                     installed.environmentSources ? lighting->residualCubeTexture(window)
                                                  : lighting->cubeTexture(window));
    setUniformMatrix(program, "anisoWorldToEnvironment", lighting->worldToEnvironment());
    const double size = lighting->cubeSize();
    program->SetUniformf("anisoLog2TexelSolidAngle",
                         static_cast<float>(std::log2(4.0 * M_PI / (6.0 * size * size))));
    program->SetUniformf("anisoMaxLod", static_cast<float>(lighting->mipLevels() - 1));
    const double nMax = std::max(settings.lobe.nu, settings.lobe.nv);
    const double nMin = std::min(settings.lobe.nu, settings.lobe.nv);
    program->SetUniformf(
        "anisoLodAnisotropy",
        static_cast<float>(kLodAnisotropyWeight * std::log2((nMax + 1.0) / (nMin + 1.0))));
    program->SetUniformf("anisoLodBias", static_cast<float>(kLodBias));
    program->SetUniformf("anisoPixelDecorrelation", settings.pixelDecorrelation ? 1.0f : 0.0f);
    if (installed.environmentMis)
    {
      hook.bindTexture(program, "anisoEnvCdf", lighting->samplingCdfTexture(window));
      hook.bindTexture(program, "anisoEnvPdf", lighting->samplingPdfTexture(window));
      hook.bindTexture(program, "anisoEnvGuide", lighting->samplingGuideTexture(window));
      const EnvironmentDistribution& d = lighting->samplingDistribution();
      program->SetUniform2i("anisoEnvGrid", std::array<int, 2>{d.width(), d.height()}.data());
      // The split from the lobe and this environment's densities (env_sampling.h), unless set.
      const double share = settings.misLobeShare > 0.0 && settings.misLobeShare < 1.0
                               ? settings.misLobeShare
                               : misLobeFraction(settings.lobe, d);
      program->SetUniformf("anisoLobeFraction", static_cast<float>(share));
    }
    if (installed.environmentSources)
    {
      hook.bindTexture(program, "anisoSourceRadiance", lighting->sourceRadianceTexture(window));
      hook.bindTexture(program, "anisoSourceTables", lighting->sourceTableTexture(window));
      hook.bindTexture(program, "anisoSourceDensity", lighting->sourceDensityTexture(window));
      setSourceGroupUniforms(program, *lighting->sourceSplit().groups);
      setSourcePointUniforms(program, frame);
      // The points the frame's pixels share; or, with a count set in the settings, that many
      // source samples of each pixel's own (M a pixel, up to 4 M where its lobe sees sources
      // smaller than itself without a count set, as before the shared points).
      const int sourceCount =
          settings.sourceSamples > 0 ? settings.sourceSamples : std::max(1, settings.samples / 4);
      const int sourceSteps =
          settings.sourceSamples > 0 ? 0 : sourceSampleSteps(sourceCount, settings.samples);
      program->SetUniformi("anisoSourceSampleCount", sourceCount);
      program->SetUniformi("anisoSourceSampleSteps", sourceSteps);
      // Pixels whose lobe samples take the sources well enough take none (not with a set count).
      const double noise = settings.sourceSamples > 0 ? 0.0 : kLobeOnlySourceNoise;
      program->SetUniformf("anisoSourceLobeOnlyVariance", static_cast<float>(noise * noise));
      // Their own blocks of the sequence, one per count, so that frames stratify them too.
      for (int k = 0; k <= 2; ++k)
      {
        const std::string index = "[" + std::to_string(k) + "]";
        setSequenceUniforms(
            program, "anisoSourceSequenceCounts" + index, "anisoSourceSequenceBlocks" + index,
            "anisoSourceSequenceColumns" + index, frame, static_cast<uint32_t>(sourceCount << k));
      }
    }
    program->SetUniform3fv(
        "anisoIrradianceSH", 9,
        reinterpret_cast<const float(*)[3]>(lighting->irradianceCoefficients().data()));

    if (halfVectorTexture.object)
    {
      hook.bindTexture(program, "anisoHalfVectorLut", halfVectorTexture.object);
      program->SetUniformi("anisoHalfVectorLutSize", halfVectorLut->size);
    }
    // The in-shader half vectors and the MIS densities read the exponents.
    const float exponents[2] = {static_cast<float>(settings.lobe.nu),
                                static_cast<float>(settings.lobe.nv)};
    program->SetUniform2f("anisoExponents", exponents);
    if (installed.field && settings.field)
    {
      setFieldUniforms(program, exponents);
    }
    if (brdfTexture.object)
    {
      hook.bindTexture(program, "anisoBrdfLut", brdfTexture.object);
    }
    const std::pair<Texture*, const char*> maps[] = {
        {&normalTexture, "anisoNormalMap"},    {&quaternionTexture, "anisoQuaternionMap"},
        {&tprTexture, "anisoTprMap"},          {&heightTexture, "anisoHeightMap"},
        {&albedoTexture, "anisoAlbedoMap"},    {&occlusionTexture, "anisoOcclusionMap"},
        {&metallicTexture, "anisoMetallicMap"}};
    for (const auto& [texture, sampler] : maps)
    {
      if (texture->object)
      {
        hook.bindTexture(program, sampler, texture->object);
      }
    }
    program->SetUniformf("anisoHeightScale", static_cast<float>(settings.heightScale));
  }

  // The points the frame's pixels share (sourcePoints): world directions with their densities
  // (count x pdf), their excess radiance, and the selection they are drawn under, which the
  // lobe samples' MIS weights read. None where the settings ask for per-pixel source samples
  // (sharedSourcePoints off, or a count of them set: the pixels then draw their own, by their
  // lobe's selection).
  void setSourcePointUniforms(vtkShaderProgram* program, uint32_t frame)
  {
    const int count = settings.sharedSourcePoints && settings.sourceSamples == 0
                          ? sourcePointCount(settings.samples)
                          : 0;
    program->SetUniformi("anisoSourcePointCount", count);
    if (count == 0)
    {
      return;
    }
    const EnvironmentLighting::SharedSourcePoints& shared =
        lighting->sharedSourcePoints(frame, count);
    constexpr int kGroups = SourceGroups::kMaxGroups;
    program->SetUniform1fv("anisoSourcePointSelection", kGroups, shared.selection.data());
    for (int g = 0; g < kGroups; ++g)
    {
      program->SetUniform2i(("anisoSourcePointRuns[" + std::to_string(g) + "]").c_str(),
                            shared.runs.data() + 2 * g);
    }
    program->SetUniform4fv("anisoSourcePoints", kMaxSourcePoints,
                           reinterpret_cast<const float(*)[4]>(shared.points.data()));
    program->SetUniform3fv("anisoSourcePointRadiance", kMaxSourcePoints,
                           reinterpret_cast<const float(*)[3]>(shared.radiance.data()));
  }

  // The source groups' caps, shares and entries (anisoSourceSelection, anisoSampleSources).
  static void setSourceGroupUniforms(vtkShaderProgram* program, const SourceGroups& groups)
  {
    program->SetUniform2i("anisoSourceGrid",
                          std::array<int, 2>{groups.width, groups.height}.data());
    program->SetUniformi("anisoSourceRowGuides",
                         static_cast<int>(groups.rowY.size() + groups.entryTexel.size()));
    constexpr int kGroups = SourceGroups::kMaxGroups;
    std::array<float, 4 * kGroups> cone{};
    std::array<float, 4 * kGroups> info{};
    const int count = std::min(int(groups.groups.size()), kGroups);
    for (int g = 0; g < count; ++g)
    {
      const SourceGroup& group = groups.groups[std::size_t(g)];
      const std::size_t i = 4 * std::size_t(g);
      cone[i] = float(group.direction.x);
      cone[i + 1] = float(group.direction.y);
      cone[i + 2] = float(group.direction.z);
      cone[i + 3] = float(std::cos(group.angularRadius));
      info[i] = float(group.power / groups.power);
      info[i + 1] = float(1.0 / group.solidAngle);
      info[i + 2] = float(group.firstRow);
      info[i + 3] = float(group.rowCount);
    }
    program->SetUniformi("anisoSourceGroupCount", count);
    program->SetUniform4fv("anisoSourceGroupCone", kGroups,
                           reinterpret_cast<const float(*)[4]>(cone.data()));
    program->SetUniform4fv("anisoSourceGroupInfo", kGroups,
                           reinterpret_cast<const float(*)[4]>(info.data()));
    program->SetUniformf("anisoSourceDefensive", static_cast<float>(kSourceDefensive));
    program->SetUniformf(
        "anisoSourceResidualShare",
        static_cast<float>(groups.power > 0.0 ? groups.residualMean / groups.power : 0.0));
    std::array<float, kGroups> squared{};
    for (int g = 0; g < count; ++g)
    {
      const SourceGroup& group = groups.groups[std::size_t(g)];
      squared[std::size_t(g)] = float(group.squaredPower / (groups.power * groups.power));
    }
    program->SetUniform1fv("anisoSourceGroupSquared", kGroups, squared.data());
  }

  // The field's range (relative to the values' offset), the target's values and its colours.
  void setFieldUniforms(vtkShaderProgram* program, const float exponents[2])
  {
    const FieldMapping& f = *settings.field;
    const FieldRange range = f.range.automatic ? fieldOwnRange : f.range;
    const float fieldRange[2] = {static_cast<float>(range.min - fieldOffset),
                                 static_cast<float>(range.max - fieldOffset)};
    program->SetUniform2f("anisoFieldRange", fieldRange);
    const float targets[2] = {static_cast<float>(f.low), static_cast<float>(f.high)};
    program->SetUniform2f("anisoFieldTargets", targets);
    program->SetUniform2f("anisoMaterialExponents", exponents);
    if (fieldColorTexture.object)
    {
      hook.bindTexture(program, "anisoFieldColors", fieldColorTexture.object);
      program->SetUniformi("anisoFieldColorCount", kFieldColorCount);
      const glm::dvec3 nan = colorMapNanColor(f.colorMap);
      setVector(program, "anisoFieldNanColor",
                glm::dvec3(srgbToLinear(nan.x), srgbToLinear(nan.y), srgbToLinear(nan.z)));
    }
  }
};

AnisoMaterial::AnisoMaterial(std::shared_ptr<EnvironmentLighting> lighting,
                             const MaterialSettings& settings)
    : impl_(std::make_unique<Impl>())
{
  if (!lighting)
  {
    throw errorAbout("environment", "a material needs lighting");
  }
  validate(settings);
  impl_->adopt(settings);
  impl_->lighting = std::move(lighting);
}

AnisoMaterial::~AnisoMaterial() = default;

void AnisoMaterial::validate(const MaterialSettings& s)
{
  checkLutInputs(s.lobe, s.lutSize, s.brdfLutSamples);
  if (s.samples < 1 || s.samples > kMaxSamples)
  {
    throw errorAbout("samples", "must be in [1, " + std::to_string(kMaxSamples) + "]");
  }
  checkColor(s.f0, "f0");
  checkColor(s.albedo, "albedo");
  if (!std::isfinite(s.heightScale) || s.heightScale < 0.0)
  {
    throw errorAbout("height-scale", "must be a finite number >= 0");
  }
  checkMap(s.normalMap, 3, "normal map");
  checkMap(s.quaternionMap, 3, "quaternion map");
  if (s.normalMap && s.quaternionMap)
  {
    throw errorAbout("normal map", "not used together with a quaternion map (one bump method)");
  }
  checkMap(s.tprMap, 2, "TPR map");
  checkMap(s.heightMap, 1, "height map");
  checkMap(s.albedoMap, 1, "albedo map");
  checkMap(s.occlusionMap, 1, "occlusion map");
  checkMap(s.metallicMap, 1, "metallic map");
  if (s.field)
  {
    if (!std::isfinite(s.field->low) || !std::isfinite(s.field->high) || s.field->low < 0.0 ||
        s.field->high < 0.0)
    {
      throw errorAbout("field-low", "the target's values must be finite numbers >= 0");
    }
    if (!s.field->colors() && s.method != SpecularMethod::Exact)
    {
      throw errorAbout("field-target", "roughness and anisotropy need the exact method "
                                       "(method exact): the split sum's BRDF table holds one lobe");
    }
  }
}

void AnisoMaterial::apply(vtkActor* actor, vtkRenderer* renderer)
{
  impl_->hook.attach(actor, renderer, impl_.get());
}

void AnisoMaterial::addMapper(vtkMapper* mapper)
{
  impl_->hook.addMapper(mapper);
}

void AnisoMaterial::detach()
{
  impl_->hook.detach();
  impl_->removeFieldValues();
  impl_->meshPoly = nullptr;
}

void AnisoMaterial::setSettings(const MaterialSettings& settings)
{
  setSettings(settings, nullptr, nullptr);
}

void AnisoMaterial::setSettings(const MaterialSettings& settings,
                                std::shared_ptr<const HalfVectorLut> halfVector,
                                std::shared_ptr<const BrdfLut> brdf)
{
  validate(settings);
  if (impl_->adopted && settings == impl_->settings)
  {
    return; // its tables are the ones held: nothing to upload, nothing to draw anew
  }
  impl_->adopt(settings, halfVector, brdf);
  if (impl_->meshPoly)
  {
    impl_->refreshField(impl_->meshPoly);
  }
  if (impl_->hook.installed())
  {
    impl_->updateVariant();
  }
  impl_->hook.changed(); // uniforms do not touch VTK's objects
}

const MaterialSettings& AnisoMaterial::settings() const
{
  return impl_->settings;
}

void AnisoMaterial::setLighting(std::shared_ptr<EnvironmentLighting> lighting)
{
  if (!lighting)
  {
    throw errorAbout("environment", "a material needs lighting");
  }
  impl_->lighting = std::move(lighting);
  if (impl_->hook.installed())
  {
    impl_->updateVariant(); // Auto may resolve otherwise under another environment
  }
  impl_->hook.changed();
}

const std::shared_ptr<EnvironmentLighting>& AnisoMaterial::lighting() const
{
  return impl_->lighting;
}

MaterialVariant AnisoMaterial::variant() const
{
  return impl_->hook.installed() ? impl_->installed
                                 : materialVariant(impl_->settings, false, false, false);
}

bool AnisoMaterial::mapsDropped() const
{
  return impl_->dropped;
}

const AnisoMaterial::Counters& AnisoMaterial::counters() const
{
  return impl_->counters;
}
} // namespace aniso
