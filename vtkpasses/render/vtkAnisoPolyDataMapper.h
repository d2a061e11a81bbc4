#pragma once
// VTK's OpenGL polydata mapper, with a shader program that does not compile reported instead of
// taking the process down.
//
// VTK 9.1 (and ParaView 5.11's VTK) compiles the program a mapper's BuildShaders produced in
// UpdateShaders, and when the mapper's first program fails to compile it dereferences the null
// program it got back (vtkOpenGLPolyDataMapper::UpdateShaders: `cellBO.Program->GetMTime()`):
// a driver that rejects GLSL another accepts (another vendor, an older context) ends the
// application with SIGSEGV. This mapper compiles each program BuildShaders produced through the
// window's shader cache first, where VTK finds it afterwards (the cache keys programs by their
// source: nothing is compiled twice). When it does not compile, the mapper invokes
// ShaderCompileFailedEvent with the compiler's log (a `const char*`), so that whoever put code
// into the shaders takes it out (ShaderHook does), and builds the shaders again: VTK then draws
// with what is left, its own shading. A program that still does not compile after that (VTK's
// own shaders on a context that cannot run them) goes to VTK as it is.
#include <map>
#include <string>
#include <vtkCommand.h>
#include <vtkOpenGLPolyDataMapper.h>

class vtkShader;
class vtkRenderer;
class vtkActor;

class vtkAnisoPolyDataMapper : public vtkOpenGLPolyDataMapper
{
public:
  static vtkAnisoPolyDataMapper* New();

  // Invoked with the compiler's log (const char*, the stage that failed named in it) when the
  // program BuildShaders produced does not compile or link.
  static constexpr unsigned long ShaderCompileFailedEvent = vtkCommand::UserEvent + 0x41534d;

  // The number of programs that did not compile since the mapper was made.
  int GetShaderCompileFailures() const { return this->ShaderCompileFailures; }

  vtkTypeMacro(vtkAnisoPolyDataMapper, vtkOpenGLPolyDataMapper)

protected:
  vtkAnisoPolyDataMapper() = default;
  ~vtkAnisoPolyDataMapper() override = default;

  void BuildShaders(std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren,
                    vtkActor* act) override;

private:
  vtkAnisoPolyDataMapper(const vtkAnisoPolyDataMapper&) = delete;
  void operator=(const vtkAnisoPolyDataMapper&) = delete;

  int ShaderCompileFailures = 0;
};
