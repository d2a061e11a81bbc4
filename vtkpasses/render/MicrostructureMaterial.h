#pragma once
// The small-scale microstructure material (core/microstructure/microstructure.h) for a vtkActor:
// K x K samples of the structure inside each pixel's footprint, with normal, parallax or
// parallax occlusion masking, optional self-shadowing and GGX or Blinn-Phong per sample, under
// point and directional lights. The structure's height, normal and albedo are uploaded as
// bilinear, repeating float textures (the core's lookups). Needs "Normals", "Tangents" and
// "TCoords" on the mesh (SurfaceShaderMaterial.h).
#include "core/image/image.h"
#include "core/lights/light.h"
#include "core/microstructure/microstructure.h"
#include "vtkpasses/render/SurfaceShaderMaterial.h"

#include <cstdint>
#include <glm/vec2.hpp>
#include <memory>
#include <string>
#include <vector>

class vtkOpenGLRenderWindow;
class vtkShaderProgram;

namespace aniso
{
struct MicrostructureSettings
{
  std::shared_ptr<const Microstructure> structure; // required
  MicroShadingOptions options;                     // samplesPerAxis, masking, BRDF, ...
  double tiles = 32.0;                             // structure tiles per unit of texture
  std::vector<Light> lights;
  // Optional tangent-plane rotation map (2+ channels, core/maps/tpr_map.h): the structure turns
  // per pixel so its grooves follow the map's direction (turnMicroPixel); circular: a brushed disk.
  std::shared_ptr<const Image> tprMap;
};

// The jitter seed of a frame from its sample shift (vtkAnisoAccumulationPass::FRAME_SHIFT),
// and the seed of pixel (x, y), y counted from the bottom row as GL does: the shader jitters
// pixel (x, y) with MicroShadingOptions::seed = microPixelSeed(x, y, frame seed).
std::uint32_t microFrameSeed(const glm::dvec2& frameShift);
std::uint32_t microPixelSeed(int x, int yFromBottom, std::uint32_t frameSeed);

// installer(settings) gives RenderSettings::installMaterial (SurfaceModelMaterial).
class MicrostructureShadingMaterial
    : public SurfaceModelMaterial<MicrostructureShadingMaterial, MicrostructureSettings>
{
public:
  // Invalid settings throw aniso::Error "name: reason".
  MicrostructureShadingMaterial(std::shared_ptr<EnvironmentLighting> lighting,
                                MicrostructureSettings settings);
  ~MicrostructureShadingMaterial() override;

  static void validate(const MicrostructureSettings& settings);

protected:
  std::string fragmentDeclarations() const override;
  std::string fragmentImplementation() const override;
  void setModelUniforms(vtkShaderProgram* program, vtkOpenGLRenderWindow* window) override;

private:
  class Textures;
  std::unique_ptr<Textures> textures_;
};
} // namespace aniso
