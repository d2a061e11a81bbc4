#pragma once
// What the materials of the LEADR and small-scale microstructure shading models
// (LeadrMaterial.h, MicrostructureMaterial.h) share, for any vtkActor drawn by a
// vtkOpenGLPolyDataMapper. Like the anisotropic material, they inject GLSL through shader
// replacements (ShaderHook.h) and set their values as uniforms each time the mapper draws. Both
// need the mesh's "Normals", "Tangents" and "TCoords" point arrays (the built-in meshes have
// them): apply() refuses a mesh without them, and a mesh that loses them later is drawn with
// VTK's own shading and a warning.
#include "core/lights/light.h"
#include "vtkpasses/render/OffscreenRenderer.h"

#include <memory>
#include <string>
#include <utility>
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

// Throws aniso::Error "light: reason" for an invalid light or more than kMaxShaderLights.
void validateShaderLights(const std::vector<Light>& lights);

// The actor, its mapper's shader replacements and attributes, the camera and frame uniforms and
// the lights. A model supplies its fragment code and its own uniforms.
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
  // Directional lights in environment coordinates (an environment's sources,
  // core/lights/env_lights.h, at rotation 0), drawn after the lights of setLights turned as the
  // lighting is turned at each draw (world = environment-to-world of lighting()); together at
  // most kMaxShaderLights (aniso::Error "light: ..." otherwise).
  void setEnvironmentLights(const std::vector<Light>& lights);
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

// A surface model's material and the settings it holds: MODEL (the material, derived from this)
// has a constructor (lighting, settings) and a static validate(settings) that throws
// aniso::Error "name: reason"; SETTINGS has the lights.
template <class Model, class Settings>
class SurfaceModelMaterial : public SurfaceShaderMaterial
{
public:
  // For RenderSettings::installMaterial: SETTINGS are validated now, so a bad setting fails
  // before any window opens; each install makes a material and applies it.
  static MaterialInstaller installer(const Settings& settings)
  {
    Model::validate(settings);
    return [settings](vtkActor* actor, vtkRenderer* renderer,
                      const std::shared_ptr<EnvironmentLighting>& lighting)
    {
      auto material = std::make_shared<Model>(lighting, settings);
      material->apply(actor, renderer);
      return std::shared_ptr<void>(material);
    };
  }

  const Settings& settings() const { return settings_; }

protected:
  // Invalid settings throw aniso::Error "name: reason".
  SurfaceModelMaterial(std::shared_ptr<EnvironmentLighting> lighting, std::string name,
                       Settings settings)
      : SurfaceShaderMaterial(std::move(lighting), std::move(name)), settings_(std::move(settings))
  {
    Model::validate(settings_);
    setLights(settings_.lights);
  }

private:
  Settings settings_;
};
} // namespace aniso
