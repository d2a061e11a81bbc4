#pragma once
// The material of the LEADR shading model (core/leadr/leadr.h) for any vtkActor drawn by a
// vtkOpenGLPolyDataMapper: the moments chain, base roughness and colours as uniforms and
// textures, over what every surface model shares (SurfaceShaderMaterial.h: the mesh needs
// "Normals", "Tangents" and "TCoords").
#include "core/leadr/leadr.h"
#include "core/lights/light.h"
#include "vtkpasses/render/SurfaceShaderMaterial.h"

#include <glm/vec2.hpp>
#include <memory>
#include <string>
#include <vector>

class vtkOpenGLRenderWindow;
class vtkShaderProgram;

namespace aniso
{
class EnvironmentLighting;

struct LeadrSettings
{
  std::shared_ptr<const LeadrMips> moments; // required
  LeadrMaterial surface;                    // diffuse, F0 and base roughness
  double tiles = 1.0;                       // repeats of the moments map per texture unit
  int gridN = 4;                            // slope grid n (n^2 samples), in [1, 16]
  bool environment = true;                  // specular and diffuse from the environment
  // The baseline LEADR improves on: only the filtered mean slope is used (what a mip-mapped
  // normal map gives), so the spread of the fine normals is lost.
  bool plainNormals = false;
  std::vector<Light> lights;
  // The environment's sources (core/lights/env_lights.h) as lights too, up to kMaxShaderLights
  // with `lights`, when the lighting has them baked: its analysis, and with `environment` its
  // sources' split, whose residual cube and residual SH9 the material then reads in place of the
  // whole environment's, so a source is counted once (as a light), not also in the cube. Without
  // the split (env-sampling off or mis, or auto on an environment that is not concentrated) the
  // whole cube is read and no source is added.
  bool environmentLights = false;
};

// installer(settings) gives RenderSettings::installMaterial (SurfaceModelMaterial).
class LeadrShadingMaterial : public SurfaceModelMaterial<LeadrShadingMaterial, LeadrSettings>
{
public:
  // Invalid settings throw aniso::Error "name: reason".
  LeadrShadingMaterial(std::shared_ptr<EnvironmentLighting> lighting, LeadrSettings settings);
  ~LeadrShadingMaterial() override;

  static void validate(const LeadrSettings& settings);

  // The environment's sources drawn as lights (environment coordinates), and whether the
  // residual is read: what environmentLights found in the lighting when the material was made.
  const std::vector<Light>& environmentLights() const { return environmentLights_; }
  bool readsResidual() const { return readsResidual_; }

protected:
  std::string fragmentDeclarations() const override;
  std::string fragmentImplementation() const override;
  void setModelUniforms(vtkShaderProgram* program, vtkOpenGLRenderWindow* window) override;

private:
  class Textures;
  std::unique_ptr<Textures> textures_;
  std::vector<Light> environmentLights_;
  bool readsResidual_ = false;
};

// The mip level LEADR reads for a pixel whose texture coordinates change by dx and dy to the
// next pixel (the GL rule: log2 of the longer footprint axis in texels), clamped to the chain.
double leadrLevelOfFootprint(const LeadrMips& mips, double tiles, const glm::dvec2& dx,
                             const glm::dvec2& dy);
} // namespace aniso
