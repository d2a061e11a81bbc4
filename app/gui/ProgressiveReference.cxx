#include "app/gui/ProgressiveReference.h"

#include "core/error.h"
#include "core/fields/color_map.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace aniso
{
namespace
{
// The tone curves of display_fs.glsl.
double toneMapped(double x, ToneMapping mapping)
{
  switch (mapping)
  {
  case ToneMapping::Aces:
    // Narkowicz's fit of the ACES filmic curve.
    return std::clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
  case ToneMapping::Reinhard:
    return x / (1.0 + x);
  case ToneMapping::Clamp:
    break;
  }
  return std::clamp(x, 0.0, 1.0);
}
} // namespace

int referenceLevel(int x, int y, int stride)
{
  const int column = (x - stride / 2) / stride;
  const int row = (y - stride / 2) / stride;
  for (int level = 0; level + 1 < kReferenceLevels; ++level)
  {
    const int block = kReferenceBlocks[level];
    if (column % block == 0 && row % block == 0)
    {
      return level;
    }
  }
  return kReferenceLevels - 1;
}

std::size_t ReferenceGrid::total() const
{
  std::size_t count = 0;
  for (const std::vector<int>& level : levels)
  {
    count += level.size();
  }
  return count;
}

ReferenceGrid referenceGrid(const std::vector<PixelSample>& geometry, int width, int height,
                            int stride)
{
  ReferenceGrid grid;
  grid.width = width;
  grid.height = height;
  grid.stride = stride;
  grid.covered.resize(geometry.size());
  for (std::size_t i = 0; i < geometry.size(); ++i)
  {
    grid.covered[i] = geometry[i].hit ? 1 : 0;
  }
  grid.levels.resize(kReferenceLevels);
  for (int index : selectPixelGrid(geometry, width, height, stride))
  {
    grid.levels[std::size_t(referenceLevel(index % width, index / width, stride))].push_back(index);
  }
  return grid;
}

std::size_t runProgressiveReference(const ReferenceInputs& inputs, int stride,
                                    const ReferenceOptions& options,
                                    const std::atomic<bool>& cancel, int chunk,
                                    const std::function<void(const ReferenceGrid&)>& grid,
                                    const std::function<void(const SceneReference&)>& pixels)
{
  if (!inputs.environment)
  {
    throw errorAbout("reference", "no environment to integrate");
  }
  const std::vector<PixelSample> geometry =
      castPixels(inputs.mesh, inputs.clipToWorld, inputs.width, inputs.height);
  if (cancel.load())
  {
    return 0;
  }
  const ReferenceGrid levels = referenceGrid(geometry, inputs.width, inputs.height, stride);
  grid(levels);
  std::size_t done = 0;
  const std::size_t step = std::size_t(std::max(chunk, 1));
  for (const std::vector<int>& level : levels.levels)
  {
    for (std::size_t begin = 0; begin < level.size(); begin += step)
    {
      if (cancel.load())
      {
        return done;
      }
      const std::vector<int> selected(level.begin() + std::ptrdiff_t(begin),
                                      level.begin() +
                                          std::ptrdiff_t(std::min(level.size(), begin + step)));
      const SceneReference part =
          computeSceneReference(geometry, inputs.width, inputs.height, selected, inputs.materials,
                                *inputs.environment, inputs.worldToEnvironment, options, &cancel);
      done += part.pixels.size();
      if (part.cancelled)
      {
        return done;
      }
      pixels(part);
    }
  }
  return done;
}

void paintReferenceBlocks(const std::vector<ReferencePixel>& pixels, const ReferenceGrid& grid,
                          const std::function<void(const ReferencePixel&, int, int)>& paint)
{
  const int stride = grid.stride;
  for (int level = 0; level < kReferenceLevels; ++level)
  {
    const int side = kReferenceBlocks[level] * stride;
    for (const ReferencePixel& p : pixels)
    {
      if (referenceLevel(p.x, p.y, stride) != level)
      {
        continue;
      }
      const int x0 = p.x - stride / 2;
      const int y0 = p.y - stride / 2;
      for (int y = std::max(0, y0); y < std::min(grid.height, y0 + side); ++y)
      {
        for (int x = std::max(0, x0); x < std::min(grid.width, x0 + side); ++x)
        {
          if (grid.covered[std::size_t(y) * std::size_t(grid.width) + std::size_t(x)])
          {
            paint(p, x, y);
          }
        }
      }
    }
  }
}

Image referenceLayer(const std::vector<ReferencePixel>& pixels, const ReferenceGrid& grid)
{
  Image layer(grid.width, grid.height, 4);
  paintReferenceBlocks(pixels, grid,
                       [&](const ReferencePixel& p, int x, int y)
                       {
                         for (int c = 0; c < 3; ++c)
                         {
                           layer.at(x, y, c) = static_cast<float>(p.value[c]);
                         }
                         layer.at(x, y, 3) = 1.0f;
                       });
  return layer;
}

Image errorLayer(const Image& errors, const std::vector<ReferencePixel>& pixels,
                 const ReferenceGrid& grid, double scale)
{
  Image layer(grid.width, grid.height, 4);
  const double range = std::isfinite(scale) && scale > 0.0 ? scale : 1.0;
  paintReferenceBlocks(pixels, grid,
                       [&](const ReferencePixel& p, int x, int y)
                       {
                         const double value = errors.at(p.x, p.y, 0);
                         if (!std::isfinite(value))
                         {
                           return;
                         }
                         const glm::dvec3 colour = colorMapColor(ColorMap::Viridis, value / range);
                         for (int c = 0; c < 3; ++c)
                         {
                           layer.at(x, y, c) = static_cast<float>(colour[c]);
                         }
                         layer.at(x, y, 3) = 1.0f;
                       });
  return layer;
}

Image displayedImage(const Image& linear, const DisplaySettings& display)
{
  Image shown(linear.width, linear.height, 4);
  const double scale = std::exp2(display.exposureEV);
  for (int y = 0; y < linear.height; ++y)
  {
    for (int x = 0; x < linear.width; ++x)
    {
      for (int c = 0; c < 3 && c < linear.channels; ++c)
      {
        const double value = linear.at(x, y, c);
        const double radiance = std::isfinite(value) ? std::max(value, 0.0) : 0.0;
        shown.at(x, y, c) =
            static_cast<float>(linearToSrgb(toneMapped(radiance * scale, display.toneMapping)));
      }
      shown.at(x, y, 3) = linear.channels >= 4 ? linear.at(x, y, 3) : 1.0f;
    }
  }
  return shown;
}

std::string referenceStrideText(int stride)
{
  switch (stride)
  {
  case 1:
    return "every pixel";
  case 2:
    return "every 2nd pixel in x and y";
  case 3:
    return "every 3rd pixel in x and y";
  default:
    return "every " + std::to_string(stride) + "th pixel in x and y";
  }
}
} // namespace aniso
