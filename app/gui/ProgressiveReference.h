#pragma once
// The window's CPU reference of its view (View > Reference, app/gui/ReferenceView.h) as plain
// data and functions: what it integrates, the order it integrates the pixels in (a coarse grid
// first, then finer ones) and the images the Reference dock shows (the reference over its blocks,
// the error map's colours, the view through the display transform). GL-free, Qt-free and
// VTK-free: the view's inputs arrive as plain data (SceneView::referenceInputs).
#include "core/env/environment.h"
#include "core/image/image.h"
#include "core/reference/pixel_geometry.h"
#include "core/reference/reference_image.h"
#include "vtkpasses/render/DisplaySettings.h"

#include <atomic>
#include <cstddef>
#include <functional>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <memory>
#include <string>
#include <vector>

namespace aniso
{
// What the reference of a view integrates: the drawn parts as one mesh in the frame they are
// drawn in, each triangle with its part's material, the camera that draws them (clip to world,
// without the frames' jitter), the environment on screen and its rotation, and the view's size.
struct ReferenceInputs
{
  TriangleMesh mesh;
  std::vector<ReferenceMaterial> materials;
  glm::dmat4 clipToWorld{1.0};
  glm::dmat3 worldToEnvironment{1.0};
  std::shared_ptr<const Environment> environment;
  int width = 0;
  int height = 0;
};

// The grid's refinement: the pixels of selectPixelGrid's grid of STRIDE whose grid column and row
// are multiples of 8 first, then of 4, then of 2, then the rest. A pixel of level L stands for a
// block of kReferenceBlocks[L] x kReferenceBlocks[L] grid cells until finer levels fill it.
inline constexpr int kReferenceLevels = 4;
inline constexpr int kReferenceBlocks[kReferenceLevels] = {8, 4, 2, 1};

// The level of pixel (X, Y) of the grid of STRIDE (a pixel selectPixelGrid selects).
int referenceLevel(int x, int y, int stride);

struct ReferenceGrid
{
  int width = 0;
  int height = 0;
  int stride = 1;
  std::vector<char> covered;            // per pixel: the ray through its centre hits a part
  std::vector<std::vector<int>> levels; // row-major pixel indices, coarsest level first
  std::size_t total() const;            // pixels of every level
};
ReferenceGrid referenceGrid(const std::vector<PixelSample>& geometry, int width, int height,
                            int stride);

// Runs the reference of INPUTS on the calling thread (the pixels themselves on all hardware
// threads, computeSceneReference): casts the pixels, calls GRID with the grid, then integrates
// level by level in chunks of about CHUNK pixels, calling PIXELS after each with the pixels it
// computed. CANCEL is read between pixels; once set, nothing more is integrated or delivered.
// Returns the pixels computed. Throws aniso::Error as castPixels and computeSceneReference do.
std::size_t runProgressiveReference(const ReferenceInputs& inputs, int stride,
                                    const ReferenceOptions& options,
                                    const std::atomic<bool>& cancel, int chunk,
                                    const std::function<void(const ReferenceGrid&)>& grid,
                                    const std::function<void(const SceneReference&)>& pixels);

// Painters over a grid's blocks: PAINT(pixel, x, y) at each covered pixel of each of PIXELS'
// blocks (a pixel of level L covers kReferenceBlocks[L] x kReferenceBlocks[L] grid cells from
// its own, a cell spanning x - stride / 2 .. x - stride / 2 + stride - 1), coarser levels first,
// so that finer pixels paint over them: the reference upscaled by nearest.
void paintReferenceBlocks(const std::vector<ReferencePixel>& pixels, const ReferenceGrid& grid,
                          const std::function<void(const ReferencePixel&, int, int)>& paint);

// The reference as linear RGBA of the grid's size: each computed pixel over its block, alpha 1
// there, 0 elsewhere.
Image referenceLayer(const std::vector<ReferencePixel>& pixels, const ReferenceGrid& grid);

// ERRORS (errorMap's image) as display colours (sRGB, RGBA in [0, 1]): Viridis over [0, SCALE]
// (core/fields/color_map.h) over each compared pixel's block, alpha 0 elsewhere and where the
// error is not finite.
Image errorLayer(const Image& errors, const std::vector<ReferencePixel>& pixels,
                 const ReferenceGrid& grid, double scale);

// LINEAR (RGB, and alpha kept) as the view shows it: times 2^exposure, tone mapped, sRGB encoded,
// as vtkpasses/render/shaders/display_fs.glsl does (negative and non-finite radiance as 0).
Image displayedImage(const Image& linear, const DisplaySettings& display);

// "every pixel", "every 2nd pixel in x and y", "every 4th pixel in x and y".
std::string referenceStrideText(int stride);
} // namespace aniso
