#pragma once
// Scatter plots with lines (error against time, Pareto fronts: log-log; a quantity over a run:
// linear axes), laid out once as a list of drawing primitives, then written as SVG text or
// rasterised into an image for PNG files, so both show the same picture. The rasteriser
// anti-aliases by exact pixel coverage and draws text with a built-in 5x7 bitmap font (printable
// ASCII). GL-free, no dependencies.
#include "core/image/image.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace aniso::bench
{
enum class Marker
{
  None,
  Circle,
  Square,
  Diamond,
};

struct PlotSeries
{
  std::string label; // legend text; empty = not in the legend
  glm::dvec3 color{0.0};
  std::vector<glm::dvec2> points; // data coordinates (> 0 on log axes; others are skipped)
  bool connect = false;           // a line through the points in order
  Marker marker = Marker::Circle;
  double markerSize = 3.0; // radius in pixels
  double opacity = 1.0;
};

struct PlotPanel
{
  std::string title;
  std::string xLabel;
  std::string yLabel;
  std::vector<PlotSeries> series;
  // Logarithmic axes span whole decades around the data (which must be > 0); linear ones span
  // round steps (1, 2 or 5 times a power of ten) around it.
  bool logX = true;
  bool logY = true;
};

struct Figure
{
  std::string title;
  std::vector<PlotPanel> panels; // laid out in rows of `columns`
  int columns = 2;
  int panelWidth = 480;
  int panelHeight = 360;
};

// Each panel's axes as it asks (logarithmic by default).
std::string figureToSvg(const Figure& figure);
// The same figure as an RGBA image (opaque white background).
Image figureToImage(const Figure& figure);

// Text width in pixels at font size SIZE, as the layout assumes (monospace, 0.6 em).
double textWidth(const std::string& text, double size);
} // namespace aniso::bench
