#include "app/render_command.h"

#include "app/cli.h"
#include "app/render_models.h"
#include "app/render_parts.h"
#include "app/render_reference.h"
#include "app/render_turntable.h"
#include "core/env/env_source_text.h"
#include "core/env/env_sources.h"
#include "core/env/environment.h"
#include "core/error.h"
#include "core/image/image.h"
#include "core/maps/map_files.h"
#include "core/maps/quaternion_map.h"
#include "core/parameters/choices.h"
#include "core/parameters/parameters.h"
#include "core/quality/adaptive_quality.h"
#include "core/quality/error_estimate.h"
#include "vtkpasses/mesh/BrushingModel.h"
#include "vtkpasses/mesh/BuiltinMeshes.h"
#include "vtkpasses/mesh/GltfWriter.h"
#include "vtkpasses/mesh/MeshLoader.h"
#include "vtkpasses/mesh/PartPlacement.h"
#include "vtkpasses/mesh/SurfacePreparation.h"
#include "vtkpasses/render/FieldValues.h"
#include "vtkpasses/render/OffscreenRenderer.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <memory>
#include <numeric>
#include <optional>
#include <set>
#include <sstream>
#include <vtkPointData.h>
#include <vtkPolyData.h>

namespace aniso::cli
{
namespace
{
namespace fs = std::filesystem;

constexpr int kMaxSide = 16384;

// The declared parameters this command takes, as --NAME options.
const char* const kDeclared[] = {"env",          "env-rotation", "nu",       "nv",
                                 "f0",           "albedo",       "method",   "filtered",
                                 "half-vectors", "samples",      "lut-size", "lut-samples",
                                 "cube-size",    "height-scale", "exposure", "tone-mapping",
                                 "env-sampling", "line-width",   "line-width-unit",
                                 "field",        "field-target", "field-colormap",
                                 "field-range",  "field-low",    "field-high",
                                 "legend"};

// "a|b|c" as "a | b | c", so that help texts can wrap between the alternatives.
std::string spacedChoices(const std::string& syntax)
{
  std::string out;
  for (char ch : syntax)
  {
    out += ch == '|' ? std::string(" | ") : std::string(1, ch);
  }
  return out;
}

// OPTION listed under GROUP in the help.
Option in(const char* group, Option option)
{
  option.group = group;
  return option;
}

Option declared(const char* name)
{
  Option o = parameterOption(name);
  // The relief depth serves the height map; the cubemap's size is how the environment is
  // sampled.
  if (o.spec.name == "height-scale")
  {
    o.group = kGroupMaps;
  }
  if (o.spec.name == "cube-size")
  {
    o.group = kGroupSampling;
  }
  for (std::string_view choice : o.spec.choices)
  {
    o.choices.emplace_back(choice);
  }
  if (std::string(name) == "env")
  {
    o.valueName = "FILE|builtin:NAME";
  }
  // A field that drives the material is read as the maps are; its legend is drawn on the image.
  if (o.spec.name.rfind("field", 0) == 0)
  {
    o.group = kGroupMaps;
  }
  if (o.spec.name == "legend")
  {
    o.group = kGroupOutput;
  }
  if (o.spec.name == "field")
  {
    o.valueName = "none|NAME[:magnitude|x|y|z|N]";
  }
  if (o.spec.name == "field-range")
  {
    o.valueName = "auto|MIN,MAX";
  }
  return o;
}

Option numberOption(std::string name, std::string valueName, ParameterType type, double value,
                    double minimum, double maximum, std::string_view unit, std::string_view help)
{
  Option o;
  o.name = std::move(name);
  o.valueName = std::move(valueName);
  o.spec.type = type;
  o.spec.defaultValue = {value, 0.0, 0.0};
  o.spec.minimum = minimum;
  o.spec.maximum = maximum;
  o.spec.unit = unit;
  o.spec.help = help;
  return o;
}

Option flagOption(std::string name, std::string_view help)
{
  Option o;
  o.name = std::move(name);
  o.spec.type = ParameterType::Text;
  o.spec.help = help;
  return o;
}

Command renderCommand()
{
  Command c;
  c.usage = "aniso render [MESH...] [options] -o FILE";
  c.summary = "Render MESH (OBJ, PLY, STL, OFF, VTK, VTP, glTF, STEP, IGES) or a built-in mesh "
              "with an "
              "anisotropic Ashikhmin-Shirley material under image-based lighting, without a "
              "window, to a PNG (tone-mapped 8-bit sRGB) or an EXR (linear float radiance, alpha "
              "= coverage). Several meshes make a scene of parts, drawn together with the camera "
              "fitting them all, each with its own material (--part): one a file, or one a "
              "block of a file (OBJ groups and objects, VTM blocks, glTF mesh nodes, STEP and IGES "
              "parts). Needs an X display; where there is none, run it under xvfb-run.";
  c.positionals = {"MESH"};
  c.lastPositionalRepeats = true;
  c.grouped = true;
  Option builtin = textOption("--builtin", "NAME", "render a built-in mesh instead of a file");
  builtin.choices = {"sphere", "torus", "plate", "disk"};
  builtin.group = kGroupScene;
  c.options.push_back(builtin);
  for (const char* name : kDeclared)
  {
    c.options.push_back(declared(name));
  }
  c.options.push_back(in(
      kGroupSampling, numberOption("--frames", "N", ParameterType::Integer, 4.0, 1.0, 65536.0, {},
                                   "progressive frames accumulated, each with a rotated sample set "
                                   "(N x samples per pixel)")));
  // The error target's default and range are the declared error-target's (the window's).
  const ParameterSpec& errorTarget = parameterSpec("error-target");
  c.options.push_back(in(
      kGroupSampling,
      numberOption(
          "--converge", "ERR", errorTarget.type, errorTarget.defaultValue[0], errorTarget.minimum,
          errorTarget.maximum, errorTarget.unit,
          "accumulate frames until the image's relative L2 error, estimated from its own frames "
          "(the mean against the mean of its first half, after 4, 6, 8, 12, 16, 24, ... frames), "
          "is at most 3/4 ERR (the estimate's measured spread), from 256 samples a pixel on, as "
          "the window's still view does with quality-mode error; --frames is then the most "
          "(without it, target-samples' default in frames)")));
  c.options.push_back(in(
      kGroupSampling,
      numberOption(
          "--quality", "ERR", errorTarget.type, errorTarget.defaultValue[0], errorTarget.minimum,
          errorTarget.maximum, errorTarget.unit,
          "error target instead of --samples: the relative L2 error of one frame (0.01 = 1%); the "
          "samples follow from the material's roughness and filtering, by the error model that "
          "'aniso bench' measured")));
  c.options.push_back(in(
      kGroupMaps,
      textOption(
          "--normal-map", "FILE",
          "tangent-space normal map; its quaternion map is baked and used unless --bump normal")));
  c.options.push_back(in(
      kGroupMaps,
      textOption("--quaternion-map", "FILE",
                 "quaternion map (a, b, c), stored like a normal map (8/16-bit files as 2c - 1)")));
  Option bump = textOption(
      "--bump", "MODE",
      "how --normal-map perturbs the frame: the baked quaternion frame (the source's method) or "
      "the normal alone with the tangent re-orthogonalised",
      "quaternion");
  bump.choices = {"quaternion", "normal"};
  bump.group = kGroupMaps;
  c.options.push_back(bump);
  c.options.push_back(
      in(kGroupMaps,
         textOption(
             "--tpr", "PATTERN|FILE",
             "tangent-plane rotation map: a file (2 channels x, y, or 1 channel angle in [0, pi]) "
             "or a "
             "pattern linear[:ANGLE], circular[:U,V], radial[:U,V], spiral[:U,V[:PITCH]], wave")));
  c.options.push_back(
      in(kGroupMaps,
         textOption("--height-map", "FILE",
                    "height map (first channel, 1 = top) for parallax occlusion mapping")));
  // Option help is a string_view: the composed text must outlive the command table.
  static const std::string tangentsHelp =
      "tangent field: " + spacedChoices(brushingModelSyntax()) +
      "; by default the mesh's own, else from its UVs, else axis:1,0,0";
  c.options.push_back(in(kGroupMaterial, textOption("--tangents", "MODEL", tangentsHelp)));
  // The declared cad-deflection is the window's (relative only); the command line also takes a
  // length.
  static const std::string deflectionDefault =
      formatNumber(parameterSpec("cad-deflection").defaultValue[0]);
  c.options.push_back(
      in(kGroupScene,
         textOption(
             "--cad-deflection", "F|Lmm",
             "STEP and IGES: the largest distance of a triangle from its face, as a fraction F of "
             "each "
             "part's bounding-box diagonal (0.0005: finer) or as a length in millimetres (0.05mm)",
             deflectionDefault)));
  c.options.push_back(parameterOption("cad-angle"));
  c.options.push_back(
      in(kGroupOutput, textOption("--size", "WxH", "image size in pixels", "512x512")));
  // The named views are the window's View menu's (viewPresets); help texts are string_views.
  static const std::string viewHelp =
      "camera looking at the centre, Z up: three-quarter (from the front left, azimuth " +
      formatNumber(kDefaultViewAzimuth) + ", and above, elevation " +
      formatNumber(kDefaultViewElevation) +
      ": a flat part is seen from above), or from one side of the object";
  static const std::string defaultView = defaultViewName();
  Option view = textOption("--view", "NAME", viewHelp, defaultView);
  view.group = kGroupView;
  for (const ViewPreset& preset : viewPresets())
  {
    view.choices.push_back(preset.name);
  }
  c.options.push_back(view);
  c.options.push_back(in(
      kGroupView, numberOption("--azimuth", "DEG", ParameterType::Real, 0.0, -360.0, 360.0, "deg",
                               "camera direction instead of --view: 0 on the -Y side, 90 on +X")));
  c.options.push_back(
      in(kGroupView, numberOption("--elevation", "DEG", ParameterType::Real, 0.0, -90.0, 90.0,
                                  "deg", "camera height above the XY plane, with --azimuth")));
  c.options.push_back(in(
      kGroupOutput,
      numberOption(
          "--turntable", "N", ParameterType::Integer, 36.0, 1.0, 3600.0, {},
          "N images turning the camera about +Z around the parts' centre from the view's azimuth, "
          "written as OUT_0000.png, OUT_0001.png, ... (OUT: --output's stem, its extension kept)")));
  c.options.push_back(
      in(kGroupView, flagOption("--ortho", "parallel projection (the view fits the object)")));
  c.options.push_back(in(kGroupOutput, textOption("--background", "env|none|R,G,B",
                                                  "behind the object: the environment, nothing "
                                                  "(transparent PNG), or a uniform linear radiance",
                                                  "env")));
  Option jitter = textOption(
      "--jitter", "on|off",
      "sub-pixel camera jitter between frames (anti-aliased edges, fractional coverage)", "on");
  jitter.choices = {"on", "off"};
  jitter.group = kGroupSampling;
  c.options.push_back(jitter);
  Option output = textOption("--output", "FILE",
                             "the image to write: .png or .exr (not with --list-parts or "
                             "--list-arrays; may be left out with "
                             "--export-gltf)");
  output.alias = "-o";
  output.required = true;
  output.group = kGroupOutput;
  c.options.push_back(output);
  c.options.push_back(
      in(kGroupOutput,
         textOption(
             "--export-gltf", "FILE",
             "write the scene's visible parts as glTF 2.0 (.glb, or .gltf with its buffer inside): "
             "each part's prepared surface (normals, tangents, UVs) in its own frame, its "
             "placement as "
             "its node's matrix, and the material it is drawn with, the library's or the command "
             "line's, as metallic-roughness with KHR_materials_anisotropy (maps and fields are "
             "not written); "
             "besides the image, or instead of it without -o")));
  c.options.push_back(
      in(kGroupOutput,
         textOption("--reference", "FILE",
                    "write the CPU reference of the rendered view as EXR (linear RGBA float, each "
                    "computed pixel over its N x N block, alpha 0 where none was) and print the "
                    "render's relative L2 error against it; for the as-env model without maps, "
                    "fields or line parts")));
  c.options.push_back(
      in(kGroupOutput,
         textOption("--error-map", "FILE",
                    "write |render - reference| / rms(reference) per compared pixel: .exr one "
                    "channel, NaN elsewhere; .png a Viridis heat map over [0, E], E the 99th "
                    "percentile, over each pixel's block, transparent elsewhere (with or without "
                    "--reference)")));
  c.options.push_back(
      in(kGroupOutput,
         numberOption("--reference-step", "N", ParameterType::Integer, 2.0, 1.0, 1024.0, {},
                      "the reference at every Nth pixel in x and y, from N/2 (2: a quarter of "
                      "the pixels)")));
  c.options.push_back(
      in(kGroupOutput,
         numberOption("--reference-tolerance", "T", ParameterType::Real, 1e-3, 1e-6, 0.5, {},
                      "the reference integrator's relative tolerance per pixel (on luminance)")));
  c.options.push_back(
      in(kGroupOutput,
         flagOption("--time", "print the median frame time and the samples per second")));
  addPartOptions(c);
  addModelOptions(c);
  c.details = "Examples:\n"
              "  aniso render --builtin sphere --nu 20000 --nv 70 -o sphere.png\n"
              "  aniso render part.stl --tangents around:0,0,1 --frames 16 -o part.exr\n"
              "  aniso render --builtin plate --tpr circular --view +z --time -o disc.png\n"
              "  aniso render --builtin sphere --model ward --light dir:1,-1,1:3 -o ward.png\n"
              "  aniso render body.stl lid.stl --part 'lid*=satin gold' --hide body -o lid.png\n"
              "  aniso render *.ply --materials shop.json --part '*=brushed steel' --list-parts\n"
              "  aniso render scene.glb --part 'shaft*=brushed steel' --export-gltf out.glb\n"
              "  aniso render flow.vtp --list-arrays\n"
              "  aniso render flow.vtp --tangents array:velocity -o flow.png\n"
              "  aniso render --builtin sphere -o s.exr --reference r.exr --error-map e.png\n";
  return c;
}

// MESH is optional when --builtin is given: parse with it, then without if it is missing.
// --output is required unless --list-parts, --list-arrays or --export-gltf is given.
Arguments parse(Command command, const std::vector<std::string>& args)
{
  for (Option& option : command.options)
  {
    if (option.name == "--output")
    {
      option.required = false;
    }
  }
  const auto checkOutputGiven = [](const Arguments& a)
  {
    if (!a.helpRequested && !a.has("--list-parts") && !a.has("--list-arrays") &&
        !a.has("--output") && !a.has("--export-gltf"))
    {
      throw usageError("-o", "missing FILE (required)");
    }
    return a;
  };
  try
  {
    return checkOutputGiven(parseArguments(command, args));
  }
  catch (const UsageError& e)
  {
    if (std::string(e.what()).rfind("MESH: missing argument", 0) != 0)
    {
      throw;
    }
    Command withoutMesh = command;
    withoutMesh.positionals.clear();
    Arguments a = parseArguments(withoutMesh, args);
    if (!a.has("--builtin") && !a.helpRequested)
    {
      throw usageError("MESH", "missing argument (or give --builtin)");
    }
    return checkOutputGiven(a);
  }
}

// The view of --view, or --azimuth and --elevation, and --ortho (the three-quarter view by
// default, as the window's).
ViewSettings viewOf(const Arguments& a)
{
  if (a.has("--view") && (a.has("--azimuth") || a.has("--elevation")))
  {
    throw usageError("--view", "give either --view or --azimuth/--elevation");
  }
  ViewSettings view = defaultViewSettings();
  try
  {
    view.direction = a.has("--azimuth") || a.has("--elevation")
                         ? viewDirectionFromAngles(a.real("--azimuth"), a.real("--elevation"))
                         : viewDirectionFromName(a.text("--view"), "--view");
  }
  catch (const Error& e)
  {
    throw UsageError(e.what());
  }
  view.parallel = a.has("--ortho");
  return view;
}

std::string lowercaseExtension(const std::string& path)
{
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  return ext;
}

// OUTPUT must end in FIRST or SECOND and its directory exist.
void checkOutput(const std::string& output, const char* first = ".png", const char* second = ".exr")
{
  const std::string ext = lowercaseExtension(output);
  if (ext != first && ext != second)
  {
    throw usageError(output, std::string("output file must end in ") + first + " or " + second);
  }
  std::error_code ec;
  const fs::path parent =
      fs::path(output).has_parent_path() ? fs::path(output).parent_path() : fs::path(".");
  if (!fs::is_directory(parent, ec))
  {
    throw errorAbout(output, "directory '" + parent.string() + "' does not exist");
  }
  if (fs::is_directory(output, ec))
  {
    throw errorAbout(output, "is a directory");
  }
}

// The parts of the command line: the built-in mesh, or every MESH file.
std::vector<ScenePart> scenePartsOf(const Arguments& a, std::ostream& warnings,
                                    const MeshReadOptions& options)
{
  if (a.has("--builtin"))
  {
    if (!a.positionals.empty())
    {
      throw usageError(a.positionals[0], "give either MESH or --builtin");
    }
    ScenePart part;
    part.name = a.text("--builtin");
    part.source = "builtin:" + a.text("--builtin");
    part.mesh = makeBuiltinMesh(parseBuiltinMesh(a.text("--builtin")));
    return {part};
  }
  return loadParts(a.positionals, warnings, options);
}

// PART's surface prepared with OPTIONS in the part's own frame (a tangent model's axes are the
// part's; placedSurface places it), the notes of its loading and preparation on OUT (each
// naming the part when there are several). A note of the loading that an earlier part of the
// same file gave already (what the reader said about the file) is in PRINTED and not repeated.
vtkSmartPointer<vtkPolyData> preparedSurface(const ScenePart& part, const SurfaceOptions& options,
                                             bool several, std::set<std::string>& printed,
                                             std::ostream& out)
{
  const std::string prefix = "  " + (several ? part.name + ": " : std::string());
  for (const std::string& line : part.mesh.report.notes())
  {
    if (printed.insert(part.source + "\n" + line).second)
    {
      out << prefix << line << "\n";
    }
  }
  if (part.lines)
  {
    return part.mesh.polyData; // a line set: its tangents are the line's (LineSet.h)
  }
  PreparedSurface prepared = prepareSurface(part.mesh.polyData, options, part.source);
  for (const std::string& note : prepared.report.notes())
  {
    out << prefix << note << "\n";
  }
  return prepared.polyData;
}

// What the summary line says the image is of: the file (or built-in mesh) of one part, else
// "N parts (K hidden) from FILE, FILE".
std::string sceneSource(const std::vector<ScenePart>& parts)
{
  if (parts.size() == 1)
  {
    return parts[0].source;
  }
  std::vector<std::string> files;
  int hidden = 0;
  for (const ScenePart& part : parts)
  {
    if (std::find(files.begin(), files.end(), part.source) == files.end())
    {
      files.push_back(part.source);
    }
    hidden += part.visible ? 0 : 1;
  }
  std::string text = std::to_string(parts.size()) + " parts";
  if (hidden > 0)
  {
    text += " (" + std::to_string(hidden) + " hidden)";
  }
  text += " from ";
  for (std::size_t i = 0; i < files.size(); ++i)
  {
    text += (i ? ", " : "") + files[i];
  }
  return text;
}

// The sources of ENV (opened from SPEC, turned by ROTATION_DEGREES: their angles are the
// world's, as --azimuth and --elevation take them) on OUT: a summary line, then one line per
// listed source, the first kSourceLines of them. A uniform environment has none and says
// nothing; an analysis that fails is a note, the render goes on. Returns the analysis, which
// the caller holds so the renderer's own request shares it (sharedEnvironmentAnalysis).
std::shared_ptr<const EnvAnalysis> printEnvironmentSources(const Environment& env,
                                                           const std::string& spec,
                                                           double rotationDegrees,
                                                           std::ostream& out)
{
  constexpr std::size_t kSourceLines = 4;
  if (dynamic_cast<const UniformEnvironment*>(&env))
  {
    return nullptr;
  }
  const std::string name =
      spec.rfind("builtin:", 0) == 0 ? spec : fs::path(spec).filename().string();
  std::shared_ptr<const EnvAnalysis> analysis;
  try
  {
    analysis = sharedEnvironmentAnalysis(env);
  }
  catch (const Error& e)
  {
    out << "render: environment " << name << ": no analysis of its sources: " << e.what() << "\n";
    return nullptr;
  }
  out << "render: environment " << name << ": " << analysisSummary(*analysis) << "\n";
  const std::vector<EnvSource>& sources = analysis->sources;
  for (std::size_t i = 0; i < std::min(sources.size(), kSourceLines); ++i)
  {
    out << "render:   " << sourceText(sources[i], rotationDegrees) << "\n";
  }
  if (sources.size() > kSourceLines)
  {
    double share = 0.0;
    for (std::size_t i = kSourceLines; i < sources.size(); ++i)
    {
      share += sources[i].powerShare;
    }
    out << "render:   and " << sources.size() - kSourceLines << " more (" << percentText(share)
        << ")\n";
  }
  return analysis;
}

// The env-sampling choice as drawn: "auto (sources)" or "auto (off)" by the analysis the
// lighting resolves it with (EnvAnalysis::concentrated), else the choice itself.
std::string samplingSummary(const ParameterSet& parameters, const EnvAnalysis* analysis)
{
  const std::string chosen = parameters.text("env-sampling");
  if (parseEnvironmentSampling(chosen) != EnvironmentSampling::Auto)
  {
    return chosen;
  }
  return chosen + (analysis && analysis->concentrated() ? " (sources)" : " (off)");
}

std::string formatMilliseconds(double seconds)
{
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(seconds < 0.1 ? 2 : 1);
  s << seconds * 1e3 << " ms";
  return s.str();
}
} // namespace

ViewSettings renderViewSettings(const std::vector<std::string>& args)
{
  return viewOf(parse(renderCommand(), args));
}

std::string renderSummary()
{
  return "render a mesh with an anisotropic material to a PNG or EXR, headless";
}

// The fields the visible surface parts' materials show: a part without the array is drawn
// without it, with a warning naming it and its file; when no part has it the run fails. What a
// field holds that is not finite is counted (drawn in the colour map's NaN colour).
static void checkFields(const std::vector<ScenePart>& scene, const std::vector<RenderPart>& parts,
                 std::ostream& report, std::ostream& err)
{
  std::map<std::string, int> found; // field -> parts that have it
  std::vector<std::pair<std::size_t, std::string>> missing;
  for (std::size_t i = 0; i < parts.size(); ++i)
  {
    const RenderPart& part = parts[i];
    if (!part.visible || scene[i].lines || !part.material.field)
    {
      continue;
    }
    const FieldSpec& spec = part.material.field->spec;
    const std::string name = formatFieldSpec(spec);
    found.emplace(name, 0);
    const auto statistics = fieldStatistics(part.surface, spec);
    if (!statistics)
    {
      missing.emplace_back(i, name);
      continue;
    }
    ++found[name];
    if (statistics->nonFinite > 0)
    {
      report << "render: field " << name << " of " << scene[i].name << ": "
             << statistics->nonFinite << " of " << statistics->values << " "
             << (statistics->perCell ? "cell" : "point")
             << " values NaN or infinite (drawn in the colour map's NaN colour)\n";
    }
  }
  for (const auto& [i, name] : missing)
  {
    if (found[name] == 0)
    {
      throw errorAbout(scene[i].source, "has no point or cell array '" +
                                            parseFieldSpec(name, "field")->array +
                                            "' for --field (aniso render --list-arrays lists "
                                            "them)");
    }
    err << "aniso: warning: " << scene[i].source << ": part " << scene[i].name
        << " has no array for field " << name << " (drawn without it)\n";
  }
}

int runRender(const std::vector<std::string>& args, std::ostream& out, std::ostream& err)
{
  const Command command = renderCommand();
  const Arguments a = parse(command, args);
  if (a.helpRequested)
  {
    out << helpText(command);
    return 0;
  }

  // Everything the command line can get wrong is checked before any work.
  // --list-parts and --list-arrays print the parts alone: what a render reports goes nowhere.
  const bool listing = a.has("--list-parts") || a.has("--list-arrays");
  std::ostringstream unreported;
  std::ostream& report = listing ? unreported : out;
  const std::string output = a.text("--output");
  const std::string exported = a.has("--export-gltf") ? a.text("--export-gltf") : std::string();
  if (!listing && !output.empty())
  {
    checkOutput(output);
  }
  if (!listing && !exported.empty())
  {
    checkOutput(exported, ".glb", ".gltf");
  }
  const std::optional<ReferenceRequest> reference = listing ? std::nullopt : referenceRequestOf(a);
  for (const std::string& file :
       reference ? std::vector<std::string>{reference->reference, reference->errorMap}
                 : std::vector<std::string>{})
  {
    if (!file.empty())
    {
      checkOutput(file, ".exr", ".png"); // the extensions are checked: where the files go
    }
  }
  RenderSettings settings;
  std::tie(settings.width, settings.height) = parseImageSize(a.text("--size"), "--size", kMaxSide);
  if (a.has("--turntable") && a.has("--compare"))
  {
    throw usageError("--turntable", "give either --turntable or --compare");
  }
  settings.view = viewOf(a);
  SurfaceOptions surfaceOptions;
  MeshReadOptions readOptions;
  try
  {
    if (a.has("--tangents"))
    {
      surfaceOptions.brushing = parseBrushingModel(a.text("--tangents"));
    }
    readOptions.cadDeflection =
        parseCadDeflection(a.text("--cad-deflection"), "--cad-deflection");
    readOptions.cadAngleDegrees = a.real("--cad-angle");
  }
  catch (const Error& e)
  {
    throw UsageError(e.what());
  }
  if (a.has("--quaternion-map") && a.has("--normal-map"))
  {
    throw usageError("--quaternion-map", "give either --normal-map or --quaternion-map");
  }
  if (a.has("--bump") && !a.has("--normal-map"))
  {
    throw usageError("--bump", "only applies to --normal-map");
  }

  ParameterSet parameters;
  for (const char* name : kDeclared)
  {
    parameters.setValue(name, a.value(std::string("--") + name));
  }
  // A choice of the declared background other than its colour (env, none) as it is; anything
  // else is the colour, background-color.
  const std::string background = a.text("--background");
  const std::vector<std::string_view>& modes = parameterSpec("background").choices;
  if (std::find(modes.begin(), modes.end(), background) != modes.end() &&
      parseBackgroundMode(background) != BackgroundMode::Color)
  {
    parameters.setText("background", background);
  }
  else
  {
    try
    {
      parameters.setText("background", spelling(BackgroundMode::Color));
      parameters.setValue("background-color", parseParameterValue(parameterSpec("background-color"),
                                                                  background, "--background"));
    }
    catch (const Error& e)
    {
      throw usageError("--background", "'" + background + "' is not env, none or R,G,B");
    }
  }
  settings.material = materialFromParameters(parameters);
  if (a.has("--quality"))
  {
    if (a.has("--samples"))
    {
      throw usageError("--quality", "give either --quality or --samples");
    }
    const QualityChoice quality =
        chooseSamples(a.real("--quality"), settings.material.lobe, settings.material.filtered);
    settings.material.samples = quality.samples;
    report << "quality: " << quality.samples << " samples per frame for a predicted error of "
           << quality.predictedError
           << (quality.reachable ? "" : " (the target needs more than the largest sample count)")
           << "\n";
  }
  settings.display = displayFromParameters(parameters);
  settings.environmentRotationDegrees = parameters.real("env-rotation");
  settings.cubeSize = parameters.integer("cube-size");
  settings.frames = a.integer("--frames");
  if (a.has("--converge"))
  {
    settings.errorTarget = a.real("--converge");
    settings.errorStopFrames = minimumErrorStopFrames(settings.material.samples);
    if (!a.has("--frames"))
    {
      const int limit = static_cast<int>(parameterSpec("target-samples").defaultValue[0]);
      settings.frames = std::max(1, limit / std::max(settings.material.samples, 1));
    }
  }
  settings.jitter = a.text("--jitter") == "on";
  applyModelOptions(a, settings);

  // The material library (the built-in metals, --materials FILE's, then the files' own) and
  // what --part assigns from it; the library files fail before any mesh is read.
  MaterialLibrary library = partLibrary(a);

  // Then the inputs, each failing with its file's name.
  std::vector<ScenePart> scene = scenePartsOf(a, err, readOptions);
  adoptFileMaterials(library, scene);
  checkPartOptions(a, library);
  assignParts(a, library, scene);
  if (listing)
  {
    if (a.has("--list-parts"))
    {
      listParts(scene, out);
    }
    if (a.has("--list-arrays"))
    {
      listArrays(scene, out);
    }
    return 0;
  }
  const bool several = scene.size() > 1;
  std::vector<vtkSmartPointer<vtkPolyData>> surfaces(scene.size());
  std::set<std::string> printed;
  for (std::size_t i = 0; i < scene.size(); ++i)
  {
    if (scene[i].visible)
    {
      surfaces[i] = preparedSurface(
          scene[i], scene[i].material ? surfaceOptionsOf(*scene[i].material) : surfaceOptions,
          several, printed, out);
    }
  }
  if (!exported.empty())
  {
    std::vector<GltfPart> written = gltfPartsOf(scene, surfaces, materialOfParameters(parameters));
    writeGltfScene(exported, written);
    out << "render: exported " << written.size() << (written.size() == 1 ? " part" : " parts")
        << " to " << exported << "\n";
    for (const std::string& name : partsWithFields(written))
    {
      out << "render: " << name
          << ": its field is not written (the file holds the material without it)\n";
    }
    if (output.empty())
    {
      return 0;
    }
  }
  for (std::size_t i = 0; i < scene.size(); ++i)
  {
    if (surfaces[i] && scene[i].placement != kIdentityPlacement)
    {
      surfaces[i] = placedSurface(surfaces[i], scene[i].placement);
    }
  }
  settings.environment = openEnvironment(parameters.text("env"));
  if (a.has("--normal-map"))
  {
    const std::string path = a.text("--normal-map");
    if (a.text("--bump") == "normal")
    {
      settings.material.normalMap = std::make_shared<const Image>(readSignedMap(path));
    }
    else
    {
      ImageInfo info;
      const Image normals = readImage(path, &info);
      settings.material.quaternionMap =
          std::make_shared<const Image>(bakeQuaternionMap(normals, info.integerFormat, nullptr));
    }
  }
  if (a.has("--quaternion-map"))
  {
    settings.material.quaternionMap =
        std::make_shared<const Image>(readSignedMap(a.text("--quaternion-map")));
  }
  if (a.has("--tpr"))
  {
    settings.material.tprMap = std::make_shared<const Image>(readTprMap(a.text("--tpr"), "--tpr"));
  }
  if (a.has("--height-map"))
  {
    settings.material.heightMap = std::make_shared<const Image>(readImage(a.text("--height-map")));
  }
  // Each library material once, its maps shared by the parts that use it.
  std::map<std::string, MaterialSettings> librarySettings;
  const std::optional<double> quality =
      a.has("--quality") ? std::optional<double>(a.real("--quality")) : std::nullopt;
  std::vector<RenderPart> parts;
  bool anyLines = false;
  for (std::size_t i = 0; i < scene.size(); ++i)
  {
    const ScenePart& part = scene[i];
    RenderPart drawn;
    drawn.name = part.name;
    drawn.visible = part.visible;
    drawn.surface = surfaces[i];
    drawn.material = settings.material;
    anyLines = anyLines || (part.visible && part.lines);
    if (part.lines)
    {
      drawn.lineStyle = lineStyleOf(part.material, parameters);
    }
    if (part.visible && part.material)
    {
      auto found = librarySettings.find(part.material->name);
      if (found == librarySettings.end())
      {
        found = librarySettings
                    .emplace(part.material->name,
                             librarySettingsOf(*part.material, parameters, quality, report))
                    .first;
      }
      drawn.material = found->second;
    }
    if (part.visible && !part.lines && drawn.material.usesMaps() &&
        !drawn.surface->GetPointData()->GetArray("TCoords"))
    {
      throw errorAbout(part.source, "has no texture coordinates, which the maps need");
    }
    parts.push_back(std::move(drawn));
  }
  checkFields(scene, parts, report, err);
  if (reference)
  {
    checkReferenceScene(scene, parts);
  }
  // One part is drawn as the renderer's one-part scene; several as its parts (and a line part,
  // whose style the one-part scene has no place for, as a scene of one part).
  if (parts.size() == 1 && !anyLines)
  {
    settings.surface = parts[0].surface;
    settings.material = parts[0].material;
  }
  else
  {
    settings.parts = std::move(parts);
  }
  const std::string source = sceneSource(scene);
  // Once every input is read, so a bad map's error is all a failed run prints.
  const std::shared_ptr<const EnvAnalysis> environmentSources =
      printEnvironmentSources(*settings.environment, parameters.text("env"),
                              settings.environmentRotationDegrees, report);

  if (a.has("--turntable"))
  {
    const int images = a.integer("--turntable");
    const std::vector<double> seconds = renderTurntable(settings, images, output, out);
    out << "render: a turntable of " << images << " images of " << source << "\n";
    if (a.has("--time"))
    {
      out << "time: median frame " << formatMilliseconds(medianSeconds(seconds)) << " over "
          << seconds.size() << " frames\n";
    }
    return 0;
  }
  const RenderResult result =
      a.has("--compare") ? renderComparison(a, settings) : renderOffscreen(settings);

  const bool exr = lowercaseExtension(output) == ".exr";
  writeRendered(output, result, settings.display.background == BackgroundMode::Transparent);
  const int samples = settings.material.samples;
  const int frames = static_cast<int>(result.frameSeconds.size());
  // A field that changes the lobe draws with half vectors from the shader, whatever was asked.
  std::string halfVectors = parameters.text("half-vectors");
  if (result.variant.field && spelling(result.variant.halfVectors) != halfVectors)
  {
    halfVectors =
        std::string(spelling(result.variant.halfVectors)) + " (the field changes the lobe)";
  }
  out << "render: wrote " << output << " (" << settings.width << "x" << settings.height << ", "
      << (exr ? "linear RGBA float, alpha = coverage" : "tone-mapped sRGB") << ") of " << source
      << ": " << frames << " frame(s) x " << samples << " samples, " << parameters.text("method")
      << ", filtered " << parameters.text("filtered") << ", half vectors from the " << halfVectors
      << ", environment sampling " << samplingSummary(parameters, environmentSources.get()) << "; "
      << modelSummary(a) << "\n";
  if (settings.errorTarget > 0.0)
  {
    const bool reached = result.estimatedErrorFrames == frames &&
                         errorTargetReached(result.estimatedError, settings.errorTarget);
    out << "converge: ";
    if (result.estimatedError < 0.0)
    {
      out << "no estimate (it needs 4 frames and a covered pixel)";
    }
    else
    {
      out << "estimated error " << result.estimatedError << " after " << result.estimatedErrorFrames
          << " frames";
    }
    out << (reached ? ", within the target " : ", not within the target ") << settings.errorTarget
        << " (" << frames << " of at most " << settings.frames << " frames; " << result.frozenPixels
        << " of " << result.coveredPixels << " covered pixels stopped before the view)\n";
  }
  if (a.has("--time"))
  {
    const double median = medianSeconds(result.frameSeconds);
    const double samplesPerSecond =
        median > 0.0 ? double(result.coveredPixels) * samples / median : 0.0;
    out << "time: median frame " << formatMilliseconds(median) << " over " << frames
        << " frame(s) (first " << formatMilliseconds(result.frameSeconds.front())
        << ", shaders and textures included; after it "
        << formatMilliseconds(
               std::accumulate(result.frameSeconds.begin() + 1, result.frameSeconds.end(), 0.0))
        << " in all); " << result.coveredPixels << " covered pixels x " << samples
        << " samples: " << samplesPerSecond / 1e6 << " M samples/s on " << result.renderer << "\n";
  }
  if (reference)
  {
    reportReference(*reference, settings, result, out);
  }
  return 0;
}
} // namespace aniso::cli
