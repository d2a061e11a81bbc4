#include "paraview/plugin/AnisoMaterial/AnisoRepresentations/vtkAnisoRepresentation.h"

#include "core/env/environment.h"
#include "core/error.h"
#include "core/parameters/material_library.h"
#include "core/parameters/parameters.h"
#include "vtkpasses/mesh/BrushingModel.h"
#include "vtkpasses/mesh/CadReader.h"
#include "vtkpasses/mesh/MeshValidation.h"
#include "vtkpasses/mesh/SurfacePreparation.h"
#include "vtkpasses/render/AnisoMaterial.h"
#include "vtkpasses/render/DisplaySettings.h"
#include "vtkpasses/render/EnvironmentLighting.h"
#include "vtkpasses/render/MaterialSettings.h"
#include "vtkpasses/render/ShaderHook.h"
#include "vtkpasses/render/vtkAnisoPolyDataMapper.h"

#include <algorithm>
#include <array>
#include <fstream>
#include <glm/vec3.hpp>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <vtkAppendPolyData.h>
#include <vtkCommunicator.h>
#include <vtkCompositeDataIterator.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataSet.h>
#include <vtkInformation.h>
#include <vtkMath.h>
#include <vtkMultiProcessController.h>
#include <vtkObjectFactory.h>
#include <vtkOpenGLShaderProperty.h>
#include <vtkPVLODActor.h>
#include <vtkPVRenderView.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTriangleFilter.h>

namespace
{
// Text of a number that parseParameterValue reads back to the same double.
std::string numberText(double value)
{
  std::ostringstream out;
  out.precision(17);
  out << value;
  return out.str();
}

// The surface of a delivered piece (a polydata or a composite of them, this process's
// partition) as one polydata of triangles; null when it has no cells.
vtkSmartPointer<vtkPolyData> trianglesOf(vtkDataObject* data)
{
  vtkNew<vtkAppendPolyData> append;
  int inputs = 0;
  if (auto* poly = vtkPolyData::SafeDownCast(data))
  {
    append->AddInputData(poly);
    ++inputs;
  }
  else if (auto* composite = vtkCompositeDataSet::SafeDownCast(data))
  {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(composite->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      auto* leaf = vtkPolyData::SafeDownCast(it->GetCurrentDataObject());
      if (leaf && leaf->GetNumberOfCells() > 0)
      {
        append->AddInputData(leaf);
        ++inputs;
      }
    }
  }
  if (inputs == 0)
  {
    return nullptr;
  }
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(append->GetOutputPort());
  triangles->PassVertsOff();
  triangles->PassLinesOff();
  triangles->Update();
  vtkSmartPointer<vtkPolyData> out = triangles->GetOutput();
  // ParaView's geometry filter keeps a mesh's "Normals" but not always as the active normals,
  // which are what the surface preparation keeps (a mesh without them gets computed ones).
  vtkPointData* points = out->GetPointData();
  vtkDataArray* normals = points->GetArray("Normals");
  if (!points->GetNormals() && normals && normals->GetNumberOfComponents() == 3)
  {
    points->SetActiveNormals("Normals");
  }
  vtkDataArray* tangents = points->GetArray("Tangents");
  if (!points->GetTangents() && tangents && tangents->GetNumberOfComponents() == 3)
  {
    points->SetActiveTangents("Tangents");
  }
  return out->GetNumberOfCells() > 0 ? out : nullptr;
}

// The tangent models `auto` chooses from, in its order (vtkpasses/mesh/SurfacePreparation.h):
// the mesh's own tangents when all are valid, the UVs, the CAD faces' dS/du, axis:1,0,0.
enum AutoTangents
{
  MeshTangents = 0,
  UvTangents = 1,
  FaceTangents = 2,
  AxisTangents = 3
};

// Which of the first three a piece's surface can give (1) or not (0): its own tangents, all
// valid against its normals (prepared as `auto` prepares it, which keeps them only then); texture
// coordinates; a CAD part's dS/du.
std::array<int, 3> tangentSourcesOf(vtkPolyData* clean)
{
  vtkPointData* points = clean->GetPointData();
  std::array<int, 3> can{0, points->GetTCoords() != nullptr ? 1 : 0,
                         points->GetArray(aniso::kBRepTangentUArray) != nullptr ? 1 : 0};
  if (points->GetTangents())
  {
    can[MeshTangents] =
        aniso::prepareSurface(clean, {}, "ParaView piece").report.tangentSource == "mesh" ? 1 : 0;
  }
  return can;
}

// The materials of a material library file, or of a session file's "materials" section.
aniso::MaterialLibrary libraryOfFile(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    throw aniso::errorAbout(path, "cannot be opened");
  }
  std::stringstream text;
  text << in.rdbuf();
  const std::string directory = path.find('/') == std::string::npos
                                    ? std::string(".")
                                    : path.substr(0, path.find_last_of('/'));
  const nlohmann::json document = nlohmann::json::parse(text.str(), nullptr, false);
  if (document.is_object() && document.contains("materials") &&
      document.value("format", std::string()) != "aniso-materials")
  {
    // A session: its materials section is a library of its own.
    nlohmann::json library = {
        {"format", "aniso-materials"}, {"version", 1}, {"materials", document["materials"]}};
    return aniso::materialLibraryFromJson(library.dump(), directory, path);
  }
  return aniso::readMaterialLibrary(path);
}
} // namespace

struct vtkAnisoRepresentation::Internals
{
  aniso::ParameterSet parameters;
  std::string library;                   // material library or session file
  std::string material;                  // a material of it
  std::string readLibrary, readMaterial; // what `values` was read from
  aniso::Material::Values values;
  aniso::MaterialSettings maps;                // its maps, read from their files
  std::string status;                          // what the last update reported
  std::map<std::string, std::string> rejected; // property: why its last value was refused
  std::string statusText;                      // GetAnisoStatus's

  vtkNew<vtkAnisoPolyDataMapper> drawn;  // the actor's mapper: the prepared surface
  std::optional<glm::dvec3> centre;      // of the whole data's bounds, over every rank
  vtkDataObject* preparedFrom = nullptr;
  vtkMTimeType preparedTime = 0;
  std::string preparedTangents;
  std::optional<glm::dvec3> preparedCentre;
  int preparedAuto = MeshTangents;
  // The tangent sources of this rank's piece (tangentSourcesOf), and the piece they are of.
  std::array<int, 3> sources{1, 1, 1};
  vtkDataObject* sourcesFrom = nullptr;
  vtkMTimeType sourcesTime = 0;
  // What `auto` stands for on this rank: the first model that every rank's piece can give, so
  // that the partitions are brushed as the whole would be (a piece alone: its own first).
  int autoTangents = MeshTangents;
  vtkSmartPointer<vtkPolyData> prepared;

  vtkRenderer* renderer = nullptr;
  std::shared_ptr<aniso::EnvironmentLighting> lighting;
  std::string lightingSpec;
  int lightingCube = 0;
  std::unique_ptr<aniso::AnisoMaterial> anisoMaterial;
  std::vector<std::pair<std::string, std::string>> displayCode;
};

vtkStandardNewMacro(vtkAnisoRepresentation);

vtkAnisoRepresentation::vtkAnisoRepresentation() : Internal(new Internals)
{
  // The actor draws the prepared surface with a polydata mapper, the one the material hooks;
  // the superclass's composite mapper only receives the delivered pieces. No level of detail:
  // a decimated surface would need tangents of its own.
  this->Internal->drawn->ScalarVisibilityOff();
  this->Actor->SetMapper(this->Internal->drawn);
  this->Actor->SetLODMapper(this->Internal->drawn);
  this->SuppressLOD = true;
}

vtkAnisoRepresentation::~vtkAnisoRepresentation()
{
  if (this->Internal->anisoMaterial)
  {
    this->Internal->anisoMaterial->detach();
  }
  delete this->Internal;
}

void vtkAnisoRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "AnisoStatus: " << this->GetAnisoStatus() << "\n";
}

void vtkAnisoRepresentation::SetParameterText(const char* property, const char* key,
                                              const std::string& text)
{
  try
  {
    const aniso::ParameterValue value =
        aniso::parseParameterValue(aniso::parameterSpec(key), text, property);
    if (key == std::string("tangents") && text != "auto")
    {
      aniso::parseBrushingModel(text, property);
    }
    this->Internal->parameters.setValue(key, value);
    this->Internal->rejected.erase(property);
    this->Modified();
  }
  catch (const std::exception& e)
  {
    this->Internal->rejected[property] = e.what();
    vtkErrorMacro(<< "aniso: " << e.what());
  }
}

void vtkAnisoRepresentation::SetAnisoRoughnessU(double nu)
{
  this->SetParameterText("AnisoRoughnessU", "nu", numberText(nu));
}
void vtkAnisoRepresentation::SetAnisoRoughnessV(double nv)
{
  this->SetParameterText("AnisoRoughnessV", "nv", numberText(nv));
}
void vtkAnisoRepresentation::SetAnisoReflectance(double r, double g, double b)
{
  this->SetParameterText("AnisoReflectance", "f0",
                         numberText(r) + "," + numberText(g) + "," + numberText(b));
}
void vtkAnisoRepresentation::SetAnisoAlbedo(double r, double g, double b)
{
  this->SetParameterText("AnisoAlbedo", "albedo",
                         numberText(r) + "," + numberText(g) + "," + numberText(b));
}
void vtkAnisoRepresentation::SetAnisoTangents(const char* model)
{
  this->SetParameterText("AnisoTangents", "tangents", model ? model : "");
}
void vtkAnisoRepresentation::SetAnisoSamples(int samples)
{
  this->SetParameterText("AnisoSamples", "samples", std::to_string(samples));
}
void vtkAnisoRepresentation::SetAnisoMethod(const char* method)
{
  this->SetParameterText("AnisoMethod", "method", method ? method : "");
}
void vtkAnisoRepresentation::SetAnisoEnvironmentSampling(const char* sampling)
{
  this->SetParameterText("AnisoEnvironmentSampling", "env-sampling", sampling ? sampling : "");
}
void vtkAnisoRepresentation::SetAnisoEnvironment(const char* environment)
{
  this->SetParameterText("AnisoEnvironment", "env", environment ? environment : "");
}
void vtkAnisoRepresentation::SetAnisoEnvironmentRotation(double degrees)
{
  this->SetParameterText("AnisoEnvironmentRotation", "env-rotation", numberText(degrees));
}
void vtkAnisoRepresentation::SetAnisoExposure(double ev)
{
  this->SetParameterText("AnisoExposure", "exposure", numberText(ev));
}
void vtkAnisoRepresentation::SetAnisoToneMapping(const char* toneMapping)
{
  this->SetParameterText("AnisoToneMapping", "tone-mapping", toneMapping ? toneMapping : "");
}
void vtkAnisoRepresentation::SetAnisoMaterialLibrary(const char* path)
{
  this->Internal->library = path ? path : "";
  this->Modified();
}
void vtkAnisoRepresentation::SetAnisoMaterialName(const char* name)
{
  this->Internal->material = name ? name : "";
  this->Modified();
}

const char* vtkAnisoRepresentation::GetAnisoStatus()
{
  // A refused value first (the property keeps its previous one), then the update's error.
  Internals& d = *this->Internal;
  d.statusText = d.rejected.empty() ? d.status : d.rejected.begin()->second;
  return d.statusText.c_str();
}

bool vtkAnisoRepresentation::AddToView(vtkView* view)
{
  if (auto* renderView = vtkPVRenderView::SafeDownCast(view))
  {
    this->Internal->renderer = renderView->GetRenderer();
  }
  return this->Superclass::AddToView(view);
}

bool vtkAnisoRepresentation::RemoveFromView(vtkView* view)
{
  if (this->Internal->anisoMaterial)
  {
    this->Internal->anisoMaterial->detach();
    this->Internal->anisoMaterial.reset();
  }
  this->Internal->renderer = nullptr;
  return this->Superclass::RemoveFromView(view);
}

int vtkAnisoRepresentation::ProcessViewRequest(vtkInformationRequestKey* request_type,
                                               vtkInformation* inInfo, vtkInformation* outInfo)
{
  if (!this->Superclass::ProcessViewRequest(request_type, inInfo, outInfo))
  {
    return 0;
  }
  if (request_type == vtkPVView::REQUEST_UPDATE())
  {
    // Every rank updates its piece together: the bounds of the whole data, for what depends on
    // them (the centre of tangents brushed around an axis).
    double local[6] = {VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX,
                       VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX};
    if (auto* data = vtkDataObject::SafeDownCast(this->GetRenderedDataObject(0)))
    {
      double b[6];
      vtkMath::UninitializeBounds(b);
      if (auto* set = vtkDataSet::SafeDownCast(data))
      {
        set->GetBounds(b);
      }
      else if (auto* composite = vtkCompositeDataSet::SafeDownCast(data))
      {
        composite->GetBounds(b);
      }
      if (vtkMath::AreBoundsInitialized(b))
      {
        // Minima, and maxima negated, so that one reduction by the minimum takes both.
        for (int axis = 0; axis < 3; ++axis)
        {
          local[2 * axis] = b[2 * axis];
          local[2 * axis + 1] = -b[2 * axis + 1];
        }
      }
    }
    double global[6];
    std::copy(local, local + 6, global);
    if (auto* controller = vtkMultiProcessController::GetGlobalController())
    {
      controller->AllReduce(local, global, 6, vtkCommunicator::MIN_OP);
    }
    this->Internal->centre.reset();
    if (global[0] <= -global[1])
    {
      this->Internal->centre =
          glm::dvec3(0.5 * (global[0] - global[1]), 0.5 * (global[2] - global[3]),
                     0.5 * (global[4] - global[5]));
    }

    // The tangent sources every rank's piece can give (an empty piece, or one that does not
    // prepare, any: it draws nothing of its own, and its error is reported at the render);
    // found again only when the piece changed, not for every property's update.
    Internals& d = *this->Internal;
    auto* piece = vtkDataObject::SafeDownCast(this->GetRenderedDataObject(0));
    if (piece != d.sourcesFrom || (piece && piece->GetMTime() != d.sourcesTime))
    {
      d.sources = {1, 1, 1};
      try
      {
        if (vtkSmartPointer<vtkPolyData> triangles = trianglesOf(piece))
        {
          aniso::MeshReport report;
          d.sources = tangentSourcesOf(aniso::sanitizeSurface(triangles, "ParaView piece", report));
        }
      }
      catch (const std::exception&)
      {
      }
      d.sourcesFrom = piece;
      d.sourcesTime = piece ? piece->GetMTime() : 0;
    }
    int can[3];
    std::copy(d.sources.begin(), d.sources.end(), can);
    int all[3];
    std::copy(can, can + 3, all);
    if (auto* controller = vtkMultiProcessController::GetGlobalController())
    {
      controller->AllReduce(can, all, 3, vtkCommunicator::MIN_OP);
    }
    d.autoTangents = all[MeshTangents]   ? MeshTangents
                     : all[UvTangents]   ? UvTangents
                     : all[FaceTangents] ? FaceTangents
                                         : AxisTangents;
  }
  else if (request_type == vtkPVView::REQUEST_RENDER())
  {
    this->UpdateMaterial();
  }
  return 1;
}

void vtkAnisoRepresentation::UpdateMaterial()
{
  Internals& d = *this->Internal;
  try
  {
    // The parameters, with a library material's values over the properties' own.
    aniso::ParameterSet parameters = d.parameters;
    if (d.library.empty() || d.material.empty())
    {
      d.values.clear();
      d.maps = {};
      d.readLibrary.clear();
      d.readMaterial.clear();
    }
    else if (d.library != d.readLibrary || d.material != d.readMaterial)
    {
      // The material and its maps' files are read once, when the library or the name changes.
      d.values.clear();
      d.maps = {};
      d.readLibrary.clear();
      const aniso::Material material = libraryOfFile(d.library).at(d.material);
      aniso::readMaterialMaps(material, d.maps);
      d.values = material.values;
      d.readLibrary = d.library;
      d.readMaterial = d.material;
    }
    for (const auto& [key, value] : d.values)
    {
      if (!aniso::isMaterialMapKey(key))
      {
        parameters.setValue(key, value);
      }
    }

    // This process's piece, prepared as the application prepares a mesh.
    vtkDataObject* piece = this->Mapper->GetInputDataObject(0, 0);
    const std::string tangents = parameters.text("tangents");
    if (d.centre != d.preparedCentre)
    {
      d.preparedFrom = nullptr; // prepared anew for the new centre
    }
    if (piece != d.preparedFrom || (piece && piece->GetMTime() != d.preparedTime) ||
        tangents != d.preparedTangents || d.autoTangents != d.preparedAuto)
    {
      d.prepared = nullptr;
      if (vtkSmartPointer<vtkPolyData> triangles = trianglesOf(piece))
      {
        aniso::MeshReport report;
        vtkSmartPointer<vtkPolyData> clean =
            aniso::sanitizeSurface(triangles, "ParaView piece", report);
        aniso::SurfaceOptions options;
        if (tangents == "auto" && d.autoTangents != MeshTangents)
        {
          // The model every rank can give: this piece's own tangents go even where they are
          // valid, as a whole's would where some of them are not.
          // (Setting no tangents removes the active array, as removing it by name would.)
          clean->GetPointData()->SetTangents(nullptr);
          aniso::BrushingModel model;
          if (d.autoTangents == FaceTangents)
          {
            model.kind = aniso::BrushingKind::FaceU;
          }
          else if (d.autoTangents == AxisTangents)
          {
            model.kind = aniso::BrushingKind::Axis;
            model.vector = glm::dvec3(1.0, 0.0, 0.0);
          }
          options.brushing = model;
        }
        else if (tangents != "auto")
        {
          options.brushing = aniso::parseBrushingModel(tangents, "AnisoTangents");
          // Brushed around an axis through the bounding box's centre: the whole data's, not
          // this rank's partition's, so that every partition brushes as the whole would.
          if (options.brushing->kind == aniso::BrushingKind::Around && !options.brushing->centre &&
              d.centre)
          {
            options.brushing->centre = *d.centre;
          }
        }
        d.prepared = aniso::prepareSurface(clean, options, "ParaView piece").polyData;
      }
      d.preparedFrom = piece;
      d.preparedTime = piece ? piece->GetMTime() : 0;
      d.preparedTangents = tangents;
      d.preparedCentre = d.centre;
      d.preparedAuto = d.autoTangents;
      if (d.prepared)
      {
        d.drawn->SetInputData(d.prepared);
      }
      else
      {
        d.drawn->SetInputData(vtkNew<vtkPolyData>());
      }
    }

    // The environment: baked again only when its file or cube size changed.
    const std::string spec = parameters.text("env");
    const int cube = parameters.integer("cube-size");
    if (!d.lighting || spec != d.lightingSpec || cube != d.lightingCube)
    {
      d.lighting = std::make_shared<aniso::EnvironmentLighting>(aniso::openEnvironment(spec), cube);
      d.lightingSpec = spec;
      d.lightingCube = cube;
      if (d.anisoMaterial)
      {
        d.anisoMaterial->setLighting(d.lighting);
      }
    }
    d.lighting->setRotationDegrees(parameters.real("env-rotation"));

    const aniso::MaterialSettings settings = aniso::materialFromParameters(parameters, d.maps);
    if (!d.anisoMaterial && d.renderer && d.prepared)
    {
      d.anisoMaterial = std::make_unique<aniso::AnisoMaterial>(d.lighting, settings);
      d.anisoMaterial->apply(this->Actor, d.renderer);
    }
    else if (d.anisoMaterial)
    {
      d.anisoMaterial->setSettings(settings);
    }

    // The display transform in the fragment: ParaView shows the draw as it is.
    auto code = aniso::displayInFragmentCode(aniso::displayFromParameters(parameters));
    if (code != d.displayCode)
    {
      auto* property = vtkOpenGLShaderProperty::SafeDownCast(this->Actor->GetShaderProperty());
      for (const auto& [tag, text] : d.displayCode)
      {
        property->ClearFragmentShaderReplacement(tag, true);
      }
      for (const auto& [tag, text] : code)
      {
        property->AddFragmentShaderReplacement(tag, true, tag + "\n" + text, false);
      }
      d.displayCode = code;
    }
    // The material draws without its maps where the piece has no texture coordinates (its
    // shader leaves them out): said, as the window says it.
    if (settings.usesMaps() && d.prepared && !aniso::meshArraysOf(d.prepared).tcoords)
    {
      throw aniso::errorAbout(d.library, "material '" + d.material +
                                             "': the data have no texture coordinates, which "
                                             "its maps need (drawn without the maps)");
    }
    d.status.clear();
  }
  catch (const std::exception& e)
  {
    if (d.status != e.what())
    {
      vtkErrorMacro(<< "aniso: " << e.what());
    }
    d.status = e.what();
  }
}
