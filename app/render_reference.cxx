#include "app/render_reference.h"

#include "core/error.h"
#include "core/fields/color_map.h"
#include "core/image/image.h"
#include "core/models/models.h"
#include "core/reference/pixel_geometry.h"
#include "core/reference/reference_image.h"
#include "vtkpasses/mesh/TriangleArrays.h"
#include "vtkpasses/render/MaterialSettings.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <glm/vec3.hpp>

namespace aniso::cli
{
namespace
{
// What one pixel may cost the integrator (ReferenceOptions::maxEvaluations): a quarter of its
// default, so that a sharp lobe's pixel stays near a second; a pixel that needs more is counted
// as not converged and reported.
constexpr uint64_t kMaxEvaluations = 1ull << 24;

std::string lowercaseExtension(const std::string& path)
{
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  return ext;
}

// "every pixel", "every 2nd", "every 3rd", "every 4th", ..., "every 21st"
std::string everyNth(int n)
{
  if (n == 1)
  {
    return "every pixel";
  }
  const int lastTwo = n % 100;
  const char* suffix = "th";
  if (lastTwo < 11 || lastTwo > 13)
  {
    suffix = n % 10 == 1 ? "st" : n % 10 == 2 ? "nd" : n % 10 == 3 ? "rd" : "th";
  }
  return "every " + std::to_string(n) + suffix + " pixel in x and y";
}

std::string formatted(const char* format, double value)
{
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

// PAINT(pixel, x, y) at every pixel of each computed pixel's STEP x STEP block (the grid of
// selectPixelGrid: pixel x covers x - step / 2 .. x - step / 2 + step - 1).
template <typename Paint>
void overBlocks(const ReferenceImage& reference, int step, Paint paint)
{
  for (const ReferencePixel& p : reference.pixels)
  {
    const int x0 = p.x - step / 2;
    const int y0 = p.y - step / 2;
    for (int y = std::max(0, y0); y < std::min(reference.height, y0 + step); ++y)
    {
      for (int x = std::max(0, x0); x < std::min(reference.width, x0 + step); ++x)
      {
        paint(p, x, y);
      }
    }
  }
}

Image referenceImage(const ReferenceImage& reference, int step)
{
  Image image(reference.width, reference.height, 4);
  overBlocks(reference, step,
             [&](const ReferencePixel& p, int x, int y)
             {
               for (int c = 0; c < 3; ++c)
               {
                 image.at(x, y, c) = static_cast<float>(p.value[c]);
               }
               image.at(x, y, 3) = 1.0f;
             });
  return image;
}

// ERRORS (errorMap's image) as Viridis over [0, SCALE], each compared pixel over its block,
// transparent elsewhere and where the error is not finite.
Image heatMap(const Image& errors, const ReferenceImage& reference, int step, double scale)
{
  Image image(errors.width, errors.height, 4);
  overBlocks(reference, step,
             [&](const ReferencePixel& p, int x, int y)
             {
               const double value = errors.at(p.x, p.y, 0);
               if (!std::isfinite(value))
               {
                 return; // a render pixel NaN or infinite: left transparent
               }
               const glm::dvec3 colour = colorMapColor(ColorMap::Viridis, value / scale);
               for (int c = 0; c < 3; ++c)
               {
                 image.at(x, y, c) = static_cast<float>(colour[c]);
               }
               image.at(x, y, 3) = 1.0f;
             });
  return image;
}
} // namespace

std::optional<ReferenceRequest> referenceRequestOf(const Arguments& a)
{
  const bool requested = a.has("--reference") || a.has("--error-map");
  if (!requested)
  {
    for (const char* option : {"--reference-step", "--reference-tolerance"})
    {
      if (a.has(option))
      {
        throw usageError(option, "only applies to --reference or --error-map");
      }
    }
    return std::nullopt;
  }
  ReferenceRequest request;
  const std::string option = a.has("--reference") ? "--reference" : "--error-map";
  if (a.has("--reference"))
  {
    request.reference = a.text("--reference");
    if (lowercaseExtension(request.reference) != ".exr")
    {
      throw usageError("--reference", "'" + request.reference + "' must end in .exr");
    }
  }
  if (a.has("--error-map"))
  {
    request.errorMap = a.text("--error-map");
    const std::string ext = lowercaseExtension(request.errorMap);
    if (ext != ".exr" && ext != ".png")
    {
      throw usageError("--error-map", "'" + request.errorMap + "' must end in .exr or .png");
    }
  }
  if (!a.has("--output"))
  {
    throw usageError(option, "needs -o FILE: the render it compares");
  }
  if (a.has("--compare") || a.text("--model") != kEnvironmentModel)
  {
    throw usageError(option,
                     "the reference is of the anisotropic environment material (--model " +
                         std::string(kEnvironmentModel) + "), not of " +
                         (a.has("--compare") ? "--compare" : "--model " + a.text("--model")));
  }
  if (a.has("--turntable"))
  {
    throw usageError(option, "give either --turntable or " + option);
  }
  request.step = a.integer("--reference-step");
  request.tolerance = a.real("--reference-tolerance");
  return request;
}

void checkReferenceScene(const std::vector<ScenePart>& scene, const std::vector<RenderPart>& parts)
{
  const bool several = scene.size() > 1;
  for (std::size_t i = 0; i < scene.size() && i < parts.size(); ++i)
  {
    if (!parts[i].visible)
    {
      continue;
    }
    std::string why;
    if (scene[i].lines)
    {
      why = "the reference does not cover line parts (illuminated lines)";
    }
    else
    {
      referenceMaterialOf(parts[i].material, why);
    }
    if (!why.empty())
    {
      throw errorAbout(scene[i].source, (several ? "part " + scene[i].name + ": " : "") + why);
    }
  }
}

void reportReference(const ReferenceRequest& request, const RenderSettings& settings,
                     const RenderResult& result, std::ostream& out)
{
  const auto start = std::chrono::steady_clock::now();
  if (settings.installMaterial)
  {
    throw errorAbout("reference", "the reference does not cover another shading model");
  }
  // The visible parts as one mesh in the frame they were drawn in, each triangle with its part's
  // material.
  TriangleMesh mesh;
  std::vector<ReferenceMaterial> materials;
  for (const RenderPart& part : sceneParts(settings))
  {
    if (!part.visible)
    {
      continue;
    }
    std::string why;
    const std::optional<ReferenceMaterial> material = referenceMaterialOf(part.material, why);
    if (!material || part.installMaterial)
    {
      throw errorAbout(part.name, why.empty() ? "the reference does not cover its model" : why);
    }
    appendTriangles(mesh, triangleMesh(part.surface), static_cast<int>(materials.size()),
                    result.drawing.centre, result.drawing.radius);
    materials.push_back(*material);
  }

  const int width = result.linear.width;
  const int height = result.linear.height;
  // The camera's own matrix: vtkAnisoAccumulationPass restores the window centre after each
  // jittered frame, so the rays go through the pixel centres the frames average around.
  const std::vector<PixelSample> geometry = castPixels(mesh, result.clipToWorld, width, height);
  const std::vector<int> selected = selectPixelGrid(geometry, width, height, request.step);
  if (selected.empty())
  {
    throw errorAbout("reference", "no pixel of the view can be compared at " +
                                      everyNth(request.step) +
                                      " (none is covered with its 3x3 neighbourhood)");
  }
  ReferenceOptions options;
  options.relativeTolerance = request.tolerance;
  options.maxEvaluations = kMaxEvaluations;
  SceneReference reference =
      computeSceneReference(geometry, width, height, selected, materials, *settings.environment,
                            result.worldToEnvironment, options);
  // What the printed error and the error map compare with is the reference as written (floats),
  // so that both can be recomputed from the files. Read back from the image: GCC 12's SLP
  // vectoriser drops the round trips of adjacent doubles through float, (double)(float)x.
  const Image written = referenceImage(reference, request.step);
  for (ReferencePixel& p : reference.pixels)
  {
    p.value = glm::dvec3(written.at(p.x, p.y, 0), written.at(p.x, p.y, 1), written.at(p.x, p.y, 2));
  }
  const ImageError error = compareToReference(result.linear, reference);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  out << "reference: relative L2 " << formatted("%.10g", error.relativeL2)
      << " against the CPU reference at " << reference.pixels.size() << " pixels ("
      << everyNth(request.step) << "), its own bound "
      << formatted("%.3g", reference.relativeErrorBound) << ", "
      << formatted(seconds < 10.0 ? "%.2f" : "%.0f", seconds) << " s";
  if (error.relativeL2 <= reference.relativeErrorBound)
  {
    out << ", within the reference's own bound";
  }
  if (reference.unconverged > 0)
  {
    out << "; " << reference.unconverged << " pixels did not converge within " << kMaxEvaluations
        << " evaluations";
  }
  if (error.uncovered > 0)
  {
    out << "; " << error.uncovered << " compared pixels not fully covered by the render";
  }
  if (error.nonFinite > 0)
  {
    out << "; " << error.nonFinite << " compared pixels of the render NaN or infinite";
  }
  out << "\n";

  if (!request.reference.empty())
  {
    writeImage(request.reference, written);
    out << "reference: wrote " << request.reference << " (" << width << "x" << height
        << ", linear RGBA float: each computed pixel over its " << request.step << "x"
        << request.step << " block, alpha 0 where none was)\n";
  }
  if (!request.errorMap.empty())
  {
    const Image errors = errorMap(result.linear, reference);
    if (lowercaseExtension(request.errorMap) == ".exr")
    {
      writeImage(request.errorMap, errors);
      out << "reference: wrote " << request.errorMap
          << " (|render - reference| / rms(reference) per compared pixel, NaN elsewhere)\n";
    }
    else
    {
      // The 99th percentile keeps a few outliers (a silhouette, a sharp reflection) from
      // darkening the rest of the map.
      const double scale =
          std::isfinite(error.percentile99) && error.percentile99 > 0.0 ? error.percentile99 : 1.0;
      writeImage(request.errorMap, heatMap(errors, reference, request.step, scale));
      out << "reference: wrote " << request.errorMap
          << " (|render - reference| / rms(reference), Viridis over [0, "
          << formatted("%.3g", scale) << "], the 99th percentile)\n";
    }
  }
}
} // namespace aniso::cli
