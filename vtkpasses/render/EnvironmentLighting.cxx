#include "vtkpasses/render/EnvironmentLighting.h"

#include "core/error.h"
#include "vtkpasses/render/TextureUpload.h"

#include <algorithm>
#include <cmath>
#include <glm/matrix.hpp>
#include <vtkOpenGLRenderWindow.h>
#include <vtkTextureObject.h>

namespace aniso
{
namespace
{
// ENV's radiance SH9 times the cosine-lobe convolution factors of bands 0, 1, 2 (Ramamoorthi
// and Hanrahan): irradiance coefficients.
std::array<glm::vec3, 9> irradianceSh9(const Environment& env)
{
  const Sh9 radiance = projectSh9(env);
  const double bandFactor[3] = {M_PI, 2.0 * M_PI / 3.0, M_PI / 4.0};
  std::array<glm::vec3, 9> irradiance{};
  for (int i = 0; i < 9; ++i)
  {
    const int band = i == 0 ? 0 : (i < 4 ? 1 : 2);
    irradiance[i] = glm::vec3(radiance[i] * bandFactor[band]);
  }
  return irradiance;
}
} // namespace

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
  irradiance_ = irradianceSh9(*environment_);
}

EnvironmentLighting::~EnvironmentLighting() = default;

std::shared_ptr<EnvironmentLighting> EnvironmentLighting::copyBakes() const
{
  std::shared_ptr<EnvironmentLighting> copy(new EnvironmentLighting());
  copy->environment_ = environment_;
  copy->cubemap_ = cubemap_;
  copy->irradiance_ = irradiance_;
  copy->rotationDegrees_ = rotationDegrees_;
  copy->distribution_ = distribution_;
  copy->analysis_ = analysis_;
  copy->analysisFailed_ = analysisFailed_;
  if (split_)
  {
    copy->split_ = std::make_unique<SourceSplit>(*split_);
  }
  return copy;
}

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

const EnvAnalysis& EnvironmentLighting::analysis()
{
  if (!analysis_)
  {
    analysis_ = sharedEnvironmentAnalysis(*environment_);
  }
  return *analysis_;
}

EnvironmentSampling EnvironmentLighting::resolveSampling(EnvironmentSampling requested)
{
  if (requested != EnvironmentSampling::Auto)
  {
    return requested;
  }
  if (!analysis_ && !analysisFailed_)
  {
    try
    {
      analysis();
    }
    catch (const Error&)
    {
      // No analysis (reported where it is shown): auto keeps to the lobe samples.
      analysisFailed_ = true;
    }
  }
  return analysis_ && analysis_->concentrated() ? EnvironmentSampling::Sources
                                                : EnvironmentSampling::Off;
}

void EnvironmentLighting::prepare(EnvironmentSampling requested)
{
  switch (resolveSampling(requested))
  {
  case EnvironmentSampling::Mis:
    samplingDistribution();
    break;
  case EnvironmentSampling::Sources:
    sourceSplit();
    break;
  default:
    break;
  }
}

bool EnvironmentLighting::prepared(EnvironmentSampling requested) const
{
  if (requested == EnvironmentSampling::Auto)
  {
    if (!analysis_)
    {
      return analysisFailed_;
    }
    requested = analysis_->concentrated() ? EnvironmentSampling::Sources : EnvironmentSampling::Off;
  }
  switch (requested)
  {
  case EnvironmentSampling::Mis:
    return distribution_ != nullptr;
  case EnvironmentSampling::Sources:
    return split_ != nullptr;
  default:
    return true;
  }
}

const EnvironmentLighting::SourceSplit& EnvironmentLighting::sourceSplit()
{
  if (!split_)
  {
    auto split = std::make_unique<SourceSplit>();
    analysis();
    split->analysis = analysis_;
    // The residual image itself (bilinear), not the environment less the excess: with an
    // analytic source smaller than the cube's samples, those would see the subtracted excess
    // and miss the source. What is drawn is then the analysed image, residual + excess, whose
    // texel means hold every source's power.
    const EquirectEnvironment residual(analysis_->residual, analysis_->key + ":residual");
    split->residualCube = buildCubemap(residual, cubemap_.size);
    split->residualIrradiance = irradianceSh9(residual);
    split->groups = std::make_shared<const SourceGroups>(buildSourceGroups(*analysis_));
    split->excess =
        std::make_shared<const EquirectEnvironment>(analysis_->excess, analysis_->key + ":excess");
    split_ = std::move(split);
  }
  return *split_;
}

const EnvironmentLighting::SharedSourcePoints&
EnvironmentLighting::sharedSourcePoints(std::uint32_t frame, int count)
{
  count = std::clamp(count, 0, kMaxSourcePoints);
  if (sharedPoints_ && sharedPoints_->frame == frame && sharedPoints_->count == count &&
      sharedPoints_->rotationDegrees == rotationDegrees_)
  {
    return *sharedPoints_;
  }
  const SourceSplit& split = sourceSplit();
  const SourceGroups& groups = *split.groups;
  auto packed = std::make_unique<SharedSourcePoints>();
  packed->frame = frame;
  packed->count = count;
  packed->rotationDegrees = rotationDegrees_;
  const std::vector<double> selection = pointSelection(groups);
  for (std::size_t g = 0; g < selection.size() && g < packed->selection.size(); ++g)
  {
    packed->selection[g] = static_cast<float>(selection[g]);
  }
  std::vector<SourcePoint> drawn = sourcePoints(groups, selection, *split.excess, frame, count);
  std::stable_sort(drawn.begin(), drawn.end(),
                   [](const SourcePoint& a, const SourcePoint& b) { return a.group < b.group; });
  const glm::dmat3 environmentToWorld = glm::transpose(worldToEnvironment());
  for (std::size_t i = 0; i < drawn.size(); ++i)
  {
    const SourcePoint& p = drawn[i];
    if (p.group >= 0 && p.group < SourceGroups::kMaxGroups)
    {
      const std::size_t g = std::size_t(p.group);
      if (packed->runs[2 * g + 1] == 0)
      {
        packed->runs[2 * g] = int(i);
      }
      ++packed->runs[2 * g + 1];
    }
    const glm::dvec3 d = environmentToWorld * p.direction;
    packed->points[4 * i] = static_cast<float>(d.x);
    packed->points[4 * i + 1] = static_cast<float>(d.y);
    packed->points[4 * i + 2] = static_cast<float>(d.z);
    packed->points[4 * i + 3] = p.density > 0.0 ? static_cast<float>(p.density) : 1.0f;
    packed->radiance[3 * i] = static_cast<float>(p.radiance.x);
    packed->radiance[3 * i + 1] = static_cast<float>(p.radiance.y);
    packed->radiance[3 * i + 2] = static_cast<float>(p.radiance.z);
  }
  sharedPoints_ = std::move(packed);
  return *sharedPoints_;
}

void EnvironmentLighting::uploadSourceTextures(vtkOpenGLRenderWindow* window)
{
  if (sourceTextures_[0] && sourceWindow_ == window && sourceTextures_[0]->GetHandle() != 0)
  {
    return;
  }
  for (auto& t : sourceTextures_)
  {
    if (t && sourceWindow_)
    {
      t->ReleaseGraphicsResources(sourceWindow_);
    }
    t = nullptr;
  }
  const SourceSplit& split = sourceSplit();
  const Image& excess = split.analysis->excess;
  const SourceGroups& groups = *split.groups;
  // The rows, then the entries, then the rows' guides, kSourceTableWidth a texture row (at
  // least one texel, so that the sampler is complete; a group-less split draws no source
  // sample): a row (cumulative within its group, grid row, index of its first entry here,
  // entry count), an entry (cumulative within its row, texel index, the guide of its row's bin
  // of the same position as an index here, 0), a row's guide (the guide of its group's bin of
  // the same position, 0, 0, 0) (core/env/env_source_groups.h, guidedSearch).
  const std::size_t rows = groups.rowY.size();
  const std::size_t entries = groups.entryTexel.size();
  const std::size_t cells = std::max<std::size_t>(2 * rows + entries, 1);
  const int tableRows = int((cells + kSourceTableWidth - 1) / kSourceTableWidth);
  std::vector<float> tableData(std::size_t(tableRows) * kSourceTableWidth * 4, 0.0f);
  for (std::size_t r = 0; r < rows; ++r)
  {
    tableData[4 * r] = groups.rowCdf[r];
    tableData[4 * r + 1] = float(groups.rowY[r]);
    tableData[4 * r + 2] = float(rows + std::size_t(groups.rowFirst[r]));
    tableData[4 * r + 3] = float(groups.rowCount[r]);
  }
  for (std::size_t e = 0; e < entries; ++e)
  {
    tableData[4 * (rows + e)] = groups.entryCdf[e];
    tableData[4 * (rows + e) + 1] = float(groups.entryTexel[e]);
    tableData[4 * (rows + e) + 2] = float(rows + groups.entryGuide[e]);
  }
  for (std::size_t r = 0; r < rows; ++r)
  {
    tableData[4 * (rows + entries + r)] = float(groups.rowGuide[r]);
  }
  std::vector<float> densityData(std::size_t(excess.width) * std::size_t(excess.height) * 2);
  for (std::size_t i = 0; i < densityData.size() / 2; ++i)
  {
    densityData[2 * i] = groups.density.empty() ? 0.0f : groups.density[i];
    densityData[2 * i + 1] = groups.group.empty() ? -1.0f : float(groups.group[i]);
  }
  sourceTextures_[0] = uploadCubemap(window, split.residualCube, "residual environment cubemap");
  sourceTextures_[1] = uploadFloatTexture(window, excess.width, excess.height, 3,
                                          excess.data.data(), TextureFiltering::Linear,
                                          TextureWrap::RepeatSClampT, "environment sources");
  sourceTextures_[2] =
      uploadFloatTexture(window, kSourceTableWidth, tableRows, 4, tableData.data(),
                         TextureFiltering::Nearest, TextureWrap::Clamp, "source group tables");
  sourceTextures_[3] =
      uploadFloatTexture(window, excess.width, excess.height, 2, densityData.data(),
                         TextureFiltering::Nearest, TextureWrap::Clamp, "source group densities");
  sourceWindow_ = window;
}

vtkTextureObject* EnvironmentLighting::residualCubeTexture(vtkOpenGLRenderWindow* window)
{
  uploadSourceTextures(window);
  return sourceTextures_[0];
}

vtkTextureObject* EnvironmentLighting::sourceRadianceTexture(vtkOpenGLRenderWindow* window)
{
  uploadSourceTextures(window);
  return sourceTextures_[1];
}

vtkTextureObject* EnvironmentLighting::sourceTableTexture(vtkOpenGLRenderWindow* window)
{
  uploadSourceTextures(window);
  return sourceTextures_[2];
}

vtkTextureObject* EnvironmentLighting::sourceDensityTexture(vtkOpenGLRenderWindow* window)
{
  uploadSourceTextures(window);
  return sourceTextures_[3];
}

void EnvironmentLighting::releaseGraphicsResources(vtkWindow* window)
{
  if (sourceWindow_ == window)
  {
    for (auto& t : sourceTextures_)
    {
      if (t)
      {
        t->ReleaseGraphicsResources(window);
      }
      t = nullptr;
    }
    sourceWindow_ = nullptr;
  }
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
