// aniso's Ashikhmin-Shirley environment material as a ParaView surface representation ("Aniso
// Surface"): ParaView's geometry representation, whose actor draws the surface prepared as the
// application prepares it (normals, tangents by the tangent model) with the material installed
// by shader replacements (vtkpasses/render/AnisoMaterial), under an environment of its own
// (an equirectangular HDR/EXR file or a built-in one), displayed in the fragment through the
// application's display transform (exposure, tone mapping, sRGB). Every property takes the
// application's parameter of the same meaning and checks it the same way; a material library
// of the application (JSON) can give the material's values by name. Each process draws its
// own partition with the same tables and environment; one frame of the chosen samples per
// render, no progressive accumulation (docs/PARAVIEW.md).
#ifndef vtkAnisoRepresentation_h
#define vtkAnisoRepresentation_h

#include <AnisoRepresentationsModule.h> // for the export macro
#include <string>                       // for std::string
#include <vtkGeometryRepresentationWithFaces.h>

class ANISOREPRESENTATIONS_EXPORT vtkAnisoRepresentation : public vtkGeometryRepresentationWithFaces
{
public:
  static vtkAnisoRepresentation* New();
  vtkTypeMacro(vtkAnisoRepresentation,
               vtkGeometryRepresentationWithFaces) void PrintSelf(ostream& os,
                                                                  vtkIndent indent) override;

  // The material's parameters, as `aniso render` spells their values (docs/PARAVIEW.md). An
  // invalid value is reported as a VTK error naming the property and the reason, and the
  // previous value is kept.
  void SetAnisoRoughnessU(double nu);
  void SetAnisoRoughnessV(double nv);
  void SetAnisoReflectance(double r, double g, double b);
  void SetAnisoAlbedo(double r, double g, double b);
  void SetAnisoTangents(const char* model);
  void SetAnisoSamples(int samples);
  void SetAnisoMethod(const char* method);
  void SetAnisoEnvironmentSampling(const char* sampling);
  void SetAnisoEnvironment(const char* environment);
  void SetAnisoEnvironmentRotation(double degrees);
  void SetAnisoExposure(double ev);
  void SetAnisoToneMapping(const char* toneMapping);
  // A material library or session file of the application and the name of one of its
  // materials (empty: none): its values replace the ones above that it holds.
  void SetAnisoMaterialLibrary(const char* path);
  void SetAnisoMaterialName(const char* name);

  // The last error (empty when the material draws as set).
  const char* GetAnisoStatus();

  int ProcessViewRequest(vtkInformationRequestKey* request_type, vtkInformation* inInfo,
                         vtkInformation* outInfo) override;

protected:
  vtkAnisoRepresentation();
  ~vtkAnisoRepresentation() override;

  bool AddToView(vtkView* view) override;
  bool RemoveFromView(vtkView* view) override;

private:
  vtkAnisoRepresentation(const vtkAnisoRepresentation&) = delete;
  void operator=(const vtkAnisoRepresentation&) = delete;

  void SetParameterText(const char* property, const char* key, const std::string& text);
  void UpdateMaterial();

  struct Internals;
  Internals* Internal;
};

#endif
