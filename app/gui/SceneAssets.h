#pragma once
// Loads what the scene's texts name (meshes, environments, maps), keeps the last few of each,
// and checks them for the model: installed as the model's validators, so a mesh, image or
// environment that does not load is refused before the scene changes, with its file's name.
#include "core/env/environment.h"
#include "core/image/image.h"
#include "scene/SceneModel.h"
#include "vtkpasses/mesh/MeshLoader.h"
#include "vtkpasses/mesh/SurfacePreparation.h"
#include "vtkpasses/render/MaterialSettings.h"

#include <algorithm>
#include <functional>
#include <list>
#include <memory>
#include <string>
#include <utility>

namespace aniso
{
// A few recently used values by key; the oldest goes first.
template <class T>
class RecentCache
{
public:
  explicit RecentCache(std::size_t capacity) : capacity_(capacity) {}

    bool contains(const std::string& key) const
  {
    return std::any_of(items_.begin(), items_.end(),
                       [&](const std::pair<std::string, T>& item) { return item.first == key; });
  }

  template <class Make>
  const T& get(const std::string& key, Make make)
  {
    for (auto it = items_.begin(); it != items_.end(); ++it)
    {
      if (it->first == key)
      {
        items_.splice(items_.begin(), items_, it);
        return items_.front().second;
      }
    }
    T value = make(); // may throw: nothing is stored then
    return put(key, std::move(value));
  }

  // Takes OTHER's entries, its most recent ending as the most recent here.
  void mergeFrom(RecentCache& other)
  {
    for (auto it = other.items_.rbegin(); it != other.items_.rend(); ++it)
    {
      put(it->first, std::move(it->second));
    }
    other.items_.clear();
  }

  // Stores VALUE as the most recent under KEY (replacing what KEY held).
  const T& put(const std::string& key, T value)
  {
    for (auto it = items_.begin(); it != items_.end(); ++it)
    {
      if (it->first == key)
      {
        items_.erase(it);
        break;
      }
    }
    items_.emplace_front(key, std::move(value));
    if (items_.size() > capacity_)
    {
      items_.pop_back();
    }
    return items_.front().second;
  }

private:
  std::size_t capacity_;
  std::list<std::pair<std::string, T>> items_;
};

// The read options a model's cad-deflection (relative) and cad-angle ask for.
MeshReadOptions meshReadOptionsOf(const SceneModel& model);

class SceneAssets
{
public:
  // The keys whose text names a map (a file, or for tpr a pattern).
  static constexpr const char* kMapKeys[] = {
      "normal-map", "quaternion-map", "tpr", "height-map", "albedo-map", "ao-map", "metallic-map"};

  // Installs the validators of mesh, tangents, env and the map keys on MODEL.
  explicit SceneAssets(SceneModel* model);
  // Assets of no model (no validators): a staging area that loads on another thread what
  // adopt() then hands to the assets of the scene.
  SceneAssets() = default;

  // Takes what STAGED loaded into these caches (as the most recent entries), so what it loaded
  // is found here without being read again. On the thread that uses these assets, once the one
  // that filled STAGED is done with it.
  void adopt(SceneAssets& staged);

  // The prepared surface of a mesh text (a path or builtin:NAME) with a tangent model text
  // ("auto" or BrushingModel.h's syntax). Throws aniso::Error "SUBJECT: reason".
  std::shared_ptr<const PreparedSurface> surface(const std::string& mesh,
                                                 const std::string& tangents);
  // Throws as surface(MESH, TANGENTS) does, unless MESH is a file whose parts include line
  // parts (loadMeshBlocks): a file of lines only has no surface but parts to draw.
  void checkMesh(const std::string& mesh, const std::string& tangents);
  // The same for one block of the mesh file (loadMeshBlocks' name; empty: the whole file). A
  // block the file does not have throws aniso::Error "MESH: no part BLOCK".
  std::shared_ptr<const PreparedSurface> surface(const std::string& mesh, const std::string& block,
                                                 const std::string& tangents);
  // The blocks of a mesh file (a built-in mesh: one, named by it), loaded once and kept; what
  // was skipped in WARNINGS. Throws aniso::Error "PATH: reason" for a file that fails as a whole.
  std::vector<std::string> blockNames(const std::string& mesh, std::vector<std::string>* warnings);
  // The blocks themselves, with the materials and placements the file gives them.
  std::shared_ptr<const LoadedBlocks> blocks(const std::string& mesh);
  // The vector arrays of a mesh text's block (empty: the whole file) as loaded, before any
  // tangent model (MeshArrays.h, vectorArrayNames); none when it is not loaded (nothing is read
  // here). Throws aniso::Error "MESH: no part BLOCK" for a block the file does not have.
  std::vector<std::string> vectorArrays(const std::string& mesh, const std::string& block);
  // What the same block offers the `field` key (core/fields/field_mapping.h), from its data
  // arrays (MeshArrays.h, describeArrays; not isGeometryArray), each name once, point arrays
  // first: "NAME" for an array of one component; "NAME" (its magnitude), "NAME:x", "NAME:y" and
  // for three components "NAME:z" for an array of 2 or 3; "NAME" and "NAME:0", "NAME:1", ... for
  // any other count. None when it is not loaded; throws as vectorArrays does.
  std::vector<std::string> fieldChoices(const std::string& mesh, const std::string& block);
  // Its stand-in while the view moves (LevelOfDetail.h), null when it is drawn as it is. Made
  // with the surface, so a surface prepared on a worker brings it along.
  vtkSmartPointer<vtkPolyData> interactiveSurface(const std::string& mesh,
                                                  const std::string& tangents);
  vtkSmartPointer<vtkPolyData> interactiveSurface(const std::string& mesh, const std::string& block,
                                                  const std::string& tangents);
  // What loading and preparing that surface had to say (dropped faces, computed normals...).
  std::vector<std::string> surfaceNotes(const std::string& mesh, const std::string& tangents);
  std::vector<std::string> surfaceNotes(const std::string& mesh, const std::string& block,
                                        const std::string& tangents);

  std::shared_ptr<const Environment> environment(const std::string& spec);
  // The maps the model's values ask for, as the material takes them (bump none: no normal or
  // quaternion map; quaternion: the quaternion map, else baked from the normal map).
  // Throws aniso::Error "PATH: reason".
  void addMaps(const SceneModel& model, MaterialSettings& settings);
  // The same from a library material's maps.
  void addMaps(const Material& material, MaterialSettings& settings);

  // Map loading by key, as addMaps does it (normal-map and quaternion-map decoded to signed
  // vectors, tpr from a pattern or a file).
  std::shared_ptr<const Image> map(const std::string& key, const std::string& text);

  // The largest texture side the view's OpenGL takes (GL_MAX_TEXTURE_SIZE); map files larger
  // than that are refused with their name. Until the view has asked its OpenGL:
  // kDefaultMaxTextureSide, the common limit of current implementations (llvmpipe's too).
  static constexpr int kDefaultMaxTextureSide = 16384;
  void setMaxTextureSide(int side) { maxTextureSide_ = side; }

  // How mesh files are read (a CAD file's tessellation) by assets of no model (a staging area
  // set up as the scene's assets read); assets of a model read its cad-deflection and cad-angle
  // (meshReadOptionsOf).
  void setMeshReadOptions(const MeshReadOptions& options) { readOptions_ = options; }
  MeshReadOptions meshReadOptions() const;
  // What the read options add to the cache keys of MESH: empty for a file they do not change
  // (anything but STEP and IGES, so those keep their entries when the options change), else the
  // options as text. Part of the keys of the blocks, the meshes and the surfaces.
  std::string readOptionsKey(const std::string& mesh) const;
  // Whether that surface is loaded and prepared with the current read options (surface() would
  // read nothing).
  bool hasSurface(const std::string& mesh, const std::string& block,
                  const std::string& tangents) const;
  int maxTextureSide() const { return maxTextureSide_; }

private:
  struct Surface
  {
    PreparedSurface prepared;
    vtkSmartPointer<vtkPolyData> interactive;
    std::vector<std::string> notes; // the mesh report's, then the preparation's
  };
  // The loaded (sanitised) mesh of a block, or of the whole file for an empty BLOCK.
  std::shared_ptr<const LoadedMesh> loadedMesh(const std::string& mesh, const std::string& block,
                                               bool* lines = nullptr);
  std::shared_ptr<const Surface> surfaceEntry(const std::string& mesh, const std::string& block,
                                              const std::string& tangents);
  // Maps by key as TEXT gives them.
  void addMaps(const std::function<const std::string&(const char*)>& text,
               MaterialSettings& settings);
  struct LoadedImage
  {
    std::shared_ptr<const Image> image;
    ImageInfo info;
  };
  const LoadedImage& rawImage(const std::string& path);

  SceneModel* model_ = nullptr;
  int maxTextureSide_ = kDefaultMaxTextureSide;
  MeshReadOptions readOptions_;
  RecentCache<std::shared_ptr<LoadedMesh>> meshes_{3};
  RecentCache<std::shared_ptr<const LoadedBlocks>> blocks_{8};
  // One entry per part of a scene of many (each with its tangents), so a scene's parts stay.
  RecentCache<std::shared_ptr<const Surface>> surfaces_{1024};
  RecentCache<std::shared_ptr<const Environment>> environments_{3};
  RecentCache<LoadedImage> images_{8};
  RecentCache<std::shared_ptr<const Image>> maps_{8};
};
} // namespace aniso
