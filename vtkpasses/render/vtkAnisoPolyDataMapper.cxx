#include "vtkpasses/render/vtkAnisoPolyDataMapper.h"

#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLShaderCache.h>
#include <vtkRenderer.h>
#include <vtkShader.h>

vtkStandardNewMacro(vtkAnisoPolyDataMapper);

namespace
{
using ShaderMap = std::map<vtkShader::Type, vtkShader*>;

// What the compiler said of the stages of a program that did not compile or link. The cache's
// program holds SHADERS (it keeps the shader objects it is given) and compiled them in turn up to
// the first that failed, which keeps the compiler's log.
std::string compileLog(const ShaderMap& shaders)
{
  std::string log;
  const std::pair<vtkShader::Type, const char*> stages[] = {{vtkShader::Vertex, "vertex"},
                                                            {vtkShader::Geometry, "geometry"},
                                                            {vtkShader::Fragment, "fragment"}};
  for (const auto& [type, name] : stages)
  {
    const auto it = shaders.find(type);
    if (it != shaders.end() && it->second && !it->second->GetError().empty())
    {
      log += std::string(log.empty() ? "" : "\n") + name + " shader: " + it->second->GetError();
    }
  }
  return log.empty() ? std::string("its stages compile, the program does not link") : log;
}

// Compiles and links the program of SHADERS through CACHE (which keeps it for VTK's own request
// of the same sources); the log when it fails, nothing when it compiles.
bool compiles(vtkOpenGLShaderCache* cache, const ShaderMap& shaders, std::string* log)
{
  // The cache writes its system-wide replacements into the shaders it is given: copies, so that
  // VTK's own request starts from the same text and finds this program by it.
  ShaderMap copies;
  vtkNew<vtkShader> vertex, fragment, geometry;
  const std::pair<vtkShader::Type, vtkShader*> stages[] = {{vtkShader::Vertex, vertex},
                                                           {vtkShader::Fragment, fragment},
                                                           {vtkShader::Geometry, geometry}};
  for (const auto& [type, copy] : stages)
  {
    copy->SetType(type);
    const auto it = shaders.find(type);
    copy->SetSource(it != shaders.end() && it->second ? it->second->GetSource() : std::string());
    copies[type] = copy;
  }
  if (cache->ReadyShaderProgram(copies))
  {
    return true;
  }
  *log = compileLog(copies);
  return false;
}
} // namespace

void vtkAnisoPolyDataMapper::BuildShaders(std::map<vtkShader::Type, vtkShader*> shaders,
                                          vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::BuildShaders(shaders, ren, act);
  auto* window = ren ? vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow()) : nullptr;
  vtkOpenGLShaderCache* cache = window ? window->GetShaderCache() : nullptr;
  std::string log;
  if (!cache || compiles(cache, shaders, &log))
  {
    return;
  }
  ++this->ShaderCompileFailures;
  this->InvokeEvent(ShaderCompileFailedEvent, const_cast<char*>(log.c_str()));
  // The observers took their code out: the shaders again, from VTK's templates.
  this->Superclass::BuildShaders(shaders, ren, act);
}
