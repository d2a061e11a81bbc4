#include "app/gui/SceneAssets.h"

#include "core/error.h"
#include "core/maps/map_files.h"
#include "core/maps/quaternion_map.h"
#include "core/maps/tpr_map.h"
#include "core/parameters/parameters.h"
#include "vtkpasses/mesh/BrushingModel.h"
#include "vtkpasses/mesh/BuiltinMeshes.h"
#include "vtkpasses/mesh/CadReader.h"
#include "vtkpasses/mesh/LevelOfDetail.h"
#include "vtkpasses/mesh/MeshArrays.h"
#include "vtkpasses/mesh/MeshLoader.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>
#include <vtkPolyData.h>

namespace aniso
{
namespace
{
const char* const kBuiltinPrefix = "builtin:";

SurfaceOptions surfaceOptions(const std::string& tangents)
{
  SurfaceOptions options;
  if (tangents != "auto")
  {
    options.brushing = parseBrushingModel(tangents, "tangents");
  }
  return options;
}
} // namespace

SceneAssets::SceneAssets(SceneModel* model) : model_(model)
{
  model->setValidator("mesh", [this](const std::string& text, const std::string&)
                      { checkMesh(text, model_->text("tangents")); });
  model->setValidator("tangents", [this](const std::string& text, const std::string&)
                      { checkMesh(model_->text("mesh"), text); });
  model->setValidator("env",
                      [this](const std::string& text, const std::string&) { environment(text); });
  for (const char* key : kMapKeys)
  {
    model->setValidator(key, [this, key](const std::string& text, const std::string&)
                        { map(key, text); });
  }
}

MeshReadOptions meshReadOptionsOf(const SceneModel& model)
{
  MeshReadOptions options;
  options.cadDeflection.value = model.real("cad-deflection");
  options.cadDeflection.absolute = false;
  options.cadAngleDegrees = model.real("cad-angle");
  return options;
}

MeshReadOptions SceneAssets::meshReadOptions() const
{
  return model_ ? meshReadOptionsOf(*model_) : readOptions_;
}

std::string SceneAssets::readOptionsKey(const std::string& mesh) const
{
  std::string ext = std::filesystem::path(mesh).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  if (mesh.rfind(kBuiltinPrefix, 0) == 0 || !isCadExtension(ext))
  {
    return {};
  }
  const MeshReadOptions options = meshReadOptions();
  return "\ncad " + toString(options.cadDeflection) + " " + formatNumber(options.cadAngleDegrees);
}

bool SceneAssets::hasSurface(const std::string& mesh, const std::string& block,
                             const std::string& tangents) const
{
  return surfaces_.contains(mesh + "\n" + block + "\n" + tangents + readOptionsKey(mesh));
}

std::shared_ptr<const LoadedBlocks> SceneAssets::blocks(const std::string& mesh)
{
  // How CAD files are tessellated is part of what was read.
  const MeshReadOptions options = meshReadOptions();
  const std::string key = mesh + readOptionsKey(mesh);
  return blocks_.get(key,
                     [&]
                     {
                       auto loaded = std::make_shared<LoadedBlocks>();
                       if (mesh.rfind(kBuiltinPrefix, 0) == 0)
                       {
                         MeshBlock block;
                         block.name = mesh.substr(8);
                         block.mesh = makeBuiltinMesh(parseBuiltinMesh(mesh.substr(8), "mesh"));
                         loaded->blocks.push_back(std::move(block));
                       }
                       else
                       {
                         *loaded = loadMeshBlocks(mesh, options);
                       }
                       return std::shared_ptr<const LoadedBlocks>(std::move(loaded));
                     });
}

void SceneAssets::checkMesh(const std::string& mesh, const std::string& tangents)
{
  try
  {
    surface(mesh, tangents);
  }
  catch (const Error&)
  {
    // A file of lines only has no surface, yet parts (its line parts) to draw.
    const bool builtin = mesh.rfind(kBuiltinPrefix, 0) == 0;
    std::shared_ptr<const LoadedBlocks> loaded;
    if (!builtin)
    {
      loaded = blocks(mesh);
    }
    if (!loaded || std::none_of(loaded->blocks.begin(), loaded->blocks.end(),
                                [](const MeshBlock& b) { return b.lines; }))
    {
      throw;
    }
  }
}

std::vector<std::string> SceneAssets::blockNames(const std::string& mesh,
                                                 std::vector<std::string>* warnings)
{
  const std::shared_ptr<const LoadedBlocks> loaded = blocks(mesh);
  std::vector<std::string> names;
  for (const MeshBlock& block : loaded->blocks)
  {
    names.push_back(block.name);
  }
  if (warnings)
  {
    *warnings = loaded->warnings;
  }
  return names;
}

std::shared_ptr<const LoadedMesh> SceneAssets::loadedMesh(const std::string& mesh,
                                                          const std::string& block, bool* lines)
{
  if (!block.empty())
  {
    const std::shared_ptr<const LoadedBlocks> all = blocks(mesh);
    for (const MeshBlock& b : all->blocks)
    {
      if (b.name == block)
      {
        if (lines)
        {
          *lines = b.lines;
        }
        return std::shared_ptr<const LoadedMesh>(all, &b.mesh);
      }
    }
    throw errorAbout(mesh, "no part \"" + block + "\"");
  }
  return meshes_.get(mesh + readOptionsKey(mesh),
                     [&]
                     {
                       if (mesh.rfind(kBuiltinPrefix, 0) == 0)
                       {
                         return std::make_shared<LoadedMesh>(
                             makeBuiltinMesh(parseBuiltinMesh(mesh.substr(8), "mesh")));
                       }
                       return std::make_shared<LoadedMesh>(loadMesh(mesh, meshReadOptions()));
                     });
}

std::vector<std::string> SceneAssets::vectorArrays(const std::string& mesh,
                                                   const std::string& block)
{
  // Only what is loaded already: a file that failed is not read again for its list.
  const std::string key = mesh + readOptionsKey(mesh);
  const bool builtin = mesh.rfind(kBuiltinPrefix, 0) == 0;
  if (block.empty() ? !builtin && !meshes_.contains(key) : !blocks_.contains(key))
  {
    return {};
  }
  return vectorArrayNames(loadedMesh(mesh, block)->polyData);
}

std::vector<std::string> SceneAssets::fieldChoices(const std::string& mesh,
                                                   const std::string& block)
{
  const std::string key = mesh + readOptionsKey(mesh);
  const bool builtin = mesh.rfind(kBuiltinPrefix, 0) == 0;
  if (block.empty() ? !builtin && !meshes_.contains(key) : !blocks_.contains(key))
  {
    return {};
  }
  std::vector<std::string> choices;
  const auto offer = [&choices](std::string choice)
  {
    if (std::find(choices.begin(), choices.end(), choice) == choices.end())
    {
      choices.push_back(std::move(choice));
    }
  };
  for (const ArrayInfo& info : describeArrays(loadedMesh(mesh, block)->polyData))
  {
    if (isGeometryArray(info.name))
    {
      continue;
    }
    offer(info.name); // the value itself, or a vector's magnitude
    if (info.components == 2 || info.components == 3)
    {
      static const char* const kAxes[] = {"x", "y", "z"};
      for (int c = 0; c < info.components; ++c)
      {
        offer(info.name + ":" + kAxes[c]);
      }
    }
    else if (info.components > 3)
    {
      for (int c = 0; c < info.components; ++c)
      {
        offer(info.name + ":" + std::to_string(c));
      }
    }
  }
  return choices;
}

std::shared_ptr<const SceneAssets::Surface> SceneAssets::surfaceEntry(const std::string& mesh,
                                                                      const std::string& block,
                                                                      const std::string& tangents)
{
  return surfaces_.get(
      mesh + "\n" + block + "\n" + tangents + readOptionsKey(mesh),
      [&]
      {
        bool lines = false;
        const std::shared_ptr<const LoadedMesh> loaded = loadedMesh(mesh, block, &lines);
        auto entry = std::make_shared<Surface>();
        if (lines)
        {
          // A line set is drawn as it was loaded (its tangents the line's), without a stand-in.
          entry->prepared.polyData = loaded->polyData;
          entry->notes = loaded->report.notes();
          return std::shared_ptr<const Surface>(std::move(entry));
        }
        entry->prepared = prepareSurface(loaded->polyData, surfaceOptions(tangents),
                                         block.empty() ? mesh : mesh + ": part " + block);
        const vtkIdType triangles = entry->prepared.polyData->GetNumberOfPolys();
        if (block.empty())
        {
          entry->interactive = interactiveLevelOfDetail(entry->prepared.polyData);
        }
        else
        {
          // A part of a file: its share of the stand-in triangles of the file's parts together
          // (their triangles as loaded and sanitised).
          vtkIdType fileTriangles = 0;
          for (const MeshBlock& b : blocks(mesh)->blocks)
          {
            if (!b.lines && b.mesh.polyData)
            {
              fileTriangles += b.mesh.polyData->GetNumberOfPolys();
            }
          }
          const vtkIdType share = partStandInTriangles(triangles, fileTriangles);
          if (share > 0)
          {
            entry->interactive =
                interactiveLevelOfDetail(entry->prepared.polyData, share, share);
          }
        }
        entry->notes = loaded->report.notes();
        for (const std::string& note : entry->prepared.report.notes())
        {
          entry->notes.push_back(note);
        }
        return std::shared_ptr<const Surface>(std::move(entry));
      });
}

void SceneAssets::adopt(SceneAssets& staged)
{
  meshes_.mergeFrom(staged.meshes_);
  blocks_.mergeFrom(staged.blocks_);
  surfaces_.mergeFrom(staged.surfaces_);
  environments_.mergeFrom(staged.environments_);
  images_.mergeFrom(staged.images_);
  maps_.mergeFrom(staged.maps_);
}

std::shared_ptr<const PreparedSurface> SceneAssets::surface(const std::string& mesh,
                                                            const std::string& tangents)
{
  return surface(mesh, {}, tangents);
}

std::shared_ptr<const PreparedSurface>
SceneAssets::surface(const std::string& mesh, const std::string& block, const std::string& tangents)
{
  std::shared_ptr<const Surface> entry = surfaceEntry(mesh, block, tangents);
  return std::shared_ptr<const PreparedSurface>(entry, &entry->prepared);
}

vtkSmartPointer<vtkPolyData> SceneAssets::interactiveSurface(const std::string& mesh,
                                                             const std::string& tangents)
{
  return interactiveSurface(mesh, {}, tangents);
}

vtkSmartPointer<vtkPolyData> SceneAssets::interactiveSurface(const std::string& mesh,
                                                             const std::string& block,
                                                             const std::string& tangents)
{
  return surfaceEntry(mesh, block, tangents)->interactive;
}

std::vector<std::string> SceneAssets::surfaceNotes(const std::string& mesh,
                                                   const std::string& tangents)
{
  return surfaceNotes(mesh, {}, tangents);
}

std::vector<std::string> SceneAssets::surfaceNotes(const std::string& mesh,
                                                   const std::string& block,
                                                   const std::string& tangents)
{
  return surfaceEntry(mesh, block, tangents)->notes;
}

std::shared_ptr<const Environment> SceneAssets::environment(const std::string& spec)
{
  return environments_.get(spec, [&]
                           { return std::shared_ptr<const Environment>(openEnvironment(spec)); });
}

const SceneAssets::LoadedImage& SceneAssets::rawImage(const std::string& path)
{
  const LoadedImage& loaded =
      images_.get(path,
                  [&]
                  {
                    LoadedImage image;
                    image.image = std::make_shared<const Image>(readImage(path, &image.info));
                    return image;
                  });
  const int side = std::max(loaded.image->width, loaded.image->height);
  if (side > maxTextureSide_)
  {
    throw errorAbout(path, std::to_string(loaded.image->width) + "x" +
                               std::to_string(loaded.image->height) + " texels, more than the " +
                               std::to_string(maxTextureSide_) +
                               " per side this OpenGL takes for a texture");
  }
  return loaded;
}

std::shared_ptr<const Image> SceneAssets::map(const std::string& key, const std::string& text)
{
  if (text.empty())
  {
    return nullptr;
  }
  if (key == "tpr")
  {
    return maps_.get("tpr\n" + text,
                     [&]
                     {
                       std::error_code ec;
                       if (!std::filesystem::exists(text, ec))
                       {
                         // Not a file: a pattern (its error names the text when it is neither).
                         return std::make_shared<const Image>(readTprMap(text, key));
                       }
                       const LoadedImage& raw = rawImage(text);
                       return std::make_shared<const Image>(
                           tprFromFileImage(*raw.image, raw.info.integerFormat));
                     });
  }
  if (key == "normal-map" || key == "quaternion-map")
  {
    return maps_.get(key + "\n" + text,
                     [&]
                     {
                       const LoadedImage& raw = rawImage(text);
                       return std::make_shared<const Image>(
                           decodeSignedMap(*raw.image, raw.info.integerFormat));
                     });
  }
  return rawImage(text).image;
}

void SceneAssets::addMaps(const SceneModel& model, MaterialSettings& settings)
{
  addMaps([&](const char* key) -> const std::string& { return model.text(key); }, settings);
}

void SceneAssets::addMaps(const Material& material, MaterialSettings& settings)
{
  addMaps([&](const char* key) -> const std::string& { return material.value(key).text; },
          settings);
}

void SceneAssets::addMaps(const std::function<const std::string&(const char*)>& text,
                          MaterialSettings& settings)
{
  const BumpMapping bump = parseBumpMapping(text("bump"));
  const std::string& normals = text("normal-map");
  const std::string& quaternions = text("quaternion-map");
  settings.normalMap = nullptr;
  settings.quaternionMap = nullptr;
  if (bump == BumpMapping::Normal)
  {
    settings.normalMap = map("normal-map", normals);
  }
  else if (bump == BumpMapping::Quaternion && !quaternions.empty())
  {
    settings.quaternionMap = map("quaternion-map", quaternions);
  }
  else if (bump == BumpMapping::Quaternion && !normals.empty())
  {
    settings.quaternionMap = maps_.get("baked-quaternion\n" + normals,
                                       [&]
                                       {
                                         const LoadedImage& raw = rawImage(normals);
                                         return std::make_shared<const Image>(bakeQuaternionMap(
                                             *raw.image, raw.info.integerFormat, nullptr));
                                       });
  }
  settings.tprMap = map("tpr", text("tpr"));
  settings.heightMap = map("height-map", text("height-map"));
  settings.albedoMap = map("albedo-map", text("albedo-map"));
  settings.occlusionMap = map("ao-map", text("ao-map"));
  settings.metallicMap = map("metallic-map", text("metallic-map"));
}
} // namespace aniso
