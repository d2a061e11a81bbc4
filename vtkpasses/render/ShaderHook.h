#pragma once
// What a material that shades a vtkActor through shader replacements does the same way
// whatever it computes: it observes the actor's OpenGL mapper (for the mesh about to be drawn,
// and for every shader update, where uniforms and textures are set), inserts its GLSL after
// VTK's tags (keeping each tag, so VTK's code and later replacements still apply) and maps the
// mesh's point arrays to vertex attributes. Detaching removes all of it. Not a vtkObject.
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

class vtkActor;
class vtkMapper;
class vtkOpenGLRenderWindow;
class vtkPolyData;
class vtkRenderer;
class vtkShaderProgram;
class vtkTextureObject;

namespace aniso
{
// The tags the materials' code follows.
namespace tags
{
constexpr const char* kVertexDec = "//VTK::Normal::Dec";
constexpr const char* kVertexImpl = "//VTK::CustomEnd::Impl";
constexpr const char* kFragmentDec = "//VTK::Light::Dec";
constexpr const char* kFragmentUniformFlow = "//VTK::UniformFlow::Impl";
constexpr const char* kFragmentImpl = "//VTK::Light::Impl";
} // namespace tags

struct ShaderCode
{
  // (tag, code inserted after it), e.g. {tags::kFragmentImpl, "..."}.
  std::vector<std::pair<std::string, std::string>> vertex;
  std::vector<std::pair<std::string, std::string>> fragment;
  // Geometry shader: applies only where VTK draws with one (wide lines, lineGeometryCode).
  std::vector<std::pair<std::string, std::string>> geometry;
  // (vertex attribute, point array) pairs the code reads.
  std::vector<std::pair<std::string, std::string>> attributes;
  // A uniform the code uses: a program without it (another pass's) is not the code's, and the
  // shader callback is not called for it.
  std::string uniform;
  // The pixels the accumulation pass froze (vtkAnisoAccumulationPass::FROZEN_PIXELS on the
  // renderer's information) are discarded before the code's shading: the hook puts
  // shaders/frozen_pixels_dec.glsl before the code's kFragmentDec text and
  // shaders/frozen_pixels_impl.glsl before its kFragmentImpl text (the code must have both), and
  // binds the mask before each draw (a 1x1 texture that freezes nothing while there is none).
  bool discardFrozenPixels = false;
};

// Which of the point arrays the materials read ("Normals", "Tangents", "TCoords":
// MaterialShaderSource.h) a mesh has, with a tuple for each point.
struct MeshArrays
{
  bool normals = false;
  bool tangents = false;
  bool tcoords = false;
  bool lines = false; // a line set (vtkpasses/mesh/LineSet.h): polylines and no faces
  bool all() const { return normals && tangents && tcoords; }
};
MeshArrays meshArraysOf(vtkPolyData* poly);
// The vertex attributes PREFIX + "NormalMC", "TangentMC" and "TCoordMC" of the arrays USED
// names, for ShaderCode::attributes.
std::vector<std::pair<std::string, std::string>> meshAttributes(const std::string& prefix,
                                                                const MeshArrays& used);

// Illuminated lines: VTK 9.1 draws lines wider than the hardware's widest through its own
// geometry shader (vtkPolyDataWideLineGS), which expands each segment into a screen-facing quad
// of the actor's line width in pixels and passes only VTK's own varyings on. A line variant names
// its two varyings PREFIX + "TangentWCVSOut" (vec3) and PREFIX + "ClipPositionVSOut" (vec4)
// (VTK renames VSOut to GSOut in the fragment shader when a geometry shader runs); this code,
// inserted in that geometry shader, passes them on: the tangent of the segment's end, and the
// clip position of the quad's own corner (the fragment's point on the quad, for its view ray).
std::vector<std::pair<std::string, std::string>> lineGeometryCode(const std::string& prefix);

// What the compiler said of the shaders of the code last installed on ACTOR, when they did not
// compile with the driver and the actor is drawn with VTK's own shading instead ("its shader does
// not compile with this OpenGL driver (the log's first lines)"); empty otherwise. Kept on the actor
// (its property keys) by the hook, so that whoever draws it can tell without knowing its material.
std::string shaderCompileFailure(vtkActor* actor);

class ShaderHook
{
public:
  // Called with the mapper's input once it is known (at attach if it has points, and after
  // each draw), so the caller can install the variant the mesh needs.
  using MeshCallback = std::function<void(vtkPolyData*)>;
  // Called with the shader program and the window before each draw while code is installed
  // (and the program uses ShaderCode::uniform): set uniforms and bind textures here. Exceptions
  // are caught and reported as a VTK warning "SUBJECT: reason" (they must not unwind through
  // VTK); the draw goes on unshaded.
  using ShaderCallback = std::function<void(vtkShaderProgram*, vtkOpenGLRenderWindow*)>;

  explicit ShaderHook(std::string subject = "material");
  ~ShaderHook();
  ShaderHook(const ShaderHook&) = delete;
  ShaderHook& operator=(const ShaderHook&) = delete;

  // Hooks ACTOR drawn by RENDERER (detaching from any previous actor first). The actor's mapper
  // must be a vtkOpenGLPolyDataMapper; aniso::Error "material: reason" otherwise, and nothing
  // changes.
  void attach(vtkActor* actor, vtkRenderer* renderer, MeshCallback onMesh, ShaderCallback onShader);
  // The same with OWNER's onMesh(vtkPolyData*) and onShader(vtkShaderProgram*,
  // vtkOpenGLRenderWindow*) as the callbacks.
  template <class Owner>
  void attach(vtkActor* actor, vtkRenderer* renderer, Owner* owner)
  {
    attach(
        actor, renderer, [owner](vtkPolyData* poly) { owner->onMesh(poly); },
        [owner](vtkShaderProgram* program, vtkOpenGLRenderWindow* window)
        { owner->onShader(program, window); });
  }
  void detach();
  // Another mapper the attached actor may draw with (a stand-in's, swapped in on the actor while
  // the view moves): observed as the actor's own and given the installed code's attribute
  // mappings, so that swapping mappers on the actor rebuilds nothing (each mapper keeps its
  // buffers and shader programs). The actor's mapper at attach() is the first; detach() forgets
  // them all. Not an OpenGL polydata mapper, or nothing attached: aniso::Error.
  void addMapper(vtkMapper* mapper);

  // Activates TEXTURE for the coming draw and points SAMPLER at its unit (call from the shader
  // callback). The unit is freed once the actor has drawn (when the next hooked actor of the
  // window draws, or the renderer has drawn), as vtkOpenGLTexture::PostRender does for VTK's own
  // textures: a scene of many hooked actors never holds more units than one of them, and no
  // texture stays active between frames or after detaching.
  void bindTexture(vtkShaderProgram* program, const char* sampler, vtkTextureObject* texture);

  // The transforms of the attached actor and renderer as PREFIX + "ClipToWorld" (mat4: the
  // camera's clip coordinates to world), PREFIX + "DirectionToWorld" (mat3: the actor's
  // model-to-world) and PREFIX + "NormalToWorld" (mat3: its inverse transpose, or itself when
  // singular). Call from the shader callback.
  void setTransforms(vtkShaderProgram* program, const std::string& prefix) const;

  // Replaces the installed code (if any) by CODE on the attached actor.
  //
  // Code whose program does not compile: VTK 9.1 would crash on it (vtkAnisoPolyDataMapper.h).
  // With the actor drawn by vtkAnisoPolyDataMapper, the hook takes the code out in the draw that
  // compiled it, so that the actor is drawn with VTK's own shading, reports it once as a VTK
  // warning "SUBJECT: its shader does not compile ..." and keeps it as
  // shaderCompileFailure(actor); installing the same code again is refused (nothing is
  // installed, the failure stays on the actor), other code is installed as usual.
  void install(const ShaderCode& code);
  // True while code given to install() is on the attached actor (attaching anew and detaching
  // remove it).
  bool installed() const;

  // Tells the attached actor (and so progressive accumulation) that its shading changed: for
  // values that live outside VTK's objects, such as uniforms.
  void changed();

  vtkActor* actor() const;
  vtkRenderer* renderer() const;

private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};
} // namespace aniso
