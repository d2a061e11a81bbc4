#include "vtkpasses/render/ShaderHook.h"

#include "aniso_shaders.h"
#include "core/error.h"
#include "core/hash.h"
#include "vtkpasses/render/LineStyle.h"
#include "vtkpasses/render/MaterialShaderSource.h"
#include "vtkpasses/render/RendererMatrices.h"
#include "vtkpasses/render/TextureUpload.h"
#include "vtkpasses/render/vtkAnisoAccumulationPass.h"
#include "vtkpasses/render/vtkAnisoPolyDataMapper.h"

#include <algorithm>
#include <cmath>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <map>
#include <mutex>
#include <vtkActor.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkDataObject.h>
#include <vtkInformation.h>
#include <vtkInformationStringKey.h>
#include <vtkNew.h>
#include <vtkOpenGLPolyDataMapper.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>
#include <vtkShaderProgram.h>
#include <vtkShaderProperty.h>
#include <vtkSmartPointer.h>
#include <vtkTextureObject.h>
#include <vtkWeakPointer.h>

namespace aniso
{
namespace
{
bool hasPointArray(vtkPolyData* poly, const char* name, int components)
{
  vtkDataArray* array = poly->GetPointData()->GetArray(name);
  return array && array->GetNumberOfComponents() == components &&
         array->GetNumberOfTuples() == poly->GetNumberOfPoints();
}
} // namespace

MeshArrays meshArraysOf(vtkPolyData* poly)
{
  MeshArrays arrays;
  arrays.normals = hasPointArray(poly, kNormalsArray, 3);
  arrays.tangents = hasPointArray(poly, kTangentsArray, 3);
  arrays.tcoords = hasPointArray(poly, kTCoordsArray, 2);
  arrays.lines = poly->GetNumberOfLines() > 0 && poly->GetNumberOfPolys() == 0 &&
                 poly->GetNumberOfStrips() == 0;
  return arrays;
}

namespace
{
// Where an actor keeps what its shaders' compiler said (shaderCompileFailure).
vtkInformationStringKey* failureKey()
{
  static vtkInformationStringKey* key = vtkInformationStringKey::MakeKey("SHADER_FAILURE", "aniso");
  return key;
}

void setShaderCompileFailure(vtkActor* actor, const std::string& message)
{
  vtkInformation* keys = actor->GetPropertyKeys();
  if (!keys)
  {
    if (message.empty())
    {
      return;
    }
    vtkNew<vtkInformation> created;
    actor->SetPropertyKeys(created);
    keys = actor->GetPropertyKeys();
  }
  const char* now = keys->Has(failureKey()) ? keys->Get(failureKey()) : nullptr;
  if (message.empty() && now)
  {
    keys->Remove(failureKey());
  }
  else if (!message.empty() && (!now || message != now))
  {
    keys->Set(failureKey(), message.c_str());
  }
}

// The first lines of a compiler's LOG, where the first error is (the rest repeats it, or
// follows from it).
std::string firstLines(const std::string& log, int lines = 3)
{
  std::string text;
  int kept = 0;
  for (std::size_t start = 0; kept < lines && start < log.size();)
  {
    std::size_t end = log.find('\n', start);
    if (end == std::string::npos)
    {
      end = log.size();
    }
    const std::string line = log.substr(start, end - start);
    if (line.find_first_not_of(" \t\r") != std::string::npos)
    {
      text += (text.empty() ? "" : " ") + line;
      ++kept;
    }
    start = end + 1;
  }
  return text;
}

// The code's identity: every text it inserts, and where.
uint64_t fingerprint(const ShaderCode& code)
{
  uint64_t hash = kFnvOffsetBasis;
  const auto add = [&hash](const std::string& text)
  {
    hash = fnv1a(text.data(), text.size(), hash);
    hash = fnv1a("\0", 1, hash);
  };
  for (const auto* stage : {&code.vertex, &code.fragment, &code.geometry})
  {
    for (const auto& [tag, text] : *stage)
    {
      add(tag);
      add(text);
    }
    add("stage");
  }
  return hash;
}

// CODE as installed: with the frozen pixels' declarations before its fragment declarations and
// their discard before its shading, where it asks for them (ShaderCode::discardFrozenPixels).
ShaderCode withFrozenPixels(ShaderCode code)
{
  if (!code.discardFrozenPixels)
  {
    return code;
  }
  bool declared = false;
  bool discarded = false;
  for (auto& [tag, text] : code.fragment)
  {
    if (tag == tags::kFragmentDec)
    {
      text = shaders::kFrozenPixelsDec + text;
      declared = true;
    }
    else if (tag == tags::kFragmentImpl)
    {
      text = shaders::kFrozenPixelsImpl + text;
      discarded = true;
    }
  }
  if (!declared || !discarded)
  {
    throw errorAbout("material", "code that discards frozen pixels needs fragment declarations "
                                 "and a fragment implementation");
  }
  return code;
}
} // namespace

std::string shaderCompileFailure(vtkActor* actor)
{
  vtkInformation* keys = actor ? actor->GetPropertyKeys() : nullptr;
  const char* message = keys && keys->Has(failureKey()) ? keys->Get(failureKey()) : nullptr;
  return message ? message : std::string();
}

std::vector<std::pair<std::string, std::string>> lineGeometryCode(const std::string& p)
{
  const std::string declarations =
      "in vec3 " + p + "TangentWCVSOut[];\n" + "out vec3 " + p + "TangentWCGSOut;\n" + "in vec4 " +
      p + "ClipPositionVSOut[];\n" + "out vec4 " + p + "ClipPositionGSOut;\n" + "uniform vec2 " +
      p + "LineWorldWidthClip; // LineStyle.h; (0, 0): VTK's width in pixels\n";
  // Before VTK's loop: the width of each end in normalised device coordinates, VTK's own
  // (pixels) or the world width's projection there; VTK's code below reads it by its name.
  const std::string start = "vec2 " + p + "LineWidthNVC[2];\n" + "for (int k = 0; k < 2; ++k)\n" +
                            "{\n  " + p + "LineWidthNVC[k] = " + p +
                            "LineWorldWidthClip.x > 0.0 ? " + p +
                            "LineWorldWidthClip / gl_in[k].gl_Position.w : lineWidthNVC;\n}\n" +
                            "#define lineWidthNVC " + p + "LineWidthNVC[i]\n";
  // Inside VTK's loop over the quad's corners j (of the segment's end i), where `normal` is the
  // segment's screen-space normal: the corner as VTK places it.
  const std::string implementation =
      p + "TangentWCGSOut = " + p + "TangentWCVSOut[i];\n" + p +
      "ClipPositionGSOut = vec4(gl_in[i].gl_Position.xy + (lineWidthNVC * normal) * "
      "(float((j + 1) % 2) - 0.5) * gl_in[i].gl_Position.w, gl_in[i].gl_Position.zw);\n";
  return {{"//VTK::Normal::Dec", declarations},
          {"//VTK::Normal::Start", start},
          {"//VTK::Normal::Impl", implementation}};
}

std::vector<std::pair<std::string, std::string>> meshAttributes(const std::string& prefix,
                                                                const MeshArrays& used)
{
  std::vector<std::pair<std::string, std::string>> attributes;
  if (used.normals)
  {
    attributes.emplace_back(prefix + "NormalMC", kNormalsArray);
  }
  if (used.tangents)
  {
    attributes.emplace_back(prefix + "TangentMC", kTangentsArray);
  }
  if (used.tcoords)
  {
    attributes.emplace_back(prefix + "TCoordMC", kTCoordsArray);
  }
  return attributes;
}

class ShaderHook::Impl
{
public:
  std::string subject;
  vtkWeakPointer<vtkActor> actor;
  vtkWeakPointer<vtkRenderer> renderer;
  MeshCallback onMesh;
  ShaderCallback onShader;
  unsigned long rendererEndTag = 0;
  // The mappers the actor may draw with, observed: the actor's at attach first, then those of
  // addMapper.
  struct Observed
  {
    vtkWeakPointer<vtkOpenGLPolyDataMapper> mapper;
    unsigned long updateShaderTag = 0;
    unsigned long mapperEndTag = 0;
    unsigned long compileFailedTag = 0;
  };
  std::vector<Observed> observed;
  bool installed = false;
  ShaderCode code; // what is installed
  // Code whose program did not compile here, by fingerprint, with what was reported: installing
  // it again is refused (its program would fail again, at every draw).
  std::map<uint64_t, std::string> refused;
  std::vector<vtkWeakPointer<vtkTextureObject>> active; // activated for the current draw
  // Bound as the frozen pixels' mask while the renderer carries none (freezes nothing: the
  // shader reads it only inside anisoFrozenSize, (0, 0) then), and the window it lives in.
  vtkSmartPointer<vtkTextureObject> notFrozen;
  vtkWeakPointer<vtkOpenGLRenderWindow> notFrozenWindow;

  // The hook that drew last in each window and may hold texture units there. A window has few
  // units (Mesa's llvmpipe: 32 per stage), so a scene of many actors, each with its own lookup
  // table, would run out of them before the renderer's end frees them: the next hook to draw in
  // a window frees the units of the one before (whose draw is issued, so they are free again).
  static std::mutex& turnMutex()
  {
    static std::mutex mutex;
    return mutex;
  }
  static std::map<const vtkOpenGLRenderWindow*, Impl*>& lastDrawn()
  {
    static std::map<const vtkOpenGLRenderWindow*, Impl*> hooks;
    return hooks;
  }

  void deactivateTextures()
  {
    for (vtkTextureObject* texture : active)
    {
      if (texture)
      {
        texture->Deactivate();
      }
    }
    active.clear();
  }

  // Before this hook's draw in WINDOW: the units of the hook that drew there before are freed.
  void takeTurn(const vtkOpenGLRenderWindow* window)
  {
    std::lock_guard<std::mutex> lock(turnMutex());
    Impl*& last = lastDrawn()[window];
    if (last != this)
    {
      if (last)
      {
        last->deactivateTextures();
      }
      last = this;
    }
  }

  void deactivate()
  {
    deactivateTextures();
    std::lock_guard<std::mutex> lock(turnMutex());
    auto& hooks = lastDrawn();
    for (auto it = hooks.begin(); it != hooks.end();)
    {
      it = it->second == this ? hooks.erase(it) : std::next(it);
    }
  }

  void onRendererEnd(vtkObject*, unsigned long, void*) { deactivate(); }

  void uninstall()
  {
    // Nothing installed, nothing to take out: the actor is not touched (a material that asks
    // for refused code at every draw must not make every draw a change).
    if (actor && installed)
    {
      vtkShaderProperty* sp = actor->GetShaderProperty();
      for (const auto& [tag, text] : code.vertex)
      {
        sp->ClearVertexShaderReplacement(tag, true);
      }
      for (const auto& [tag, text] : code.fragment)
      {
        sp->ClearFragmentShaderReplacement(tag, true);
      }
      for (const auto& [tag, text] : code.geometry)
      {
        sp->ClearGeometryShaderReplacement(tag, true);
      }
      actor->Modified();
    }
    for (vtkOpenGLPolyDataMapper* m : allMappers())
    {
      for (const auto& [attribute, array] : code.attributes)
      {
        m->RemoveVertexAttributeMapping(attribute.c_str());
      }
    }
    code = ShaderCode{};
    installed = false;
  }

  // The observed mappers that still exist.
  std::vector<vtkOpenGLPolyDataMapper*> allMappers() const
  {
    std::vector<vtkOpenGLPolyDataMapper*> all;
    for (const Observed& o : observed)
    {
      if (o.mapper)
      {
        all.push_back(o.mapper);
      }
    }
    return all;
  }

  // Observes MAPPER (draws and shader updates) and gives it the installed attribute mappings.
  void observe(vtkOpenGLPolyDataMapper* mapper)
  {
    Observed o;
    o.mapper = mapper;
    o.updateShaderTag = mapper->AddObserver(vtkCommand::UpdateShaderEvent, this, &Impl::onUpdateShader);
    o.mapperEndTag = mapper->AddObserver(vtkCommand::EndEvent, this, &Impl::onMapperEnd);
    o.compileFailedTag = mapper->AddObserver(vtkAnisoPolyDataMapper::ShaderCompileFailedEvent, this,
                                             &Impl::onCompileFailed);
    observed.push_back(o);
    if (installed)
    {
      mapAttributes(mapper);
    }
  }

  void mapAttributes(vtkOpenGLPolyDataMapper* mapper) const
  {
    for (const auto& [attribute, array] : code.attributes)
    {
      mapper->MapDataArrayToVertexAttribute(attribute.c_str(), array.c_str(),
                                            vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
    }
  }

  void onMapperEnd(vtkObject* caller, unsigned long, void*)
  {
    // The mapper that drew (at attach, called without one: the actor's own).
    auto* drew = vtkOpenGLPolyDataMapper::SafeDownCast(caller);
    vtkOpenGLPolyDataMapper* from =
        drew ? drew : (observed.empty() ? nullptr : observed.front().mapper.GetPointer());
    vtkPolyData* poly = from ? from->GetInput() : nullptr;
    if (poly && onMesh)
    {
      onMesh(poly);
    }
  }

  // The program with the installed code did not compile (vtkAnisoPolyDataMapper): the code is
  // taken out, so that the mapper builds VTK's own shaders in this same draw, and refused from
  // now on; the actor keeps the message and it is reported as a VTK warning.
  void onCompileFailed(vtkObject*, unsigned long, void* data)
  {
    if (!installed || !actor)
    {
      return;
    }
    const std::string log = data ? static_cast<const char*>(data) : "";
    const std::string message =
        "its shader does not compile with this OpenGL driver (" + firstLines(log) + ")";
    refused[fingerprint(code)] = message;
    uninstall();
    setShaderCompileFailure(actor, message);
    vtkGenericWarningMacro(<< subject << ": " << message << "; drawn with VTK's own shading");
  }

  void bind(vtkShaderProgram* program, const char* sampler, vtkTextureObject* texture)
  {
    texture->Activate();
    program->SetUniformi(sampler, texture->GetTextureUnit());
    if (std::find(active.begin(), active.end(), texture) == active.end())
    {
      active.emplace_back(texture);
    }
  }

  // The mask of the pixels the accumulation pass froze, from the renderer's information, or the
  // texture that freezes nothing.
  void bindFrozenPixels(vtkShaderProgram* program, vtkOpenGLRenderWindow* window)
  {
    vtkInformation* info = renderer->GetInformation();
    auto* frozen =
        info && info->Has(vtkAnisoAccumulationPass::FROZEN_PIXELS())
            ? vtkTextureObject::SafeDownCast(info->Get(vtkAnisoAccumulationPass::FROZEN_PIXELS()))
            : nullptr;
    vtkTextureObject* mask = frozen;
    if (!mask)
    {
      // A texture of handle 0 was released with the window's context: upload it again.
      if (!notFrozen || notFrozenWindow != window || notFrozen->GetHandle() == 0)
      {
        const float none = 0.0f;
        notFrozen = uploadFloatTexture(window, 1, 1, 1, &none, TextureFiltering::Nearest,
                                       TextureWrap::Clamp, "frozen pixels");
        notFrozenWindow = window;
      }
      mask = notFrozen;
    }
    bind(program, "anisoFrozen", mask);
    const int size[2] = {frozen ? int(frozen->GetWidth()) : 0,
                         frozen ? int(frozen->GetHeight()) : 0};
    program->SetUniform2i("anisoFrozenSize", size);
  }

  void onUpdateShader(vtkObject*, unsigned long, void* data)
  {
    auto* program = static_cast<vtkShaderProgram*>(data);
    if (!program || !installed || !actor || !renderer || !onShader ||
        (!code.uniform.empty() && !program->IsUniformUsed(code.uniform.c_str())))
    {
      return;
    }
    auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
    if (!window)
    {
      return;
    }
    takeTurn(window);
    try
    {
      if (code.discardFrozenPixels)
      {
        bindFrozenPixels(program, window);
      }
      onShader(program, window);
    }
    catch (const std::exception& e)
    {
      vtkGenericWarningMacro(<< subject << ": " << e.what());
    }
  }
};

ShaderHook::ShaderHook(std::string subject) : impl_(std::make_unique<Impl>())
{
  impl_->subject = std::move(subject);
}

ShaderHook::~ShaderHook()
{
  detach();
}

void ShaderHook::attach(vtkActor* actor, vtkRenderer* renderer, MeshCallback onMesh,
                        ShaderCallback onShader)
{
  if (!actor || !renderer)
  {
    throw errorAbout("material", "needs an actor and a renderer");
  }
  auto* mapper = vtkOpenGLPolyDataMapper::SafeDownCast(actor->GetMapper());
  if (!mapper)
  {
    throw errorAbout("material", "the actor's mapper is not an OpenGL polydata mapper");
  }
  detach();
  Impl& d = *impl_;
  d.actor = actor;
  d.renderer = renderer;
  d.onMesh = std::move(onMesh);
  d.onShader = std::move(onShader);
  d.observe(mapper);
  d.rendererEndTag = renderer->AddObserver(vtkCommand::EndEvent, &d, &Impl::onRendererEnd);
  // If the mesh is already there, the variant is known now; otherwise the first draw tells.
  if (vtkPolyData* poly = mapper->GetInput())
  {
    if (poly->GetNumberOfPoints() > 0)
    {
      d.onMapperEnd(nullptr, 0, nullptr);
    }
  }
  actor->Modified();
}

void ShaderHook::detach()
{
  Impl& d = *impl_;
  d.uninstall();
  d.deactivate();
  if (d.renderer)
  {
    d.renderer->RemoveObserver(d.rendererEndTag);
  }
  for (const Impl::Observed& o : d.observed)
  {
    if (o.mapper)
    {
      o.mapper->RemoveObserver(o.updateShaderTag);
      o.mapper->RemoveObserver(o.mapperEndTag);
      o.mapper->RemoveObserver(o.compileFailedTag);
    }
  }
  d.observed.clear();
  d.actor = nullptr;
  d.renderer = nullptr;
  d.onMesh = nullptr;
  d.onShader = nullptr;
}

void ShaderHook::addMapper(vtkMapper* added)
{
  Impl& d = *impl_;
  auto* mapper = vtkOpenGLPolyDataMapper::SafeDownCast(added);
  if (!mapper || !d.actor)
  {
    throw errorAbout(d.subject, mapper ? "a further mapper needs an attached actor"
                                       : "a further mapper is not an OpenGL polydata mapper");
  }
  const std::vector<vtkOpenGLPolyDataMapper*> all = d.allMappers();
  if (std::find(all.begin(), all.end(), mapper) == all.end())
  {
    d.observe(mapper);
  }
}

void ShaderHook::bindTexture(vtkShaderProgram* program, const char* sampler,
                             vtkTextureObject* texture)
{
  impl_->bind(program, sampler, texture);
}

void ShaderHook::setTransforms(vtkShaderProgram* program, const std::string& prefix) const
{
  setUniformMatrix(program, (prefix + "ClipToWorld").c_str(), clipToWorld(impl_->renderer));
  const glm::dmat3 toWorld(toGlm(impl_->actor->GetMatrix()));
  const double det = glm::determinant(toWorld);
  const glm::dmat3 normalToWorld =
      det != 0.0 && std::isfinite(det) ? glm::transpose(glm::inverse(toWorld)) : toWorld;
  setUniformMatrix(program, (prefix + "DirectionToWorld").c_str(), toWorld);
  setUniformMatrix(program, (prefix + "NormalToWorld").c_str(), normalToWorld);
  const std::string lineWidth = prefix + "LineWorldWidthClip";
  if (program->IsUniformUsed(lineWidth.c_str()))
  {
    float clip[2];
    lineWorldWidthClip(impl_->actor, impl_->renderer, clip);
    program->SetUniform2f(lineWidth.c_str(), clip);
  }
}

void ShaderHook::install(const ShaderCode& given)
{
  Impl& d = *impl_;
  if (!d.actor || d.allMappers().empty())
  {
    return;
  }
  const ShaderCode code = withFrozenPixels(given);
  d.uninstall();
  const auto refused = d.refused.find(fingerprint(code));
  if (refused != d.refused.end())
  {
    // Drawn with VTK's own shading, as when it failed; nothing to report again.
    setShaderCompileFailure(d.actor, refused->second);
    return;
  }
  setShaderCompileFailure(d.actor, std::string());
  vtkShaderProperty* sp = d.actor->GetShaderProperty();
  for (const auto& [tag, text] : code.vertex)
  {
    sp->AddVertexShaderReplacement(tag, true, tag + "\n" + text, false);
  }
  for (const auto& [tag, text] : code.fragment)
  {
    sp->AddFragmentShaderReplacement(tag, true, tag + "\n" + text, false);
  }
  for (const auto& [tag, text] : code.geometry)
  {
    sp->AddGeometryShaderReplacement(tag, true, tag + "\n" + text, false);
  }
  d.code = code;
  for (vtkOpenGLPolyDataMapper* m : d.allMappers())
  {
    d.mapAttributes(m);
  }
  d.installed = true;
  d.actor->Modified();
}

void ShaderHook::changed()
{
  if (impl_->actor)
  {
    impl_->actor->Modified();
  }
}

bool ShaderHook::installed() const
{
  return impl_->installed;
}

vtkActor* ShaderHook::actor() const
{
  return impl_->actor;
}

vtkRenderer* ShaderHook::renderer() const
{
  return impl_->renderer;
}
} // namespace aniso
