#pragma once
// The light of a scene: an environment baked into a float cubemap with its full mip chain
// (specular lookups, background) and SH9 irradiance (diffuse), rotated about the world Z axis.
// Shared by every anisotropic material of a renderer and by the accumulation pass.
#include "core/env/cubemap.h"
#include "core/env/env_sampling.h"
#include "core/env/env_source_groups.h"
#include "core/env/env_sources.h"
#include "core/env/environment.h"
#include "core/parameters/choices.h"

#include <array>
#include <cstdint>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <string>
#include <vtkSmartPointer.h>
#include <vtkWeakPointer.h>

class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

namespace aniso
{
// Guide table of a CDF table (the layout of EnvironmentDistribution::cdfTable): entry j of a CDF
// of `count` intervals holds the interval containing j / count, for j = 0..count, so the interval
// of any u lies between the entries of floor(u count) and the next: a search starts there and
// takes no step where the density is high (the sun) instead of log2(count) steps everywhere.
// Same size and rows as cdf; computed from its float values, the ones the shader compares.
Image samplingGuideTable(const Image& cdf, int width, int height);

class EnvironmentLighting
{
public:
  // Bakes the cubemap (level 0 of cubeSize, a power of two) and the SH9 projection now.
  // Throws aniso::Error for an invalid size.
  EnvironmentLighting(std::shared_ptr<const Environment> environment, int cubeSize);
  ~EnvironmentLighting();
  // A lighting with what this one has baked (cubemap, SH9, rotation, analysis, distribution,
  // split) and none of its textures: what a worker then prepares further while this one is
  // drawn from.
  std::shared_ptr<EnvironmentLighting> copyBakes() const;
  EnvironmentLighting(const EnvironmentLighting&) = delete;
  EnvironmentLighting& operator=(const EnvironmentLighting&) = delete;

  const Environment& environment() const { return *environment_; }
  const Cubemap& cubemap() const { return cubemap_; }
  int cubeSize() const { return cubemap_.size; }
  int mipLevels() const { return static_cast<int>(cubemap_.mips.size()); }

  // Radiance SH9 coefficients multiplied by the cosine-lobe factors (pi, 2pi/3, pi/4), so that
  // E(n) = sum c_i Y_i(n) in environment coordinates (what the shaders evaluate).
  const std::array<glm::vec3, 9>& irradianceCoefficients() const { return irradiance_; }

  // The environment turned by this angle about +Z (counter-clockwise seen from above): the
  // light arriving from world direction d is radiance(R_z(-angle) d).
  void setRotationDegrees(double degrees);
  double rotationDegrees() const { return rotationDegrees_; }
  glm::dmat3 worldToEnvironment() const;

  // Bumped by every change of what the lighting shows (rotation), so progressive
  // accumulation knows to start over.
  uint64_t revision() const { return revision_; }

  // The cube texture in WINDOW's context, uploaded on first use (and again for a new window).
  vtkTextureObject* cubeTexture(vtkOpenGLRenderWindow* window);

  // Environment importance sampling, baked on first use only (a material with sampling off
  // never pays for it): the luminance x solid-angle distribution over a 1024 x 512 grid (texels
  // about the sun's size, so its samples land on it), covering where the cube map shows
  // radiance (EnvironmentDistribution::bake with the cube), shared through sharedDistribution.
  const EnvironmentDistribution& samplingDistribution();
  // Its shader tables in WINDOW's context (R32F, the density's RG32F, nearest, read with texelFetch): the CDFs
  // (EnvironmentDistribution::cdfTable), the density per solid angle (pdfTable) with the level
  // bound of filtered lookups (lodBoundTable) as a second channel, and the guide
  // table (samplingGuideTable).
  vtkTextureObject* samplingCdfTexture(vtkOpenGLRenderWindow* window);
  vtkTextureObject* samplingPdfTexture(vtkOpenGLRenderWindow* window);
  vtkTextureObject* samplingGuideTexture(vtkOpenGLRenderWindow* window);

  // The environment's analysis (core/env/env_sources.h, shared through
  // sharedEnvironmentAnalysis), made on first use.
  const EnvAnalysis& analysis();
  // The analysis if it was made (by analysis(), prepare or a copy's bakes), else null: what the
  // UI thread reads, never baking.
  const std::shared_ptr<const EnvAnalysis>& bakedAnalysis() const { return analysis_; }
  // What a material asking for REQUESTED draws with: Auto is Sources when the analysis finds
  // concentrated sources and Off otherwise, or when the analysis fails (it makes the analysis);
  // the others stay.
  EnvironmentSampling resolveSampling(EnvironmentSampling requested);
  // Bakes now what a material drawing with REQUESTED needs (the analysis for Auto, the
  // distribution for Mis, the split for Sources): what a worker calls before the lighting is
  // shown, so the UI thread never bakes.
  void prepare(EnvironmentSampling requested);
  // True when prepare(REQUESTED) has nothing left to bake.
  bool prepared(EnvironmentSampling requested) const;

  // The sources split off (Sources): the residual's cubemap (the analysed image less its
  // excess, core/env/env_sources.h, with its mip chain: what the lobe samples read) and the
  // excess's source groups on the grid of the analysis (core/env/env_source_groups.h: the
  // strongest sources each a group, the rest together; within a group each texel's density
  // proportional to its excess luminance, uniform inside it, so the excess, read nearest, over
  // the density is constant across a source of one colour; each pixel chooses between the
  // groups by its lobe). What is drawn is the analysed image (the image itself for an
  // equirectangular environment at most EnvAnalysisOptions::maxWidth wide; an analytic one
  // sampled into texel means, which keep a small sun's power). Baked on first use.
  struct SourceSplit
  {
    std::shared_ptr<const EnvAnalysis> analysis;
    Cubemap residualCube;
    // The residual's irradiance SH9 (as irradianceCoefficients): the diffuse of a material whose
    // lights are the sources (LEADR with env-lights, core/lights/env_lights.h).
    std::array<glm::vec3, 9> residualIrradiance{};
    std::shared_ptr<const SourceGroups> groups;
    // The excess as an environment (bilinear, as the shader reads it): the radiance of the
    // points a frame's pixels share (sourcePoints).
    std::shared_ptr<const EquirectEnvironment> excess;
  };
  const SourceSplit& sourceSplit();
  // The points a frame's pixels share (core sourcePoints under pointSelection, COUNT of them
  // for FRAME), ordered by group, in world coordinates, packed as the shader's uniforms (a
  // point of density 0 as radiance 0 over density 1). Kept for the last frame, count and
  // rotation asked: the parts of a scene drawing one frame share one draw of them.
  struct SharedSourcePoints
  {
    std::uint32_t frame = 0;
    int count = 0;
    double rotationDegrees = 0.0;
    std::array<float, SourceGroups::kMaxGroups> selection{};
    std::array<int, 2 * SourceGroups::kMaxGroups> runs{}; // per group: first point, count
    std::array<float, 4 * kMaxSourcePoints> points{};     // world direction, count x pdf
    std::array<float, 3 * kMaxSourcePoints> radiance{};
  };
  const SharedSourcePoints& sharedSourcePoints(std::uint32_t frame, int count);
  // In WINDOW's context: the residual cube (as cubeTexture), the excess (RGB float,
  // equirectangular, nearest), the groups' tables (RGBA float, kSourceTableWidth wide, cell i at
  // (i mod width, i / width): the rows, then the entries, as SourceGroups lays them out, a row's
  // first entry given as its cell) and per texel of the grid its density within its group and
  // its group (RG float, -1 outside).
  static constexpr int kSourceTableWidth = 4096;
  vtkTextureObject* residualCubeTexture(vtkOpenGLRenderWindow* window);
  vtkTextureObject* sourceRadianceTexture(vtkOpenGLRenderWindow* window);
  vtkTextureObject* sourceTableTexture(vtkOpenGLRenderWindow* window);
  vtkTextureObject* sourceDensityTexture(vtkOpenGLRenderWindow* window);

  void releaseGraphicsResources(vtkWindow* window);

private:
  EnvironmentLighting() = default;

  std::shared_ptr<const Environment> environment_;
  Cubemap cubemap_;
  std::array<glm::vec3, 9> irradiance_{};
  double rotationDegrees_ = 0.0;
  uint64_t revision_ = 0;
  vtkSmartPointer<vtkTextureObject> texture_;
  vtkWeakPointer<vtkOpenGLRenderWindow> textureWindow_;
  std::shared_ptr<const EnvironmentDistribution> distribution_;
  vtkSmartPointer<vtkTextureObject> cdfTexture_;
  vtkSmartPointer<vtkTextureObject> pdfTexture_;
  vtkSmartPointer<vtkTextureObject> guideTexture_;
  vtkWeakPointer<vtkOpenGLRenderWindow> samplingWindow_;

  std::shared_ptr<const EnvAnalysis> analysis_;
  bool analysisFailed_ = false; // resolveSampling found no analysis: auto is off
  std::unique_ptr<SourceSplit> split_;
  std::unique_ptr<SharedSourcePoints> sharedPoints_;
  // residual cube, excess, entries, density and group
  std::array<vtkSmartPointer<vtkTextureObject>, 4> sourceTextures_;
  vtkWeakPointer<vtkOpenGLRenderWindow> sourceWindow_;

  void uploadSamplingTables(vtkOpenGLRenderWindow* window);
  void uploadSourceTextures(vtkOpenGLRenderWindow* window);
};
} // namespace aniso
