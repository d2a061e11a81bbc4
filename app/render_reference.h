#pragma once
// `aniso render --reference FILE`, `--error-map FILE`: the CPU reference of the view just
// rendered (core/reference/reference_image.h, the integrator's converged radiance at pixel
// centres), the render's relative L2 error against it printed, the reference and the per-pixel
// error written. The reference is of the anisotropic environment material: the as-env model,
// without maps, data fields or line parts. It is computed on a regular grid (--reference-step N:
// every Nth pixel in x and y, from N / 2) at the pixels whose 3x3 neighbourhood the ray cast
// covers, facing the viewer (selectPixelGrid).
#include "app/cli.h"
#include "app/render_parts.h"
#include "vtkpasses/render/OffscreenRenderer.h"

#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace aniso::cli
{
struct ReferenceRequest
{
  std::string reference;   // --reference FILE (.exr), or empty
  std::string errorMap;    // --error-map FILE (.exr or .png), or empty
  int step = 2;            // --reference-step
  double tolerance = 1e-3; // --reference-tolerance: the integrator's relative tolerance
};

// What the command line asks for: nothing without --reference and --error-map. Throws
// UsageError naming the option for a file of another extension, --reference-step or
// --reference-tolerance alone, no -o, and a model other than as-env (--model, --compare) or
// --turntable.
std::optional<ReferenceRequest> referenceRequestOf(const Arguments& arguments);

// Throws aniso::Error "SOURCE: [part NAME: ]the reference does not ..." for the first visible
// part of SCENE (drawn as PARTS, in the same order) the reference does not cover: a line part,
// or a material with maps or a data field (referenceMaterialOf).
void checkReferenceScene(const std::vector<ScenePart>& scene, const std::vector<RenderPart>& parts);

// The reference of the view RESULT drew of SETTINGS (its visible parts, their materials and
// environment) at the unjittered camera (RenderResult::clipToWorld), compared with
// RESULT.linear: one line on OUT, then the files REQUEST names, each with a line. Throws
// aniso::Error when no pixel can be compared or a file cannot be written.
void reportReference(const ReferenceRequest& request, const RenderSettings& settings,
                     const RenderResult& result, std::ostream& out);
} // namespace aniso::cli
