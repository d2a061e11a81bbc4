#include "vtkpasses/render/EnvironmentLighting.h"

#include "core/error.h"
#include "vtkpasses/render/TextureUpload.h"

#include <cmath>
#include <vtkOpenGLRenderWindow.h>
#include <vtkTextureObject.h>

namespace aniso
{
EnvironmentLighting::EnvironmentLighting(std::shared_ptr<const Environment> environment,
                                         int cubeSize)
    : environment_(std::move(environment))
{
  if (!environment_)
  {
    throw errorAbout("environment", "none given");
  }
  cubemap_ = buildCubemap(*environment_, cubeSize);
  // Projected from the environment itself rather than the cubemap: the diffuse term then does
  // not depend on the cube resolution.
  const Sh9 radiance = projectSh9(*environment_);
  // Cosine-lobe convolution factors of bands 0, 1, 2 (Ramamoorthi and Hanrahan).
  const double bandFactor[3] = {M_PI, 2.0 * M_PI / 3.0, M_PI / 4.0};
  for (int i = 0; i < 9; ++i)
  {
    const int band = i == 0 ? 0 : (i < 4 ? 1 : 2);
    irradiance_[i] = glm::vec3(radiance[i] * bandFactor[band]);
  }
}

EnvironmentLighting::~EnvironmentLighting() = default;

void EnvironmentLighting::setRotationDegrees(double degrees)
{
  if (!std::isfinite(degrees))
  {
    throw errorAbout("env-rotation", "not a finite angle");
  }
  if (degrees != rotationDegrees_)
  {
    rotationDegrees_ = degrees;
    ++revision_;
  }
}

glm::dmat3 EnvironmentLighting::worldToEnvironment() const
{
  const double a = -rotationDegrees_ * M_PI / 180.0;
  const double c = std::cos(a);
  const double s = std::sin(a);
  // Column-major: R_z(a) maps (x, y, z) to (c x - s y, s x + c y, z).
  return glm::dmat3(c, s, 0.0, -s, c, 0.0, 0.0, 0.0, 1.0);
}

vtkTextureObject* EnvironmentLighting::cubeTexture(vtkOpenGLRenderWindow* window)
{
  // A handle of 0: released with the window's context, which its widget may make anew.
  if (!texture_ || textureWindow_ != window || texture_->GetHandle() == 0)
  {
    if (texture_ && textureWindow_)
    {
      texture_->ReleaseGraphicsResources(textureWindow_);
    }
    texture_ = uploadCubemap(window, cubemap_, "environment cubemap");
    textureWindow_ = window;
  }
  return texture_;
}

Image samplingGuideTable(const Image& cdf, int width, int height)
{
  Image guide(cdf.width, cdf.height, 1);
  auto fill = [&](int row, int count)
  {
    int interval = 0;
    for (int j = 0; j <= count; ++j)
    {
      const float u = static_cast<float>(j) / static_cast<float>(count);
      // The last interval whose lower CDF value is <= u (the CDF never falls).
      while (interval + 1 < count && cdf.at(interval + 1, row, 0) <= u)
      {
        ++interval;
      }
      guide.at(j, row, 0) = static_cast<float>(interval);
    }
  };
  for (int y = 0; y < height; ++y)
  {
    fill(y, width);
  }
  fill(height, height);
  return guide;
}

const EnvironmentDistribution& EnvironmentLighting::samplingDistribution()
{
  if (!distribution_)
  {
    EnvSamplingOptions options;
    options.width = 1024;
    // Covering what the cube shows: its bilinear reach of the sun is wider than the sun's texels
    // (docs/BENCHMARKS.md, "MIS outliers next to the sun").
    distribution_ = sharedDistribution(*environment_, options, &cubemap_);
  }
  return *distribution_;
}

void EnvironmentLighting::uploadSamplingTables(vtkOpenGLRenderWindow* window)
{
  if (cdfTexture_ && pdfTexture_ && guideTexture_ && samplingWindow_ == window &&
      cdfTexture_->GetHandle() != 0)
  {
    return;
  }
  for (vtkTextureObject* t : {cdfTexture_.Get(), pdfTexture_.Get(), guideTexture_.Get()})
  {
    if (t && samplingWindow_)
    {
      t->ReleaseGraphicsResources(samplingWindow_);
    }
  }
  const EnvironmentDistribution& d = samplingDistribution();
  const Image cdf = d.cdfTable();
  const Image density = d.pdfTable();
  const Image lodBound = d.lodBoundTable(cubemap_.size, mipLevels() - 1);
  Image pdf(density.width, density.height, 2);
  for (std::size_t i = 0; i < density.data.size(); ++i)
  {
    pdf.data[2 * i] = density.data[i];
    pdf.data[2 * i + 1] = lodBound.data[i];
  }
  cdfTexture_ =
      uploadFloatTexture(window, cdf.width, cdf.height, 1, cdf.data.data(),
                         TextureFiltering::Nearest, TextureWrap::Clamp, "environment sampling CDF");
  pdfTexture_ = uploadFloatTexture(window, pdf.width, pdf.height, 2, pdf.data.data(),
                                   TextureFiltering::Nearest, TextureWrap::Clamp,
                                   "environment sampling density");
  const Image guide = samplingGuideTable(cdf, d.width(), d.height());
  guideTexture_ = uploadFloatTexture(window, guide.width, guide.height, 1, guide.data.data(),
                                     TextureFiltering::Nearest, TextureWrap::Clamp,
                                     "environment sampling guide");
  samplingWindow_ = window;
}

vtkTextureObject* EnvironmentLighting::samplingCdfTexture(vtkOpenGLRenderWindow* window)
{
  uploadSamplingTables(window);
  return cdfTexture_;
}

vtkTextureObject* EnvironmentLighting::samplingPdfTexture(vtkOpenGLRenderWindow* window)
{
  uploadSamplingTables(window);
  return pdfTexture_;
}

vtkTextureObject* EnvironmentLighting::samplingGuideTexture(vtkOpenGLRenderWindow* window)
{
  uploadSamplingTables(window);
  return guideTexture_;
}

void EnvironmentLighting::releaseGraphicsResources(vtkWindow* window)
{
  if (samplingWindow_ == window)
  {
    for (vtkTextureObject* t : {cdfTexture_.Get(), pdfTexture_.Get(), guideTexture_.Get()})
    {
      if (t)
      {
        t->ReleaseGraphicsResources(window);
      }
    }
    cdfTexture_ = nullptr;
    pdfTexture_ = nullptr;
    guideTexture_ = nullptr;
    samplingWindow_ = nullptr;
  }
  if (texture_ && textureWindow_ == window)
  {
    texture_->ReleaseGraphicsResources(window);
    texture_ = nullptr;
    textureWindow_ = nullptr;
  }
}
} // namespace aniso
