#include "vtkpasses/render/AnisoMaterial.h"

#include "core/error.h"
#include "core/lut/lut.h"
#include "core/lut/lut_cache.h"
#include "vtkpasses/render/EnvironmentLighting.h"
#include "vtkpasses/render/RendererMatrices.h"
#include "vtkpasses/render/TextureUpload.h"
#include "vtkpasses/render/vtkAnisoAccumulationPass.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <optional>
#include <string>
#include <vtkActor.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkDataObject.h>
#include <vtkInformation.h>
#include <vtkInformationDoubleVectorKey.h>
#include <vtkInformationIntegerKey.h>
#include <vtkMatrix4x4.h>
#include <vtkOpenGLPolyDataMapper.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLState.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>
#include <vtkShaderProgram.h>
#include <vtkShaderProperty.h>
#include <vtkSmartPointer.h>
#include <vtkTextureObject.h>
#include <vtkWeakPointer.h>
#include <vtk_glew.h>

namespace aniso
{
namespace
{
// The tags the material's code follows (each replacement starts with its tag, so VTK's own
// substitution still happens there).
constexpr const char* kVertexDecTag = "//VTK::Normal::Dec";
constexpr const char* kVertexImplTag = "//VTK::CustomEnd::Impl";
constexpr const char* kFragmentDecTag = "//VTK::Light::Dec";
constexpr const char* kFragmentUniformFlowTag = "//VTK::UniformFlow::Impl";
constexpr const char* kFragmentImplTag = "//VTK::Light::Impl";

constexpr int kMaxSamples = 1 << 16;

// Filtered importance sampling: the level from the sample's footprint along the lobe's sharp
// axis (the anisotropy term is 0.5 log2 of the width ratio sqrt((n_max + 1) / (n_min + 1))) and
// no bias. Measured against the reference, it beats unfiltered lookups at N = 4, 16, 64 for
// (10, 10), (1000, 100) and (20000, 70), where the isotropic footprint with a bias of +1 lost
// to them at every N (docs/BENCHMARKS.md, "Filtered importance sampling and MIS in the shader").
constexpr double kLodAnisotropyWeight = 0.25;
constexpr double kLodBias = 0.0;

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

bool hasArray(vtkPolyData* poly, const char* name, int components)
{
  vtkDataArray* array = poly->GetPointData()->GetArray(name);
  return array && array->GetNumberOfComponents() == components &&
         array->GetNumberOfTuples() == poly->GetNumberOfPoints();
}
} // namespace

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
  vtkWeakPointer<vtkActor> actor;
  vtkWeakPointer<vtkRenderer> renderer;
  vtkWeakPointer<vtkOpenGLPolyDataMapper> mapper;
  unsigned long updateShaderTag = 0;
  unsigned long mapperEndTag = 0;
  unsigned long rendererEndTag = 0;
  // Activated for the current draw; freed once the renderer has drawn (as
  // vtkOpenGLTexture::PostRender frees VTK's own), so none stays active between frames.
  std::vector<vtkWeakPointer<vtkTextureObject>> active;
  std::optional<MaterialVariant> installed;
  bool normals = false;
  bool tangents = false;
  bool tcoords = false;
  bool dropped = false;

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

  ~Impl() { detach(); }

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
    if (s.halfVectors == HalfVectorSource::Lut)
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
  }

  void deactivate()
  {
    for (vtkTextureObject* texture : active)
    {
      if (texture)
      {
        texture->Deactivate();
      }
    }
    active.clear();
  }

  void onRendererEnd(vtkObject*, unsigned long, void*) { deactivate(); }

  void detach()
  {
    deactivate();
    if (renderer)
    {
      renderer->RemoveObserver(rendererEndTag);
    }
    if (mapper)
    {
      mapper->RemoveObserver(updateShaderTag);
      mapper->RemoveObserver(mapperEndTag);
      for (const char* attribute : {"anisoNormalMC", "anisoTangentMC", "anisoTCoordMC"})
      {
        mapper->RemoveVertexAttributeMapping(attribute);
      }
    }
    if (actor)
    {
      vtkShaderProperty* sp = actor->GetShaderProperty();
      sp->ClearVertexShaderReplacement(kVertexDecTag, true);
      sp->ClearVertexShaderReplacement(kVertexImplTag, true);
      sp->ClearFragmentShaderReplacement(kFragmentDecTag, true);
      sp->ClearFragmentShaderReplacement(kFragmentUniformFlowTag, true);
      sp->ClearFragmentShaderReplacement(kFragmentImplTag, true);
      actor->Modified();
    }
    mapper = nullptr;
    actor = nullptr;
    renderer = nullptr;
    installed.reset();
  }

  // Looks at the mesh the mapper is about to draw (its input is up to date at EndEvent) and
  // installs the matching variant.
  void onMapperEnd(vtkObject*, unsigned long, void*)
  {
    vtkPolyData* poly = mapper ? mapper->GetInput() : nullptr;
    if (!poly)
    {
      return;
    }
    normals = hasArray(poly, kNormalsArray, 3);
    tangents = hasArray(poly, kTangentsArray, 3);
    tcoords = hasArray(poly, kTCoordsArray, 2);
    updateVariant();
  }

  void updateVariant()
  {
    dropped = droppedMaps(settings, tcoords);
    const MaterialVariant v = materialVariant(settings, normals, tangents, tcoords);
    if (!installed || *installed != v)
    {
      install(v);
    }
  }

  void install(const MaterialVariant& v)
  {
    if (!actor || !mapper)
    {
      return;
    }
    const MaterialShaderCode code = composeMaterialShaders(v);
    vtkShaderProperty* sp = actor->GetShaderProperty();
    auto replace = [](const char* tag, const std::string& text)
    { return std::string(tag) + "\n" + text; };
    sp->ClearVertexShaderReplacement(kVertexDecTag, true);
    sp->ClearVertexShaderReplacement(kVertexImplTag, true);
    sp->ClearFragmentShaderReplacement(kFragmentDecTag, true);
    sp->ClearFragmentShaderReplacement(kFragmentUniformFlowTag, true);
    sp->ClearFragmentShaderReplacement(kFragmentImplTag, true);
    sp->AddVertexShaderReplacement(kVertexDecTag, true,
                                   replace(kVertexDecTag, code.vertexDeclarations), false);
    sp->AddVertexShaderReplacement(kVertexImplTag, true,
                                   replace(kVertexImplTag, code.vertexImplementation), false);
    sp->AddFragmentShaderReplacement(kFragmentDecTag, true,
                                     replace(kFragmentDecTag, code.fragmentDeclarations), false);
    sp->AddFragmentShaderReplacement(kFragmentUniformFlowTag, true,
                                     replace(kFragmentUniformFlowTag, code.fragmentUniformFlow),
                                     false);
    sp->AddFragmentShaderReplacement(kFragmentImplTag, true,
                                     replace(kFragmentImplTag, code.fragmentImplementation), false);

    auto map = [this](bool on, const char* attribute, const char* array)
    {
      if (on)
      {
        mapper->MapDataArrayToVertexAttribute(attribute, array,
                                              vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
      }
      else
      {
        mapper->RemoveVertexAttributeMapping(attribute);
      }
    };
    map(v.normals, "anisoNormalMC", kNormalsArray);
    map(v.tangents, "anisoTangentMC", kTangentsArray);
    map(v.tcoords, "anisoTCoordMC", kTCoordsArray);
    installed = v;
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
    auto refresh = [](Texture& texture, std::shared_ptr<const void> source, auto&& make)
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
        texture.object = make();
        texture.source = source;
      }
    };
    refresh(halfVectorTexture, halfVectorLut,
            [&]
            {
              return uploadFloatTexture(window, halfVectorLut->size, halfVectorLut->size, 4,
                                        halfVectorLut->rgba.data(), TextureFiltering::Nearest,
                                        TextureWrap::Clamp, "half-vector LUT");
            });
    refresh(brdfTexture, brdfLut,
            [&]
            {
              return uploadFloatTexture(window, brdfLut->size, brdfLut->size, 2, brdfLut->rg.data(),
                                        TextureFiltering::Linear, TextureWrap::Clamp, "BRDF LUT");
            });
    const MaterialVariant& v = *installed;
    auto mapTexture = [&](Texture& texture, bool used, const std::shared_ptr<const Image>& image,
                          int channels, const char* name)
    {
      refresh(texture, used ? image : nullptr,
              [&] { return uploadMapTexture(window, *image, channels, name); });
    };
    mapTexture(normalTexture, v.normalMap, settings.normalMap, 3, "normal map");
    mapTexture(quaternionTexture, v.quaternionMap, settings.quaternionMap, 3, "quaternion map");
    mapTexture(tprTexture, v.tprMap, settings.tprMap, 2, "TPR map");
    mapTexture(heightTexture, v.heightMap, settings.heightMap, 1, "height map");
    mapTexture(occlusionTexture, v.occlusionMap, settings.occlusionMap, 1, "occlusion map");
    mapTexture(metallicTexture, v.metallicMap, settings.metallicMap, 1, "metallic map");
    refresh(albedoTexture, v.albedoMap ? settings.albedoMap : nullptr,
            [&] { return uploadMapTexture(window, asRgb(*settings.albedoMap), 3, "albedo map"); });
  }

  std::array<Texture*, 9> allTextures()
  {
    return {&halfVectorTexture, &brdfTexture,   &normalTexture,    &quaternionTexture, &tprTexture,
            &heightTexture,     &albedoTexture, &occlusionTexture, &metallicTexture};
  }

  // Uniforms and textures, every time the mapper draws: no value here changes the shader.
  void onUpdateShader(vtkObject*, unsigned long, void* data)
  {
    auto* program = static_cast<vtkShaderProgram*>(data);
    if (!program || !installed || !actor || !renderer || !lighting ||
        !program->IsUniformUsed("anisoSampleCount"))
    {
      return;
    }
    auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
    if (!window)
    {
      return;
    }
    try
    {
      updateTextures(window);
      setUniforms(program, window);
    }
    catch (const std::exception& e)
    {
      // Exceptions must not unwind through VTK's render loop; the draw goes on unshaded.
      vtkGenericWarningMacro("anisotropic material: " << e.what());
    }
  }

  void bind(vtkShaderProgram* program, const char* sampler, vtkTextureObject* texture)
  {
    texture->Activate();
    program->SetUniformi(sampler, texture->GetTextureUnit());
    if (std::find(active.begin(), active.end(), texture) == active.end())
    {
      active.emplace_back(texture);
    }
  }

  void setUniforms(vtkShaderProgram* program, vtkOpenGLRenderWindow* window)
  {
    setUniformMatrix(program, "anisoClipToWorld", clipToWorld(renderer));
    const glm::dmat3 toWorld(toGlm(actor->GetMatrix()));
    const double det = glm::determinant(toWorld);
    const glm::dmat3 normalToWorld =
        det != 0.0 && std::isfinite(det) ? glm::transpose(glm::inverse(toWorld)) : toWorld;
    setUniformMatrix(program, "anisoDirectionToWorld", toWorld);
    setUniformMatrix(program, "anisoNormalToWorld", normalToWorld);

    setVector(program, "anisoF0", settings.f0);
    setVector(program, "anisoAlbedo", settings.albedo);
    program->SetUniformi("anisoSampleCount", settings.samples);
    double shift[2] = {0.0, 0.0};
    vtkInformation* info = renderer->GetInformation();
    if (info && info->Has(vtkAnisoAccumulationPass::FRAME_SHIFT()))
    {
      info->Get(vtkAnisoAccumulationPass::FRAME_SHIFT(), shift);
    }
    const float frameShift[2] = {static_cast<float>(shift[0]), static_cast<float>(shift[1])};
    program->SetUniform2f("anisoFrameShift", frameShift);
    const int frameIndex = info && info->Has(vtkAnisoAccumulationPass::FRAME_INDEX())
                               ? info->Get(vtkAnisoAccumulationPass::FRAME_INDEX())
                               : 0;
    program->SetUniformf("anisoLog2FrameCount", static_cast<float>(std::log2(frameIndex + 1.0)));

    // The environment: cube with seamless filtering across faces (VTK enables it only for
    // its own image-based lighting).
    window->GetState()->vtkglEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    bind(program, "anisoEnvironment", lighting->cubeTexture(window));
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
    if (installed->environmentMis)
    {
      bind(program, "anisoEnvCdf", lighting->samplingCdfTexture(window));
      bind(program, "anisoEnvPdf", lighting->samplingPdfTexture(window));
      bind(program, "anisoEnvGuide", lighting->samplingGuideTexture(window));
      const EnvironmentDistribution& d = lighting->samplingDistribution();
      program->SetUniform2i("anisoEnvGrid", std::array<int, 2>{d.width(), d.height()}.data());
      // The split from the lobe and this environment's densities (env_sampling.h), unless set.
      const double share = settings.misLobeShare > 0.0 && settings.misLobeShare < 1.0
                               ? settings.misLobeShare
                               : misLobeFraction(settings.lobe, d);
      program->SetUniformf("anisoLobeFraction", static_cast<float>(share));
    }
    program->SetUniform3fv(
        "anisoIrradianceSH", 9,
        reinterpret_cast<const float(*)[3]>(lighting->irradianceCoefficients().data()));

    if (halfVectorTexture.object)
    {
      bind(program, "anisoHalfVectorLut", halfVectorTexture.object);
      program->SetUniformi("anisoHalfVectorLutSize", halfVectorLut->size);
    }
    // The in-shader half vectors and the MIS densities read the exponents.
    const float exponents[2] = {static_cast<float>(settings.lobe.nu),
                                static_cast<float>(settings.lobe.nv)};
    program->SetUniform2f("anisoExponents", exponents);
    if (brdfTexture.object)
    {
      bind(program, "anisoBrdfLut", brdfTexture.object);
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
        bind(program, sampler, texture->object);
      }
    }
    program->SetUniformf("anisoHeightScale", static_cast<float>(settings.heightScale));
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
}

void AnisoMaterial::apply(vtkActor* actor, vtkRenderer* renderer)
{
  if (!actor || !renderer)
  {
    throw errorAbout("material", "needs an actor and a renderer");
  }
  auto* mapper = vtkOpenGLPolyDataMapper::SafeDownCast(actor->GetMapper());
  if (!mapper)
  {
    throw errorAbout("material", "the actor's mapper is not an OpenGL polydata mapper");
  }
  impl_->detach();
  impl_->actor = actor;
  impl_->renderer = renderer;
  impl_->mapper = mapper;
  Impl* impl = impl_.get();
  impl_->updateShaderTag =
      mapper->AddObserver(vtkCommand::UpdateShaderEvent, impl, &Impl::onUpdateShader);
  impl_->mapperEndTag = mapper->AddObserver(vtkCommand::EndEvent, impl, &Impl::onMapperEnd);
  impl_->rendererEndTag = renderer->AddObserver(vtkCommand::EndEvent, impl, &Impl::onRendererEnd);
  // If the mesh is already there, install now; otherwise the first draw does.
  if (vtkPolyData* poly = mapper->GetInput())
  {
    if (poly->GetNumberOfPoints() > 0)
    {
      impl_->onMapperEnd(nullptr, 0, nullptr);
    }
  }
  actor->Modified();
}

void AnisoMaterial::detach()
{
  impl_->detach();
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
  impl_->adopt(settings, halfVector, brdf);
  if (impl_->installed)
  {
    impl_->updateVariant();
  }
  if (impl_->actor)
  {
    // Uniform changes do not touch VTK's objects; this tells progressive accumulation.
    impl_->actor->Modified();
  }
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
  if (impl_->actor)
  {
    impl_->actor->Modified();
  }
}

const std::shared_ptr<EnvironmentLighting>& AnisoMaterial::lighting() const
{
  return impl_->lighting;
}

MaterialVariant AnisoMaterial::variant() const
{
  return impl_->installed ? *impl_->installed
                          : materialVariant(impl_->settings, false, false, false);
}

bool AnisoMaterial::mapsDropped() const
{
  return impl_->dropped;
}
} // namespace aniso
