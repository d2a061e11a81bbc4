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
};

// installer(settings) gives RenderSettings::installMaterial (SurfaceModelMaterial).
class LeadrShadingMaterial : public SurfaceModelMaterial<LeadrShadingMaterial, LeadrSettings>
{
public:
  // Invalid settings throw aniso::Error "name: reason".
  LeadrShadingMaterial(std::shared_ptr<EnvironmentLighting> lighting, LeadrSettings settings);
  ~LeadrShadingMaterial() override;

  static void validate(const LeadrSettings& settings);

protected:
  std::string fragmentDeclarations() const override;
  std::string fragmentImplementation() const override;
  void setModelUniforms(vtkShaderProgram* program, vtkOpenGLRenderWindow* window) override;

private:
  class Textures;
  std::unique_ptr<Textures> textures_;
};

// The mip level LEADR reads for a pixel whose texture coordinates change by dx and dy to the
// next pixel (the GL rule: log2 of the longer footprint axis in texels), clamped to the chain.
double leadrLevelOfFootprint(const LeadrMips& mips, double tiles, const glm::dvec2& dx,
                             const glm::dvec2& dy);
} // namespace aniso
