#include "app/render_parts.h"

#include "core/models/models.h"
#include "core/parameters/choices.h"
#include "core/quality/adaptive_quality.h"
#include "vtkpasses/mesh/BrushingModel.h"

#include <filesystem>
#include <memory>
#include <set>
#include <vtkPolyData.h>

namespace aniso::cli
{
namespace
{
namespace fs = std::filesystem;

// The names of PARTS for a message: "a, b, c" (the first few of many).
std::string partNames(const std::vector<ScenePart>& parts)
{
  constexpr std::size_t kShown = 8;
  std::string names;
  for (std::size_t i = 0; i < parts.size() && i < kShown; ++i)
  {
    names += (i ? ", " : "") + parts[i].name;
  }
  if (parts.size() > kShown)
  {
    names += ", ... (" + std::to_string(parts.size()) + " parts)";
  }
  return names;
}

// "PATTERN=MATERIAL", split at the first '='.
std::pair<std::string, std::string> splitPartRule(const std::string& rule)
{
  const std::size_t equals = rule.find('=');
  if (equals == std::string::npos || equals == 0 || equals + 1 == rule.size())
  {
    throw usageError("--part", "'" + rule + "' is not PATTERN=MATERIAL");
  }
  return {rule.substr(0, equals), rule.substr(equals + 1)};
}
} // namespace

void addPartOptions(Command& c)
{
  Option materials = textOption(
      "--materials", "FILE",
      "a material library (JSON, format aniso-materials) whose materials --part may assign, "
      "besides the built-in metals (a material of the same name as a built-in one wins)");
  materials.group = kGroupScene;
  c.options.push_back(materials);
  Option part = textOption(
      "--part", "PATTERN=MATERIAL",
      "draw the parts whose names match PATTERN ('*' any run of characters, '?' one character) "
      "with library material MATERIAL instead of the command line's material; repeatable, a "
      "later --part wins where patterns overlap. Parts are named by their file's stem, or by "
      "their block in a file of several (OBJ g and o, VTM blocks, glTF nodes); 'name 2' for a "
      "second of the same name; --list-parts shows them");
  part.repeatable = true;
  part.group = kGroupScene;
  c.options.push_back(part);
  Option hide = textOption("--hide", "PATTERN",
                           "leave out the parts whose names match PATTERN (not drawn, and the "
                           "camera fits the others); repeatable");
  hide.repeatable = true;
  hide.group = kGroupScene;
  c.options.push_back(hide);
  Option list = textOption("--list-parts", "",
                           "print the parts, one line each (name, triangles, material, 'hidden' "
                           "for a hidden one), and exit without rendering");
  list.group = kGroupScene;
  c.options.push_back(list);
  Option arrays = textOption(
      "--list-arrays", "",
      "print each part's data arrays, one line each under the part's name (name, point or cell, "
      "components, the range of the finite values or of their lengths, the count of NaN or Inf "
      "values), and exit without rendering");
  c.options.push_back(arrays);
}

FileMeshes meshesOfFile(const std::string& path, const MeshReadOptions& options)
{
  LoadedBlocks loaded = loadMeshBlocks(path, options);
  FileMeshes file;
  file.warnings = std::move(loaded.warnings);
  if (loaded.blocks.size() == 1)
  {
    const fs::path p(path);
    std::string stem = p.stem().string();
    loaded.blocks[0].name = stem.empty() ? p.filename().string() : stem;
  }
  for (MeshBlock& block : loaded.blocks)
  {
    NamedMesh named;
    named.name = std::move(block.name);
    named.mesh = std::move(block.mesh);
    named.lines = block.lines;
    named.material = std::move(block.material);
    named.placement = block.placement;
    file.meshes.push_back(std::move(named));
  }
  return file;
}

std::vector<std::string> uniquePartNames(const std::vector<std::string>& names)
{
  std::set<std::string> taken;
  std::vector<std::string> unique;
  unique.reserve(names.size());
  for (const std::string& name : names)
  {
    std::string candidate = name;
    for (int i = 2; taken.count(candidate); ++i)
    {
      candidate = name + " " + std::to_string(i);
    }
    taken.insert(candidate);
    unique.push_back(candidate);
  }
  return unique;
}

std::vector<ScenePart> loadParts(const std::vector<std::string>& paths, std::ostream& warnings,
                                 const MeshReadOptions& options)
{
  std::vector<ScenePart> parts;
  std::vector<std::string> failures; // of the files that did not load
  std::vector<std::string> failed;
  std::vector<std::string> skipped; // files and blocks, in order
  for (const std::string& path : paths)
  {
    try
    {
      FileMeshes file = meshesOfFile(path, options);
      for (NamedMesh& named : file.meshes)
      {
        ScenePart part;
        part.name = std::move(named.name);
        part.source = path;
        part.mesh = std::move(named.mesh);
        part.lines = named.lines;
        part.fileMaterial = std::move(named.material);
        part.placement = named.placement;
        parts.push_back(std::move(part));
      }
      for (std::string& warning : file.warnings)
      {
        skipped.push_back(oneLine(std::move(warning)));
      }
    }
    catch (const Error& e)
    {
      if (paths.size() == 1)
      {
        throw;
      }
      failed.push_back(path);
      failures.push_back(oneLine(e.what()));
      skipped.push_back(failures.back());
    }
  }
  if (parts.empty())
  {
    std::string files;
    std::string reasons;
    for (std::size_t i = 0; i < failed.size(); ++i)
    {
      files += (i ? ", " : "") + failed[i];
      reasons += (i ? "; " : "") + failures[i];
    }
    throw errorAbout(files, "no mesh could be loaded (" + reasons + ")");
  }
  for (const std::string& warning : skipped)
  {
    warnings << "aniso: warning: " << warning << " (skipped)\n";
  }
  std::vector<std::string> names;
  for (const ScenePart& part : parts)
  {
    names.push_back(part.name);
  }
  names = uniquePartNames(names);
  for (std::size_t i = 0; i < parts.size(); ++i)
  {
    parts[i].name = names[i];
  }
  return parts;
}

void adoptFileMaterials(MaterialLibrary& library, std::vector<ScenePart>& parts)
{
  std::vector<std::string> names(parts.size());
  for (std::size_t i = 0; i < parts.size(); ++i)
  {
    if (parts[i].fileMaterial)
    {
      names[i] = library.adopt(std::move(*parts[i].fileMaterial));
      parts[i].fileMaterial.reset();
    }
  }
  // Assigned once every material is in: the library's storage moves as it grows.
  for (std::size_t i = 0; i < parts.size(); ++i)
  {
    if (!names[i].empty())
    {
      parts[i].material = &library.at(names[i]);
    }
  }
}

MaterialLibrary partLibrary(const Arguments& a)
{
  MaterialLibrary library = builtinMaterials();
  if (a.has("--materials"))
  {
    const MaterialLibrary file = readMaterialLibrary(a.text("--materials"));
    for (const Material& material : file.materials())
    {
      library.put(material);
    }
  }
  return library;
}

void checkPartOptions(const Arguments& a, const MaterialLibrary& library)
{
  if (!a.has("--part"))
  {
    return;
  }
  if (a.has("--compare") || a.text("--model") != kEnvironmentModel)
  {
    throw usageError("--part", "only applies to --model as-env (the other models draw every "
                               "part with the command line's material)");
  }
  for (const std::string& rule : a.texts("--part"))
  {
    const std::string material = splitPartRule(rule).second;
    if (!library.contains(material))
    {
      std::string known;
      for (const Material& m : library.materials())
      {
        known += (known.empty() ? "" : ", ") + m.name;
      }
      throw usageError("--part", "no material '" + material + "' in the library (" + known +
                                     (a.has("--materials") ? "" : "; --materials FILE adds more") +
                                     ")");
    }
  }
}

void assignParts(const Arguments& a, const MaterialLibrary& library, std::vector<ScenePart>& parts)
{
  for (const std::string& rule : a.texts("--part"))
  {
    const auto [pattern, material] = splitPartRule(rule);
    const Material& assigned = library.at(material);
    bool matched = false;
    for (ScenePart& part : parts)
    {
      if (matchesPartPattern(pattern, part.name))
      {
        part.material = &assigned;
        matched = true;
      }
    }
    if (!matched)
    {
      throw usageError("--part", "pattern '" + pattern +
                                     "' matches no part (the parts: " + partNames(parts) + ")");
    }
  }
  for (const std::string& pattern : a.texts("--hide"))
  {
    bool matched = false;
    for (ScenePart& part : parts)
    {
      if (matchesPartPattern(pattern, part.name))
      {
        part.visible = false;
        matched = true;
      }
    }
    if (!matched)
    {
      throw usageError("--hide", "pattern '" + pattern +
                                     "' matches no part (the parts: " + partNames(parts) + ")");
    }
  }
  bool anyVisible = false;
  for (const ScenePart& part : parts)
  {
    anyVisible = anyVisible || part.visible;
  }
  if (!anyVisible && !a.has("--list-parts") && !a.has("--list-arrays"))
  {
    throw usageError("--hide", "hides every part: nothing is left to render");
  }
}

void listParts(const std::vector<ScenePart>& parts, std::ostream& out)
{
  for (const ScenePart& part : parts)
  {
    if (part.lines)
    {
      const int64_t segments = part.mesh.report.lineSegments;
      out << part.name << "\t" << segments
          << (segments == 1 ? " line segment\t" : " line segments\t");
    }
    else
    {
      const vtkIdType triangles = part.mesh.polyData->GetNumberOfCells();
      out << part.name << "\t" << triangles << (triangles == 1 ? " triangle\t" : " triangles\t");
    }
    out << (part.material ? part.material->name : std::string("(command line)"))
        << (part.visible ? "" : "\thidden") << "\n";
  }
}

void listArrays(const std::vector<ScenePart>& parts, std::ostream& out)
{
  for (const ScenePart& part : parts)
  {
    const std::vector<ArrayInfo> arrays = describeArrays(part.mesh.polyData);
    out << part.name << (arrays.empty() ? "\t(no arrays)" : "") << "\n";
    for (const ArrayInfo& info : arrays)
    {
      out << "  " << formatArrayInfo(info) << "\n";
    }
  }
}

SurfaceOptions surfaceOptionsOf(const Material& material)
{
  SurfaceOptions options;
  const std::string& tangents = material.value("tangents").text;
  if (tangents != "auto")
  {
    options.brushing = parseBrushingModel(tangents, material.name + ": tangents");
  }
  return options;
}

Material materialOfParameters(const ParameterSet& parameters)
{
  Material material = defaultMaterial("command line");
  for (std::string_view key : materialKeys())
  {
    if (!isMaterialMapKey(key))
    {
      material.values[std::string(key)] = parameters.value(key);
    }
  }
  return material;
}

std::vector<GltfPart> gltfPartsOf(const std::vector<ScenePart>& parts,
                                  const std::vector<vtkSmartPointer<vtkPolyData>>& surfaces,
                                  const Material& commandLine)
{
  std::vector<GltfPart> out;
  for (std::size_t i = 0; i < parts.size(); ++i)
  {
    if (!parts[i].visible || parts[i].lines)
    {
      continue; // glTF's triangles only: a line set is not written
    }
    GltfPart part;
    part.name = parts[i].name;
    part.polyData = surfaces[i];
    part.material = parts[i].material ? *parts[i].material : commandLine;
    part.placement = parts[i].placement;
    out.push_back(std::move(part));
  }
  return out;
}

LineStyle lineStyleOf(const Material* material, const ParameterSet& parameters)
{
  LineStyle style;
  style.width = material ? material->value("line-width").number[0] : parameters.real("line-width");
  style.unit = parseLineWidthUnit(material ? material->value("line-width-unit").text
                                           : parameters.text("line-width-unit"));
  return style;
}

MaterialSettings librarySettingsOf(const Material& material, const ParameterSet& commandLine,
                                   std::optional<double> quality, std::ostream& out)
{
  ParameterSet parameters = commandLine;
  for (std::string_view key : materialKeys())
  {
    if (!isMaterialMapKey(key))
    {
      parameters.setValue(key, material.value(key));
    }
  }
  MaterialSettings s = materialFromParameters(parameters);
  if (quality)
  {
    const QualityChoice choice = chooseSamples(*quality, s.lobe, s.filtered);
    s.samples = choice.samples;
    out << "quality: material '" << material.name << "': " << choice.samples
        << " samples per frame for a predicted error of " << choice.predictedError
        << (choice.reachable ? "" : " (the target needs more than the largest sample count)")
        << "\n";
  }
  readMaterialMaps(material, s);
  return s;
}
} // namespace aniso::cli
