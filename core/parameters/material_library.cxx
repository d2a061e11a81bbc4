#include "core/parameters/material_library.h"

#include "core/error.h"
#include "core/maps/tpr_map.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <sstream>
#include <unistd.h>

namespace aniso
{
namespace
{
namespace fs = std::filesystem;
// Ordered: materials keep the library's order, keys the declaration order.
using Json = nlohmann::ordered_json;

constexpr int kLibraryVersion = 1;
constexpr std::string_view kLibraryFormat = "aniso-materials";

// Whether the text of map key KEY is a file path (not a built-in name or a TPR pattern).
bool isMapPath(std::string_view key, const std::string& text)
{
  if (text.empty() || text.rfind("builtin:", 0) == 0)
  {
    return false;
  }
  if (key == "tpr")
  {
    try
    {
      parseTprPattern(text);
      return false;
    }
    catch (const Error&)
    {
      return true;
    }
  }
  return true;
}

std::string relativeTo(const std::string& base, const std::string& path)
{
  if (base.empty())
  {
    return path;
  }
  std::error_code ec;
  const fs::path absolute = fs::absolute(path, ec).lexically_normal();
  const fs::path dir = fs::absolute(base, ec).lexically_normal();
  const fs::path relative = absolute.lexically_relative(dir);
  if (ec || relative.empty() || *relative.begin() == "..")
  {
    return path;
  }
  return relative.string();
}

std::string resolvedAgainst(const std::string& base, const std::string& path)
{
  if (base.empty() || fs::path(path).is_absolute())
  {
    return path;
  }
  return (fs::path(base) / path).lexically_normal().string();
}

Json valueToJson(std::string_view key, const ParameterValue& value, const std::string& base)
{
  if (isMaterialMapKey(key))
  {
    return isMapPath(key, value.text) ? relativeTo(base, value.text) : value.text;
  }
  const ParameterSpec& spec = parameterSpec(key);
  switch (spec.type)
  {
  case ParameterType::Integer:
    return static_cast<long long>(value.number[0]);
  case ParameterType::Real:
    return value.number[0];
  case ParameterType::Color:
    return Json::array({value.number[0], value.number[1], value.number[2]});
  case ParameterType::Text:
    break;
  }
  return value.text;
}

ParameterValue valueFromJson(std::string_view key, const Json& json, const std::string& base,
                             const std::string& subject)
{
  ParameterValue v;
  if (isMaterialMapKey(key))
  {
    if (!json.is_string())
    {
      throw errorAbout(subject, "expected a text (a file path, or \"\" for none)");
    }
    const std::string text = json.get<std::string>();
    v.text = isMapPath(key, text) ? resolvedAgainst(base, text) : text;
    return v;
  }
  const ParameterSpec& spec = parameterSpec(key);
  switch (spec.type)
  {
  case ParameterType::Integer:
  case ParameterType::Real:
    if (!json.is_number())
    {
      throw errorAbout(subject, "expected a number");
    }
    v.number.fill(json.get<double>());
    break;
  case ParameterType::Color:
    if (json.is_number())
    {
      v.number.fill(json.get<double>());
      break;
    }
    if (!json.is_array() || json.size() != 3 || !json[0].is_number() || !json[1].is_number() ||
        !json[2].is_number())
    {
      throw errorAbout(subject, "expected an array of three numbers");
    }
    for (int i = 0; i < 3; ++i)
    {
      v.number[i] = json[i].get<double>();
    }
    break;
  case ParameterType::Text:
    if (!json.is_string())
    {
      throw errorAbout(subject, "expected a text");
    }
    v.text = json.get<std::string>();
    break;
  }
  checkParameterValue(spec, v, subject);
  return v;
}

void checkKeys(const Material& material)
{
  for (const auto& [key, value] : material.values)
  {
    if (!isMaterialKey(key))
    {
      throw errorAbout(material.name, key + ": not a material key");
    }
    checkMaterialValue(key, value, material.name + ": " + key);
  }
}

Material withDefaults(Material material)
{
  Material full = defaultMaterial(material.name);
  for (auto& [key, value] : material.values)
  {
    full.values[key] = std::move(value);
  }
  return full;
}

Material metal(std::string name, double nu, double nv, ParameterValue f0,
               std::string tangents = "auto")
{
  Material m = defaultMaterial(std::move(name));
  m.values["nu"] = numberValue(nu);
  m.values["nv"] = numberValue(nv);
  m.values["f0"] = std::move(f0);
  m.values["tangents"] = textValue(std::move(tangents));
  return m;
}

// A glob match of the whole NAME: '*' any run, '?' one character.
bool globMatch(std::string_view p, std::string_view n)
{
  std::size_t pi = 0, ni = 0, star = std::string_view::npos, mark = 0;
  while (ni < n.size())
  {
    if (pi < p.size() && (p[pi] == '?' || p[pi] == n[ni]))
    {
      ++pi;
      ++ni;
    }
    else if (pi < p.size() && p[pi] == '*')
    {
      star = pi++;
      mark = ni;
    }
    else if (star != std::string_view::npos)
    {
      pi = star + 1;
      ni = ++mark;
    }
    else
    {
      return false;
    }
  }
  while (pi < p.size() && p[pi] == '*')
  {
    ++pi;
  }
  return pi == p.size();
}
} // namespace

const std::vector<std::string_view>& materialKeys()
{
  static const std::vector<std::string_view> keys = []
  {
    std::vector<std::string_view> k;
    for (const ParameterSpec& spec : parameterSpecs())
    {
      if (spec.scope == ParameterScope::Material)
      {
        k.push_back(spec.name);
      }
    }
    for (std::string_view map : kMaterialMapKeys)
    {
      k.push_back(map);
    }
    return k;
  }();
  return keys;
}

bool isMaterialKey(std::string_view key)
{
  const auto& keys = materialKeys();
  return std::find(keys.begin(), keys.end(), key) != keys.end();
}

bool isMaterialMapKey(std::string_view key)
{
  return std::find(std::begin(kMaterialMapKeys), std::end(kMaterialMapKeys), key) !=
         std::end(kMaterialMapKeys);
}

void checkMaterialValue(std::string_view key, const ParameterValue& value,
                        const std::string& subject)
{
  if (!isMaterialKey(key))
  {
    throw errorAbout(subject, std::string(key) + ": not a material key");
  }
  if (!isMaterialMapKey(key))
  {
    checkParameterValue(parameterSpec(key), value, subject);
  }
}

const ParameterValue& Material::value(std::string_view key) const
{
  const auto it = values.find(key);
  if (it == values.end())
  {
    throw errorAbout(name, std::string(key) + ": not a material key");
  }
  return it->second;
}

Material defaultMaterial(std::string name)
{
  Material m;
  m.name = std::move(name);
  for (std::string_view key : materialKeys())
  {
    m.values.emplace(std::string(key), isMaterialMapKey(key)
                                           ? ParameterValue{}
                                           : defaultParameterValue(parameterSpec(key)));
  }
  return m;
}

const Material* MaterialLibrary::find(std::string_view name) const
{
  const auto it = std::find_if(materials_.begin(), materials_.end(),
                               [&](const Material& m) { return m.name == name; });
  return it == materials_.end() ? nullptr : &*it;
}

const Material& MaterialLibrary::at(std::string_view name) const
{
  const Material* m = find(name);
  if (!m)
  {
    throw errorAbout(std::string(name), "no such material");
  }
  return *m;
}

void MaterialLibrary::put(const Material& material)
{
  if (material.name.empty())
  {
    throw errorAbout("material", "a material needs a name");
  }
  checkKeys(material);
  Material full = withDefaults(material);
  for (Material& m : materials_)
  {
    if (m.name == full.name)
    {
      m = std::move(full);
      return;
    }
  }
  materials_.push_back(std::move(full));
}

void MaterialLibrary::setValue(std::string_view name, std::string_view key,
                               const ParameterValue& value)
{
  checkMaterialValue(key, value, std::string(name) + ": " + std::string(key));
  for (Material& m : materials_)
  {
    if (m.name == name)
    {
      m.values[std::string(key)] = value;
      return;
    }
  }
  throw errorAbout(std::string(name), "no such material");
}

bool MaterialLibrary::remove(std::string_view name)
{
  const auto it = std::find_if(materials_.begin(), materials_.end(),
                               [&](const Material& m) { return m.name == name; });
  if (it == materials_.end())
  {
    return false;
  }
  materials_.erase(it);
  return true;
}

bool MaterialLibrary::operator==(const MaterialLibrary& o) const
{
  if (materials_.size() != o.materials_.size())
  {
    return false;
  }
  for (const Material& m : materials_)
  {
    const Material* other = o.find(m.name);
    if (!other || *other != m)
    {
      return false;
    }
  }
  return true;
}

std::string MaterialLibrary::adopt(Material material)
{
  const std::string stem = material.name.empty() ? std::string("material") : material.name;
  for (int i = 1;; ++i)
  {
    const std::string name = i == 1 ? stem : stem + " " + std::to_string(i);
    const Material* held = find(name);
    if (!held)
    {
      material.name = name;
      put(material);
      return name;
    }
    if (held->values == material.values)
    {
      return name;
    }
  }
}

std::string MaterialLibrary::uniqueName(std::string_view base) const
{
  const std::string stem = base.empty() ? std::string("material") : std::string(base);
  if (!contains(stem))
  {
    return stem;
  }
  for (int i = 2;; ++i)
  {
    std::string name = stem + " " + std::to_string(i);
    if (!contains(name))
    {
      return name;
    }
  }
}

const MaterialLibrary& builtinMaterials()
{
  // F0: the linear reflectance at normal incidence of each metal as Real-Time Rendering (4th
  // edition, table 9.2) lists it; aluminium is the declared default.
  static const MaterialLibrary library = []
  {
    MaterialLibrary l;
    l.put(defaultMaterial(std::string(kDefaultMaterialName)));
    l.put(metal(std::string(kStartMaterialName), 10000.0, 20.0, defaultMaterial({}).value("f0")));
    l.put(metal("brushed steel", 800.0, 40.0, colorValue(0.562, 0.565, 0.578)));
    l.put(metal("brushed titanium", 600.0, 60.0, colorValue(0.542, 0.497, 0.449)));
    l.put(metal("turned brass", 2000.0, 80.0, colorValue(0.910, 0.778, 0.423), "around:0,0,1"));
    l.put(metal("brushed copper", 1000.0, 50.0, colorValue(0.955, 0.638, 0.538)));
    l.put(metal("satin gold", 150.0, 150.0, colorValue(1.000, 0.782, 0.344)));
    l.put(metal("polished chromium", 10000.0, 10000.0, colorValue(0.549, 0.556, 0.554)));
    return l;
  }();
  return library;
}

std::string materialLibraryToJson(const MaterialLibrary& library, const std::string& baseDirectory)
{
  Json materials = Json::object();
  for (const Material& m : library.materials())
  {
    Json values = Json::object();
    for (std::string_view key : materialKeys())
    {
      values[std::string(key)] = valueToJson(key, m.value(key), baseDirectory);
    }
    materials[m.name] = std::move(values);
  }
  Json document = Json::object();
  document["format"] = std::string(kLibraryFormat);
  document["version"] = kLibraryVersion;
  document["materials"] = std::move(materials);
  return document.dump(2) + "\n";
}

MaterialLibrary materialLibraryFromJson(const std::string& text, const std::string& baseDirectory,
                                        const std::string& subject)
{
  Json document;
  try
  {
    document = Json::parse(text);
  }
  catch (const Json::exception& e)
  {
    std::string reason = e.what();
    const auto colon = reason.find("] ");
    if (colon != std::string::npos)
    {
      reason = reason.substr(colon + 2);
    }
    throw errorAbout(subject, "not JSON (" + reason + ")");
  }
  if (!document.is_object())
  {
    throw errorAbout(subject, "not a material library (expected a JSON object)");
  }
  const auto format = document.find("format");
  if (format == document.end() || !format->is_string() ||
      format->get<std::string>() != kLibraryFormat)
  {
    throw errorAbout(subject, "not a material library (\"format\" is not \"" +
                                  std::string(kLibraryFormat) + "\")");
  }
  const auto version = document.find("version");
  if (version == document.end() || !version->is_number_integer())
  {
    throw errorAbout(subject, "\"version\" missing or not an integer");
  }
  if (version->get<long long>() > kLibraryVersion || version->get<long long>() < 1)
  {
    throw errorAbout(subject, "version " + std::to_string(version->get<long long>()) +
                                  " (this version reads 1 to " + std::to_string(kLibraryVersion) +
                                  ")");
  }
  const auto materials = document.find("materials");
  if (materials == document.end() || !materials->is_object())
  {
    throw errorAbout(subject, "\"materials\" missing or not an object");
  }
  MaterialLibrary library;
  for (auto entry = materials->begin(); entry != materials->end(); ++entry)
  {
    const std::string& name = entry.key();
    const Json& values = entry.value();
    const std::string where = subject + ": material \"" + name + "\"";
    if (name.empty())
    {
      throw errorAbout(subject, "a material with an empty name");
    }
    if (!values.is_object())
    {
      throw errorAbout(where, "expected an object of material keys");
    }
    Material m = defaultMaterial(name);
    for (auto it = values.begin(); it != values.end(); ++it)
    {
      if (!isMaterialKey(it.key()))
      {
        throw errorAbout(where, it.key() + ": not a material key");
      }
      m.values[it.key()] = valueFromJson(it.key(), *it, baseDirectory, where + ": " + it.key());
    }
    library.put(m);
  }
  return library;
}

MaterialLibrary readMaterialLibrary(const std::string& path)
{
  std::error_code ec;
  if (fs::is_directory(path, ec))
  {
    throw errorAbout(path, "is a directory");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    throw errorAbout(path, std::string("cannot open (") + std::strerror(errno) + ")");
  }
  constexpr std::uintmax_t kMaxBytes = 16u << 20;
  const std::uintmax_t size = fs::file_size(path, ec);
  if (!ec && size > kMaxBytes)
  {
    throw errorAbout(path, "larger than a material library may be (16 MiB)");
  }
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const fs::path parent = fs::absolute(fs::path(path), ec).parent_path();
  return materialLibraryFromJson(text, parent.string(), path);
}

void writeMaterialLibrary(const std::string& path, const MaterialLibrary& library)
{
  std::error_code ec;
  const fs::path target(path);
  const fs::path parent = fs::absolute(target, ec).parent_path();
  const std::string text = materialLibraryToJson(library, parent.string());
  const fs::path temp =
      parent / ("." + target.filename().string() + ".tmp-" + std::to_string(::getpid()));
  {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    if (!out)
    {
      throw errorAbout(path, std::string("cannot write (") + std::strerror(errno) + ")");
    }
    out << text;
    out.flush();
    if (!out)
    {
      out.close();
      fs::remove(temp, ec);
      throw errorAbout(path, "cannot write (the disk may be full)");
    }
  }
  fs::rename(temp, target, ec);
  if (ec)
  {
    const std::string reason = ec.message();
    fs::remove(temp, ec);
    throw errorAbout(path, "cannot replace (" + reason + ")");
  }
}

bool matchesPartPattern(std::string_view pattern, std::string_view name)
{
  return globMatch(pattern, name);
}
} // namespace aniso
