#pragma once
// An anisotropic (Ashikhmin-Shirley) material under image-based lighting, given to any
// vtkActor whose mapper is a vtkOpenGLPolyDataMapper. It injects its GLSL through shader
// replacements (VTK's tags are kept, the shaders are never replaced whole), binds its lookup
// tables, maps and the environment cubemap as named textures, and sets the values sliders move
// as uniforms when the mapper draws, so moving them never recompiles. Features the material
// does not use are compiled out. The mesh's point arrays "Normals", "Tangents" and "TCoords"
// are used when present (see MaterialShaderSource.h).
#include "vtkpasses/render/MaterialSettings.h"
#include "vtkpasses/render/MaterialShaderSource.h"

#include <memory>

class vtkActor;
class vtkMapper;
class vtkRenderer;

namespace aniso
{
class EnvironmentLighting;
struct BrdfLut;
struct HalfVectorLut;

class AnisoMaterial
{
public:
  // Invalid settings throw aniso::Error "name: reason".
  explicit AnisoMaterial(std::shared_ptr<EnvironmentLighting> lighting,
                         const MaterialSettings& settings = {});
  ~AnisoMaterial();
  AnisoMaterial(const AnisoMaterial&) = delete;
  AnisoMaterial& operator=(const AnisoMaterial&) = delete;

  // Gives the material to ACTOR, drawn by RENDERER (whose camera and window the shaders use).
  // The actor's mapper must be set and be an OpenGL polydata mapper; aniso::Error otherwise.
  // A material serves one actor: applying it again moves it.
  void apply(vtkActor* actor, vtkRenderer* renderer);
  // Another mapper the actor may draw with, swapped in on it (its stand-in's while the view
  // moves): the material shades what it draws as well, and swapping rebuilds nothing
  // (ShaderHook::addMapper). After apply(); applying again or detaching forgets it.
  void addMapper(vtkMapper* mapper);
  // Takes the material off its actor (the actor draws with VTK's own shading again).
  void detach();

  // New values: uniforms and lookup tables are updated (LUTs from the shared LutCache), the
  // shader is rebuilt only if the variant changed. Throws aniso::Error "name: reason" for an
  // invalid value and keeps the previous settings.
  void setSettings(const MaterialSettings& settings);
  // The same with lookup tables already at hand (baked or read on a worker): a table whose
  // inputs match the settings is used as it is, as is one the material holds already, so the
  // cache is asked (and may read a file or bake) only for tables neither provides.
  void setSettings(const MaterialSettings& settings,
                   std::shared_ptr<const HalfVectorLut> halfVector,
                   std::shared_ptr<const BrdfLut> brdf);
  const MaterialSettings& settings() const;

  void setLighting(std::shared_ptr<EnvironmentLighting> lighting);
  const std::shared_ptr<EnvironmentLighting>& lighting() const;

  // The variant compiled for the actor's mesh (known once the actor has been drawn).
  MaterialVariant variant() const;
  // True when maps were asked for but the mesh has no texture coordinates to read them with.
  bool mapsDropped() const;

  // What the material has done to the GPU so far: shader variants installed (each compiles once
  // drawn) and textures uploaded (lookup tables and maps; a texture another material made of the
  // same data in the same window is shared, not uploaded again: parts of one lobe share their
  // tables' textures). Settings equal to the current ones
  // change nothing (not even the accumulation: the image stays converged).
  struct Counters
  {
    int shaderInstalls = 0;
    int textureUploads = 0;
  };
  const Counters& counters() const;

  // Throws aniso::Error "name: reason" unless SETTINGS can be rendered.
  static void validate(const MaterialSettings& settings);

private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};
} // namespace aniso
