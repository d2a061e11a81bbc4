#include "vtkpasses/render/MicrostructureMaterial.h"

#include "aniso_shaders.h"
#include "core/error.h"
#include "vtkpasses/render/TextureUpload.h"
#include "vtkpasses/render/vtkAnisoAccumulationPass.h"

#include <cmath>
#include <glm/gtc/type_ptr.hpp>
#include <vtkInformation.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkShaderProgram.h>
#include <vtkSmartPointer.h>
#include <vtkTextureObject.h>
#include <vtkWeakPointer.h>

namespace aniso
{
namespace
{
// CHANNELS of IMAGE as a bilinear, repeating float texture, row 0 at v = 1 (the structure's
// y = 1), so texture(s, p) is the core's wrapping bilinear lookup at p.
vtkSmartPointer<vtkTextureObject> uploadStructure(vtkOpenGLRenderWindow* window, const Image& image,
                                                  int channels, const char* subject)
{
  std::vector<float> texels(std::size_t(image.width) * image.height * channels);
  for (int y = 0; y < image.height; ++y)
  {
    const int row = image.height - 1 - y;
    for (int x = 0; x < image.width; ++x)
    {
      for (int c = 0; c < channels; ++c)
      {
        texels[(std::size_t(y) * image.width + x) * channels + c] =
            image.at(x, row, std::min(c, image.channels - 1));
      }
    }
  }
  return uploadFloatTexture(window, image.width, image.height, channels, texels.data(),
                            TextureFiltering::Linear, TextureWrap::Repeat, subject);
}
} // namespace

std::uint32_t microFrameSeed(const glm::dvec2& frameShift)
{
  const double x = frameShift.x - std::floor(frameShift.x);
  const double y = frameShift.y - std::floor(frameShift.y);
  return std::uint32_t(x * 4294967296.0) ^ (std::uint32_t(y * 65536.0) << 16);
}

std::uint32_t microPixelSeed(int x, int yFromBottom, std::uint32_t frameSeed)
{
  return (std::uint32_t(x) | (std::uint32_t(yFromBottom) << 16)) ^ frameSeed;
}

class MicrostructureShadingMaterial::Textures
{
public:
  vtkWeakPointer<vtkOpenGLRenderWindow> window;
  vtkSmartPointer<vtkTextureObject> height;
  vtkSmartPointer<vtkTextureObject> normal;
  vtkSmartPointer<vtkTextureObject> albedo;
  vtkSmartPointer<vtkTextureObject> tpr;
};

MicrostructureShadingMaterial::MicrostructureShadingMaterial(
    std::shared_ptr<EnvironmentLighting> lighting, MicrostructureSettings settings)
    : SurfaceModelMaterial(std::move(lighting), "microstructure material", std::move(settings)),
      textures_(std::make_unique<Textures>())
{
}

MicrostructureShadingMaterial::~MicrostructureShadingMaterial() = default;

void MicrostructureShadingMaterial::validate(const MicrostructureSettings& s)
{
  if (!s.structure || s.structure->height.empty() || s.structure->normal.empty() ||
      s.structure->albedo.empty())
  {
    throw errorAbout("microstructure", "no structure (height, normal and albedo) to sample");
  }
  validateMicroOptions(s.options);
  if (!(s.tiles > 0.0 && std::isfinite(s.tiles)))
  {
    throw errorAbout("tiles", "must be a finite number > 0");
  }
  validateShaderLights(s.lights);
  if (s.tprMap)
  {
    const Image& m = *s.tprMap;
    if (m.empty() || m.channels < 2)
    {
      throw errorAbout("TPR map", "needs two channels (the direction x, y) and texels");
    }
    for (float value : m.data)
    {
      if (!std::isfinite(value))
      {
        throw errorAbout("TPR map", "holds a value that is not finite");
      }
    }
  }
}

std::string MicrostructureShadingMaterial::fragmentDeclarations() const
{
  // Without a map the turn is compiled out rather than branched over.
  return settings().tprMap ? std::string("#define MICRO_TPR\n") + shaders::kMicroFsDec
                           : std::string(shaders::kMicroFsDec);
}

std::string MicrostructureShadingMaterial::fragmentImplementation() const
{
  return shaders::kMicroFsImpl;
}

void MicrostructureShadingMaterial::setModelUniforms(vtkShaderProgram* program,
                                                     vtkOpenGLRenderWindow* window)
{
  const MicrostructureSettings& micro = settings();
  const Microstructure& s = *micro.structure;
  // A texture of handle 0 was released with the window's context: upload them again.
  if (textures_->window != window || !textures_->height || textures_->height->GetHandle() == 0)
  {
    textures_->height = uploadStructure(window, s.height, 1, "microstructure height");
    textures_->normal = uploadStructure(window, s.normal, 3, "microstructure normals");
    textures_->albedo = uploadStructure(window, s.albedo, 3, "microstructure albedo");
    textures_->tpr = micro.tprMap ? uploadStructure(window, *micro.tprMap, 2, "TPR map") : nullptr;
    textures_->window = window;
  }
  bindTexture(program, "microHeight", textures_->height);
  bindTexture(program, "microNormal", textures_->normal);
  bindTexture(program, "microAlbedo", textures_->albedo);
  if (textures_->tpr)
  {
    bindTexture(program, "microTpr", textures_->tpr);
  }
  const MicroShadingOptions& o = micro.options;
  program->SetUniformf("microDepth", float(s.depth));
  program->SetUniformf("microTiles", float(micro.tiles));
  program->SetUniformi("microK", o.samplesPerAxis);
  program->SetUniformi("microJittered", o.jittered ? 1 : 0);
  double shift[2] = {0.0, 0.0};
  vtkInformation* info = renderer() ? renderer()->GetInformation() : nullptr;
  if (info && info->Has(vtkAnisoAccumulationPass::FRAME_SHIFT()))
  {
    info->Get(vtkAnisoAccumulationPass::FRAME_SHIFT(), shift);
  }
  program->SetUniformi("microFrameSeed",
                       static_cast<int>(microFrameSeed(glm::dvec2(shift[0], shift[1]))));
  program->SetUniformi("microMasking", o.masking == MicroMasking::Normal     ? 0
                                       : o.masking == MicroMasking::Parallax ? 1
                                                                             : 2);
  program->SetUniformi("microSelfShadowing", o.selfShadowing ? 1 : 0);
  program->SetUniformi("microBrdf", o.brdf == MicroBrdf::BlinnPhong ? 1 : 0);
  program->SetUniformf("microRoughness", float(o.roughness));
  program->SetUniformf("microBlinnExponent", float(o.blinnExponent));
  const glm::vec3 f0(o.f0);
  program->SetUniform3f("microF0", glm::value_ptr(f0));
  program->SetUniformi("microMarchSteps", o.marchSteps);
}
} // namespace aniso
