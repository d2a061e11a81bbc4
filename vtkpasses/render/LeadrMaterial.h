#pragma once
// Materials of the LEADR and small-scale microstructure shading models (core/leadr/leadr.h,
// core/microstructure/microstructure.h) for any vtkActor drawn by a vtkOpenGLPolyDataMapper.
// Like the anisotropic material, they inject GLSL through shader replacements and set their
// values as uniforms each time the mapper draws. Both need the mesh's "Normals", "Tangents" and
// "TCoords" point arrays (the built-in meshes have them): apply() refuses a mesh without them,
// and a mesh that loses them later is drawn with VTK's own shading and a warning.
#include "core/leadr/leadr.h"
#include "core/lights/light.h"
#include "vtkpasses/render/OffscreenRenderer.h"

#include <memory>
#include <string>
#include <vector>

class vtkActor;
class vtkOpenGLRenderWindow;
class vtkRenderer;
class vtkShaderProgram;
class vtkTextureObject;

namespace aniso
{
class EnvironmentLighting;

// Lights a shader can take at once.
constexpr int kMaxShaderLights = 8;

// What the LEADR and microstructure materials share: the actor, its mapper's shader
// replacements and attributes, the camera and frame uniforms and the lights. A model supplies
// its fragment code and its own uniforms.
class SurfaceShaderMaterial
{
public:
  virtual ~SurfaceShaderMaterial();
  SurfaceShaderMaterial(const SurfaceShaderMaterial&) = delete;
  SurfaceShaderMaterial& operator=(const SurfaceShaderMaterial&) = delete;

  // Gives the material to ACTOR, drawn by RENDERER. aniso::Error "material: reason" when the
  // actor has no OpenGL polydata mapper, "mesh: reason" when its input lacks the arrays.
  void apply(vtkActor* actor, vtkRenderer* renderer);
  void detach();

protected:
  SurfaceShaderMaterial(std::shared_ptr<EnvironmentLighting> lighting, std::string name);
  // Fragment declarations and the block that writes gl_FragData[0] (the frame code, which
  // defines viewWC, t, b, n, tbn and the tangent-space view v, replaces the line //LEADR_FRAME).
  virtual std::string fragmentDeclarations() const = 0;
  virtual std::string fragmentImplementation() const = 0;
  virtual void setModelUniforms(vtkShaderProgram* program, vtkOpenGLRenderWindow* window) = 0;
  void setLights(const std::vector<Light>& lights);
  EnvironmentLighting& lighting() const { return *lighting_; }
  vtkRenderer* renderer() const;
  // Activates TEXTURE for the coming draw only (ShaderHook::bindTexture).
  void bindTexture(vtkShaderProgram* program, const char* sampler, vtkTextureObject* texture);
  void changed(); // tells the actor (and progressive accumulation) that the shading changed

private:
  class Impl;
  std::unique_ptr<Impl> impl_;
  std::shared_ptr<EnvironmentLighting> lighting_;
};

// Throws aniso::Error "light: reason" for an invalid light or more than kMaxShaderLights.
void validateShaderLights(const std::vector<Light>& lights);

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

class LeadrShadingMaterial : public SurfaceShaderMaterial
{
public:
  // Invalid settings throw aniso::Error "name: reason".
  LeadrShadingMaterial(std::shared_ptr<EnvironmentLighting> lighting, LeadrSettings settings);
  ~LeadrShadingMaterial() override;

  static void validate(const LeadrSettings& settings);
  // For RenderSettings::installMaterial.
  static MaterialInstaller installer(const LeadrSettings& settings);

protected:
  std::string fragmentDeclarations() const override;
  std::string fragmentImplementation() const override;
  void setModelUniforms(vtkShaderProgram* program, vtkOpenGLRenderWindow* window) override;

private:
  class Textures;
  LeadrSettings settings_;
  std::unique_ptr<Textures> textures_;
};

// The mip level LEADR reads for a pixel whose texture coordinates change by dx and dy to the
// next pixel (the GL rule: log2 of the longer footprint axis in texels), clamped to the chain.
double leadrLevelOfFootprint(const LeadrMips& mips, double tiles, const glm::dvec2& dx,
                             const glm::dvec2& dy);
} // namespace aniso
