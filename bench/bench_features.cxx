// What each shader feature costs when a scene uses it, and that it costs nothing when it does
// not: the default scene (the built-in torus, azimuth 30, elevation 35, under the studio, 512x512)
// drawn with a lean baseline material and with each feature added alone.
//
// 1. Source: the fragment code the material compiles for the baseline and for each feature,
//    after the preprocessor (the variants are #defines): its size, and whether each feature's
//    identifiers (uniforms, functions) are in it. The baseline must hold none of them.
// 2. Frame time: in each of R rounds every configuration is drawn right after the baseline (on
//    the same mesh), F frames each, the fastest after the first kept; the ratio to that baseline
//    is taken per round, and the table prints the median over the rounds and their range (wall
//    time, and the process CPU time, llvmpipe's threads included). "Parameters set, feature off"
//    rows set what a feature reads while the feature stays off: their ratio is the noise floor, and
//    should equal the baseline drawn again.
// 3. Display transform and background (drawn by the accumulation pass, not the material):
//    timed likewise through renderOffscreen, each round a fresh window.
// 4. Counters: what a redraw, a return to a variant drawn before, and a return to a lobe baked
//    before cost (shader compiles, texture uploads, LUT bakes and cache hits).
//
// Needs an X display (xvfb-run). Usage: bench_features [--rounds R] [--frames F] [--size S]
#include "bench/render_session.h"
#include "core/env/environment.h"
#include "core/error.h"
#include "core/lut/lut_cache.h"
#include "core/maps/quaternion_map.h"
#include "core/maps/tpr_map.h"
#include "vtkpasses/mesh/BuiltinMeshes.h"
#include "vtkpasses/render/DisplaySettings.h"
#include "vtkpasses/render/MaterialSettings.h"
#include "vtkpasses/render/MaterialShaderSource.h"
#include "vtkpasses/render/OffscreenRenderer.h"
#include "vtkpasses/render/ViewSettings.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <vector>
#include <vtkPointData.h>
#include <vtkPolyData.h>

namespace
{
using aniso::Image;
using aniso::MaterialSettings;
constexpr double kPi = 3.14159265358979323846;

// ---- The active fragment code of a variant -------------------------------------------------

// Evaluates a preprocessor condition made of defined(NAME), !, &&, || and parentheses (all the
// material's shaders use).
class ConditionParser
{
public:
  ConditionParser(const std::string& text, const std::set<std::string>& defined)
      : text_(text), defined_(defined)
  {
  }
  bool parse()
  {
    const bool value = parseOr();
    skipSpace();
    if (pos_ != text_.size())
      throw aniso::errorAbout("shader", "cannot evaluate #if " + text_);
    return value;
  }

private:
  void skipSpace()
  {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_])))
      ++pos_;
  }
  bool take(const char* token)
  {
    skipSpace();
    const std::size_t n = std::strlen(token);
    if (text_.compare(pos_, n, token) == 0)
    {
      pos_ += n;
      return true;
    }
    return false;
  }
  std::string identifier()
  {
    skipSpace();
    const std::size_t start = pos_;
    while (pos_ < text_.size() &&
           (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_'))
      ++pos_;
    if (start == pos_)
      throw aniso::errorAbout("shader", "cannot evaluate #if " + text_);
    return text_.substr(start, pos_ - start);
  }
  bool parseOr()
  {
    bool value = parseAnd();
    while (take("||"))
      value = parseAnd() || value;
    return value;
  }
  bool parseAnd()
  {
    bool value = parseUnary();
    while (take("&&"))
      value = parseUnary() && value;
    return value;
  }
  bool parseUnary()
  {
    if (take("!"))
      return !parseUnary();
    if (take("("))
    {
      const bool value = parseOr();
      if (!take(")"))
        throw aniso::errorAbout("shader", "unbalanced parentheses in #if " + text_);
      return value;
    }
    if (identifier() != "defined")
      throw aniso::errorAbout("shader", "only defined() is supported in #if " + text_);
    const bool parenthesised = take("(");
    const bool value = defined_.count(identifier()) > 0;
    if (parenthesised && !take(")"))
      throw aniso::errorAbout("shader", "unbalanced parentheses in #if " + text_);
    return value;
  }

  const std::string& text_;
  const std::set<std::string>& defined_;
  std::size_t pos_ = 0;
};

// The lines of SOURCE the preprocessor keeps (directives, comments and blank lines dropped):
// the code the GLSL compiler sees.
std::string activeCode(const std::string& source)
{
  struct Level
  {
    bool parentActive;
    bool taken; // a branch of this #if was active already
    bool active;
  };
  std::vector<Level> stack;
  std::set<std::string> defined;
  auto active = [&] { return stack.empty() || stack.back().active; };
  std::istringstream lines(source);
  std::string line;
  std::string code;
  while (std::getline(lines, line))
  {
    const std::size_t first = line.find_first_not_of(" \t");
    if (first != std::string::npos && line[first] == '#')
    {
      std::istringstream directive(line.substr(first + 1));
      std::string keyword;
      directive >> keyword;
      std::string rest;
      std::getline(directive, rest);
      if (keyword == "ifdef" || keyword == "ifndef" || keyword == "if")
      {
        const bool parent = active();
        bool value = false;
        if (keyword == "if")
          value = ConditionParser(rest, defined).parse();
        else
        {
          std::istringstream name(rest);
          std::string identifier;
          name >> identifier;
          value = (defined.count(identifier) > 0) == (keyword == "ifdef");
        }
        stack.push_back({parent, value, parent && value});
      }
      else if (keyword == "elif" || keyword == "else")
      {
        if (stack.empty())
          throw aniso::errorAbout("shader", "#" + keyword + " without #if");
        Level& level = stack.back();
        const bool value = keyword == "else" || ConditionParser(rest, defined).parse();
        level.active = level.parentActive && !level.taken && value;
        level.taken = level.taken || value;
      }
      else if (keyword == "endif")
      {
        if (stack.empty())
          throw aniso::errorAbout("shader", "#endif without #if");
        stack.pop_back();
      }
      else if (keyword == "define" && active())
      {
        std::istringstream name(rest);
        std::string identifier;
        name >> identifier;
        defined.insert(identifier);
      }
      continue;
    }
    if (!active())
      continue;
    const std::size_t comment = line.find("//");
    std::string kept = comment == std::string::npos ? line : line.substr(0, comment);
    if (kept.find_first_not_of(" \t") == std::string::npos)
      continue;
    code += kept;
    code += '\n';
  }
  if (!stack.empty())
    throw aniso::errorAbout("shader", "#if without #endif");
  return code;
}

// The material's fragment code for SETTINGS on a mesh with normals, tangents and, when TCOORDS,
// texture coordinates, in the order it lands in the shader.
std::string fragmentCode(const MaterialSettings& settings, bool tcoords)
{
  const aniso::MaterialShaderCode code =
      aniso::composeMaterialShaders(aniso::materialVariant(settings, true, true, tcoords));
  return activeCode(code.fragmentDeclarations + code.fragmentUniformFlow +
                    code.fragmentImplementation);
}

std::size_t countLines(const std::string& text)
{
  return std::size_t(std::count(text.begin(), text.end(), '\n'));
}

bool containsWord(const std::string& text, const std::string& word)
{
  for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1))
  {
    const bool startOk =
        at == 0 || !(std::isalnum(static_cast<unsigned char>(text[at - 1])) || text[at - 1] == '_');
    const std::size_t end = at + word.size();
    const bool endOk = end >= text.size() ||
                       !(std::isalnum(static_cast<unsigned char>(text[end])) || text[end] == '_');
    if (startOk && endOk)
      return true;
  }
  return false;
}

// ---- Procedural maps (256 x 256, row 0 at the top) -------------------------------------------

constexpr int kMapSize = 256;

// A field of bumps: h = 1/2 + 1/2 sin(2 pi 8 u) sin(2 pi 8 v).
double bumpHeight(double u, double v)
{
  return 0.5 + 0.5 * std::sin(2.0 * kPi * 8.0 * u) * std::sin(2.0 * kPi * 8.0 * v);
}

template <class Texel>
std::shared_ptr<const Image> makeMap(int channels, Texel texel)
{
  auto image = std::make_shared<Image>(kMapSize, kMapSize, channels);
  for (int y = 0; y < kMapSize; ++y)
    for (int x = 0; x < kMapSize; ++x)
    {
      const double u = (x + 0.5) / kMapSize;
      const double v = 1.0 - (y + 0.5) / kMapSize;
      const std::vector<double> value = texel(u, v);
      for (int c = 0; c < channels; ++c)
        image->at(x, y, c) = float(value[std::size_t(c)]);
    }
  return image;
}

struct Maps
{
  std::shared_ptr<const Image> normal, quaternion, tpr, height, albedo, occlusion, metallic;
};

Maps makeMaps()
{
  Maps m;
  m.height = makeMap(1, [](double u, double v) { return std::vector<double>{bumpHeight(u, v)}; });
  m.normal = makeMap(3,
                     [](double u, double v)
                     {
                       // The bumps' slope (central differences), 0.05 deep per unit of u, v.
                       const double e = 1e-3;
                       const double du = (bumpHeight(u + e, v) - bumpHeight(u - e, v)) / (2 * e);
                       const double dv = (bumpHeight(u, v + e) - bumpHeight(u, v - e)) / (2 * e);
                       const double k = 0.05;
                       const double length = std::sqrt(1.0 + k * k * (du * du + dv * dv));
                       return std::vector<double>{-k * du / length, -k * dv / length, 1.0 / length};
                     });
  m.quaternion = std::make_shared<Image>(aniso::bakeQuaternionMap(*m.normal, false, nullptr));
  m.tpr = std::make_shared<Image>(
      aniso::bakeTprMap(aniso::parseTprPattern("circular"), kMapSize, kMapSize));
  m.albedo = makeMap(
      3,
      [](double u, double v)
      {
        const bool dark = (int(u * 8.0) + int(v * 8.0)) % 2 != 0;
        return dark ? std::vector<double>{0.2, 0.1, 0.05} : std::vector<double>{0.8, 0.7, 0.6};
      });
  m.occlusion = makeMap(1, [](double u, double v)
                        { return std::vector<double>{0.5 + 0.5 * bumpHeight(u, v)}; });
  m.metallic = makeMap(1, [](double u, double)
                       { return std::vector<double>{int(u * 16.0) % 2 ? 1.0 : 0.0}; });
  return m;
}

// ---- Configurations --------------------------------------------------------------------------

MaterialSettings baselineMaterial()
{
  MaterialSettings s;
  s.lobe = {1000.0, 50.0}; // the application's default material
  s.albedo = glm::dvec3(0.0);
  s.samples = 16;
  s.method = aniso::SpecularMethod::Exact;
  s.filtered = false;
  s.halfVectors = aniso::HalfVectorSource::Lut;
  s.environmentSampling = aniso::EnvironmentSampling::Off;
  return s;
}

struct Feature
{
  std::string name;
  bool featureOn = true; // false: the feature's parameters are set but it stays off
  bool tcoords = true;   // false: drawn on the torus without its texture coordinates
  MaterialSettings material;
  std::vector<std::string> identifiers; // in the fragment code only when the feature is on
};

std::vector<Feature> materialFeatures(const Maps& maps)
{
  const MaterialSettings base = baselineMaterial();
  std::vector<Feature> f;
  auto add = [&](std::string name, std::vector<std::string> identifiers,
                 const std::function<void(MaterialSettings&)>& change, bool on = true,
                 bool tcoords = true)
  {
    MaterialSettings s = base;
    change(s);
    f.push_back({std::move(name), on, tcoords, s, std::move(identifiers)});
  };
  add("baseline", {}, [](MaterialSettings&) {});
  add(
      "baseline drawn again", {}, [](MaterialSettings&) {}, false);
  add(
      "height scale 0.08 set, no height map", {}, [](MaterialSettings& s) { s.heightScale = 0.08; },
      false);
  add(
      "LUT size 256, 4096 LUT samples set (exact: no BRDF LUT)", {},
      [](MaterialSettings& s)
      {
        s.lutSize = 256;
        s.brdfLutSamples = 4096;
      },
      false);
  add("SH9 diffuse: albedo 0.5 (a uniform: always compiled)", {},
      [](MaterialSettings& s) { s.albedo = glm::dvec3(0.5); });
  add("normal map", {"anisoNormalMap"}, [&](MaterialSettings& s) { s.normalMap = maps.normal; });
  add("quaternion map", {"anisoQuaternionMap"},
      [&](MaterialSettings& s) { s.quaternionMap = maps.quaternion; });
  add("TPR map", {"anisoTprMap"}, [&](MaterialSettings& s) { s.tprMap = maps.tpr; });
  add("height map (parallax occlusion)",
      {"anisoHeightMap", "anisoHeightScale", "anisoParallaxOcclusion"},
      [&](MaterialSettings& s) { s.heightMap = maps.height; });
  add("albedo map", {"anisoAlbedoMap"}, [&](MaterialSettings& s) { s.albedoMap = maps.albedo; });
  add("occlusion map", {"anisoOcclusionMap"},
      [&](MaterialSettings& s) { s.occlusionMap = maps.occlusion; });
  add("metallic map", {"anisoMetallicMap"},
      [&](MaterialSettings& s) { s.metallicMap = maps.metallic; });
  // Its uniforms (anisoLodAnisotropy, anisoLodBias, ...) stay declared; unread, the GLSL
  // compiler drops them.
  add("filtered sampling", {"log2SampleSolidAngle"},
      [](MaterialSettings& s) { s.filtered = true; });
  add("split sum (BRDF LUT)", {"anisoBrdfLut", "anisoBrdfLutCoords"},
      [](MaterialSettings& s) { s.method = aniso::SpecularMethod::SplitSum; });
  add("half vectors in the shader (no LUT)", {"anisoExponents", "log2CosTheta"},
      [](MaterialSettings& s) { s.halfVectors = aniso::HalfVectorSource::Shader; });
  add("environment MIS",
      {"anisoEnvCdf", "anisoEnvPdf", "anisoEnvGuide", "anisoSampleEnvironment",
       "anisoLobeFraction"},
      [](MaterialSettings& s) { s.environmentSampling = aniso::EnvironmentSampling::Mis; });
  add(
      "no texture coordinates: baseline", {}, [](MaterialSettings&) {}, true, false);
  add(
      "no texture coordinates: all seven maps given (dropped)", {},
      [&](MaterialSettings& s)
      {
        s.normalMap = maps.normal;
        s.quaternionMap = nullptr; // at most one of normal and quaternion map
        s.tprMap = maps.tpr;
        s.heightMap = maps.height;
        s.albedoMap = maps.albedo;
        s.occlusionMap = maps.occlusion;
        s.metallicMap = maps.metallic;
      },
      false, false);
  return f;
}

// ---- Statistics ------------------------------------------------------------------------------

double median(std::vector<double> v)
{
  if (v.empty())
    return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// The fastest of the frames after the first (which may compile a shader or upload a texture):
// on a machine shared with other work, the frame least slowed down by it.
aniso::bench::FrameTime steadyFrame(const std::vector<aniso::bench::FrameTime>& frames)
{
  aniso::bench::FrameTime best{1e30, 1e30};
  for (std::size_t i = 1; i < frames.size(); ++i)
  {
    best.wall = std::min(best.wall, frames[i].wall);
    best.cpu = std::min(best.cpu, frames[i].cpu);
  }
  return best;
}

struct Ratios
{
  std::vector<double> wall;
  std::vector<double> cpu;
  std::vector<double> frame; // this configuration's frame (wall) in each round
};

// One table row per configuration: the median ratio over the rounds, their range, the median
// CPU ratio (when measured) and the configuration's median frame.
void printRatioTable(const char* heading, const std::vector<std::string>& names,
                     const std::vector<bool>& featureOn, const std::vector<Ratios>& ratios,
                     bool withCpu)
{
  std::printf("%s\n\n| Configuration | Feature | Wall ratio (median) | Wall ratio (range) |%s "
              "Frame (median) |\n| --- | --- | --- | --- |%s --- |\n",
              heading, withCpu ? " CPU ratio (median) |" : "", withCpu ? " --- |" : "");
  for (std::size_t i = 0; i < names.size(); ++i)
  {
    const Ratios& r = ratios[i];
    const auto [lo, hi] = std::minmax_element(r.wall.begin(), r.wall.end());
    std::printf("| %s | %s | %.3f | %.2f-%.2f |", names[i].c_str(),
                featureOn[i] ? "on" : "off, parameters set", median(r.wall), *lo, *hi);
    if (withCpu)
      std::printf(" %.3f |", median(r.cpu));
    std::printf(" %.1f ms |\n", 1e3 * median(r.frame));
  }
  std::fflush(stdout);
}

// ---- Counters --------------------------------------------------------------------------------

struct Snapshot
{
  aniso::bench::SessionCounters session;
  aniso::LutCacheStats lut;
};

Snapshot snapshot(const aniso::bench::RenderSession& session)
{
  return {session.counters(), aniso::LutCache::shared().stats()};
}

void printCounterRow(const char* change, const Snapshot& before, const Snapshot& after)
{
  std::printf(
      "| %s | %llu | %llu | %llu | %llu | %llu |\n", change,
      static_cast<unsigned long long>(after.session.shaderPrograms - before.session.shaderPrograms),
      static_cast<unsigned long long>(after.session.textureUploads - before.session.textureUploads),
      static_cast<unsigned long long>(after.lut.bakes - before.lut.bakes),
      static_cast<unsigned long long>(after.lut.memoryHits - before.lut.memoryHits),
      static_cast<unsigned long long>(after.lut.diskHits - before.lut.diskHits));
}
} // namespace

int main(int argc, char** argv)
{
  int rounds = 5;
  int frames = 4;
  int size = 512;
  for (int i = 1; i < argc; ++i)
  {
    if (std::strcmp(argv[i], "--rounds") == 0 && i + 1 < argc)
      rounds = std::max(1, std::atoi(argv[++i]));
    else if (std::strcmp(argv[i], "--frames") == 0 && i + 1 < argc)
      frames = std::max(2, std::atoi(argv[++i]));
    else if (std::strcmp(argv[i], "--size") == 0 && i + 1 < argc)
      size = std::max(16, std::atoi(argv[++i]));
    else
    {
      std::fprintf(stderr, "usage: %s [--rounds R] [--frames F] [--size S]\n", argv[0]);
      return 2;
    }
  }
  try
  {
    const Maps maps = makeMaps();
    const std::vector<Feature> features = materialFeatures(maps);

    // 1. The compiled fragment code.
    const std::string baselineCode = fragmentCode(features.front().material, true);
    std::printf("## Fragment code after the preprocessor (the material's part)\n\n"
                "Baseline: %zu lines, %zu characters.\n\n"
                "| Configuration | Lines | Characters | Feature identifiers | In the baseline | "
                "In this variant |\n| --- | --- | --- | --- | --- | --- |\n",
                countLines(baselineCode), baselineCode.size());
    bool baselineClean = true;
    for (const Feature& f : features)
    {
      const std::string code = fragmentCode(f.material, f.tcoords);
      std::string names;
      int inBaseline = 0;
      int inVariant = 0;
      for (const std::string& id : f.identifiers)
      {
        names += (names.empty() ? "" : ", ") + id;
        inBaseline += containsWord(baselineCode, id) ? 1 : 0;
        inVariant += containsWord(code, id) ? 1 : 0;
      }
      baselineClean = baselineClean && inBaseline == 0;
      const bool sameAsBaseline = code == baselineCode;
      std::printf("| %s | %zu | %zu | %s | %d of %zu | %s |\n", f.name.c_str(), countLines(code),
                  code.size(), names.empty() ? "-" : names.c_str(), inBaseline,
                  f.identifiers.size(),
                  f.identifiers.empty()
                      ? (sameAsBaseline ? "code identical to the baseline's" : "code differs")
                      : (std::to_string(inVariant) + " of " + std::to_string(f.identifiers.size()))
                            .c_str());
    }
    std::printf("\nBaseline free of every feature's identifiers: %s\n\n",
                baselineClean ? "yes" : "NO");

    // 2. Frame time of each material feature, interleaved.
    aniso::bench::RenderSession session(size, size);
    aniso::ViewSettings view;
    view.direction = aniso::viewDirectionFromAngles(30.0, 35.0);
    vtkSmartPointer<vtkPolyData> torus = aniso::makeTorus();
    auto bare = vtkSmartPointer<vtkPolyData>::New();
    bare->DeepCopy(torus);
    bare->GetPointData()->RemoveArray(aniso::kTCoordsArray);
    auto studio = std::make_shared<aniso::StudioEnvironment>();
    session.setSurface(torus, view);
    session.setEnvironment(studio, 256);
    std::vector<Ratios> ratios(features.size());
    bool tcoordsShown = true;
    auto draw = [&](const Feature& f)
    {
      if (f.tcoords != tcoordsShown)
      {
        session.setSurface(f.tcoords ? torus : bare, view);
        tcoordsShown = f.tcoords;
      }
      session.useMaterial(f.material);
      return steadyFrame(session.render(frames));
    };
    const Feature& baseline = features.front();
    const Feature& bareBaseline = *std::find_if(features.begin(), features.end(),
                                                [](const Feature& f) { return !f.tcoords; });
    // Round -1 warms up: every variant compiled, every texture uploaded, not counted. In each
    // round every configuration is drawn right after the baseline on the same mesh, and its
    // ratio is to that baseline: a change of the machine's load in between is short.
    for (int round = -1; round < rounds; ++round)
    {
      for (std::size_t i = 0; i < features.size(); ++i)
      {
        const aniso::bench::FrameTime base = draw(features[i].tcoords ? baseline : bareBaseline);
        const aniso::bench::FrameTime time = draw(features[i]);
        if (round < 0)
          continue;
        ratios[i].wall.push_back(time.wall / base.wall);
        ratios[i].cpu.push_back(time.cpu / base.cpu);
        ratios[i].frame.push_back(time.wall);
      }
      if (round < 0)
        std::printf("Renderer: %s; %dx%d, torus, studio, %d rounds; each configuration after "
                    "the baseline, %d frames each, the fastest of all but the first kept\n\n",
                    session.rendererName().c_str(), size, size, rounds, frames);
    }
    std::vector<std::string> names;
    std::vector<bool> featureOn;
    for (const Feature& f : features)
    {
      names.push_back(f.name);
      featureOn.push_back(f.featureOn);
    }
    printRatioTable("## Frame time against the baseline drawn just before", names, featureOn,
                    ratios, true);

    // 3. Display transform and background: the accumulation pass's variants.
    struct DisplayCase
    {
      std::string name;
      bool featureOn;
      aniso::DisplaySettings display;
    };
    aniso::DisplaySettings displayBase;
    displayBase.background = aniso::BackgroundMode::Transparent;
    displayBase.toneMapping = aniso::ToneMapping::Clamp;
    std::vector<DisplayCase> displays;
    displays.push_back({"transparent background, clamp (baseline)", true, displayBase});
    displays.push_back({"baseline drawn again", false, displayBase});
    {
      aniso::DisplaySettings d = displayBase;
      d.exposureEV = 1.0;
      d.backgroundColor = glm::dvec3(0.5, 0.2, 0.1);
      displays.push_back({"exposure +1 EV and background colour set", false, d});
      d = displayBase;
      d.toneMapping = aniso::ToneMapping::Aces;
      displays.push_back({"ACES tone mapping", true, d});
      d.toneMapping = aniso::ToneMapping::Reinhard;
      displays.push_back({"Reinhard tone mapping", true, d});
      d = displayBase;
      d.background = aniso::BackgroundMode::Color;
      displays.push_back({"background colour", true, d});
      d.background = aniso::BackgroundMode::Environment;
      displays.push_back({"background environment", true, d});
    }
    std::vector<Ratios> displayRatios(displays.size());
    auto drawDisplay = [&](const aniso::DisplaySettings& display)
    {
      aniso::RenderSettings r;
      r.surface = torus;
      r.environment = studio;
      r.material = baselineMaterial();
      r.display = display;
      r.view = view;
      r.width = size;
      r.height = size;
      r.frames = frames;
      r.jitter = false;
      const aniso::RenderResult result = aniso::renderOffscreen(r);
      return *std::min_element(result.frameSeconds.begin() + 1, result.frameSeconds.end());
    };
    for (int round = -1; round < rounds; ++round)
      for (std::size_t i = 0; i < displays.size(); ++i)
      {
        const double base = drawDisplay(displays.front().display);
        const double time = drawDisplay(displays[i].display);
        if (round < 0)
          continue;
        displayRatios[i].wall.push_back(time / base);
        displayRatios[i].frame.push_back(time);
      }
    names.clear();
    featureOn.clear();
    for (const DisplayCase& c : displays)
    {
      names.push_back(c.name);
      featureOn.push_back(c.featureOn);
    }
    printRatioTable("\n## Display transform and background (renderOffscreen, wall time only)",
                    names, featureOn, displayRatios, false);

    // 4. Counters: what each change costs the next frame.
    std::printf("\n## What the next frame redoes (counters)\n\n"
                "| Change | Shader compiles | Texture uploads | LUT bakes | LUT memory hits | "
                "LUT disk hits |\n| --- | --- | --- | --- | --- | --- |\n");
    session.setSurface(torus, view);
    MaterialSettings s = baselineMaterial();
    session.useMaterial(s);
    session.render(1);
    auto step = [&](const char* change, const std::function<void()>& apply)
    {
      const Snapshot before = snapshot(session);
      apply();
      session.useMaterial(s);
      session.render(1);
      printCounterRow(change, before, snapshot(session));
    };
    step("nothing (the view drawn again)", [] {});
    step("samples 16 -> 32, F0, albedo, height scale (uniforms)",
         [&]
         {
           s.samples = 32;
           s.f0 = glm::dvec3(0.9, 0.6, 0.5);
           s.albedo = glm::dvec3(0.2);
           s.heightScale = 0.05;
         });
    step("normal map added (a variant drawn before, its texture released since)",
         [&] { s.normalMap = maps.normal; });
    step("normal map removed", [&] { s.normalMap = nullptr; });
    step("the same normal map image added again", [&] { s.normalMap = maps.normal; });
    step("a new normal map image (same content, new image)",
         [&] { s.normalMap = std::make_shared<Image>(*maps.normal); });
    step("normal map removed again", [&] { s.normalMap = nullptr; });
    step("environment MIS on (a variant drawn before)",
         [&] { s.environmentSampling = aniso::EnvironmentSampling::Mis; });
    step("environment MIS off", [&] { s.environmentSampling = aniso::EnvironmentSampling::Off; });
    step("n_u, n_v to (3000, 70): a new half-vector LUT", [&] { s.lobe = {3000.0, 70.0}; });
    step("n_u, n_v back to (1000, 50): LUT cache hit", [&] { s.lobe = {1000.0, 50.0}; });
    const aniso::bench::SessionCounters total = session.counters();
    std::printf("\nWhole session: %llu shader programs, %llu texture uploads, %llu LUT bakes.\n",
                static_cast<unsigned long long>(total.shaderPrograms),
                static_cast<unsigned long long>(total.textureUploads),
                static_cast<unsigned long long>(total.lutBakes));
    return baselineClean ? 0 : 1;
  }
  catch (const std::exception& e)
  {
    std::fprintf(stderr, "bench_features: %s\n", e.what());
    return 1;
  }
}
