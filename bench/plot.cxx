#include "bench/plot.h"

#include "bench/raster_font.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <limits>
#include <sstream>

namespace aniso::bench
{
namespace
{
constexpr double kEm = 0.6;         // advance of a character, in font sizes
constexpr double kTitleSize = 16.0; // figure title
constexpr double kLabelSize = 12.0; // panel titles, axis labels, legend
constexpr double kTickSize = 11.0;  // tick labels
constexpr double kFigureTitleHeight = 34.0;
constexpr double kLegendRowHeight = 22.0;
// Plot area inside a panel.
constexpr double kLeft = 64.0;
constexpr double kRight = 14.0;
constexpr double kTop = 26.0;
constexpr double kBottom = 44.0;

const glm::dvec3 kBlack{0.0};
const glm::dvec3 kGrid{0.86};
const glm::dvec3 kMinorGrid{0.94};

enum class Anchor
{
  Start,
  Middle,
  End,
};

struct Line
{
  glm::dvec2 a;
  glm::dvec2 b;
  double width;
  glm::dvec3 color;
  double opacity;
};

struct Dot
{
  glm::dvec2 centre;
  double radius;
  Marker marker;
  glm::dvec3 color;
  double opacity;
};

struct Text
{
  glm::dvec2 position; // baseline point at the anchor
  std::string text;
  double size;
  Anchor anchor;
  bool vertical; // reads bottom to top
  glm::dvec3 color;
};

// The figure as primitives, in drawing order within each list: lines, then dots, then texts.
struct Drawing
{
  int width = 0;
  int height = 0;
  std::vector<Line> lines;
  std::vector<Dot> dots;
  std::vector<Text> texts;
};

struct Axis
{
  bool log = true;
  int lowDecade = 0;  // log
  int highDecade = 1; // log
  double low = 0.0;   // linear: the value at FROM
  double high = 1.0;  // linear: the value at TO
  double step = 1.0;  // linear: between labelled grid lines
  double from = 0.0;  // pixel of lowDecade (log) or low (linear)
  double to = 1.0;    // pixel of highDecade (log) or high (linear)

  double map(double value) const
  {
    const double t = log ? (std::log10(value) - lowDecade) / double(highDecade - lowDecade)
                         : (value - low) / (high - low);
    return from + t * (to - from);
  }
  bool holds(double value) const { return std::isfinite(value) && (!log || value > 0.0); }
};

Axis axisFor(double lo, double hi, double from, double to)
{
  Axis axis;
  if (!(lo > 0.0) || !(hi >= lo) || !std::isfinite(hi))
  {
    lo = 1.0;
    hi = 10.0;
  }
  axis.lowDecade = static_cast<int>(std::floor(std::log10(lo)));
  axis.highDecade = static_cast<int>(std::ceil(std::log10(hi)));
  if (axis.highDecade <= axis.lowDecade)
  {
    axis.highDecade = axis.lowDecade + 1;
  }
  axis.from = from;
  axis.to = to;
  return axis;
}

// About six labelled steps of 1, 2 or 5 times a power of ten, from a multiple of the step at or
// below LO to one at or above HI.
Axis linearAxisFor(double lo, double hi, double from, double to)
{
  Axis axis;
  axis.log = false;
  if (!std::isfinite(lo) || !std::isfinite(hi) || hi < lo)
  {
    lo = 0.0;
    hi = 1.0;
  }
  if (hi - lo <= 1e-12 * std::max(1.0, std::abs(hi)))
  {
    const double pad = lo == 0.0 ? 1.0 : 0.1 * std::abs(lo);
    lo -= pad;
    hi += pad;
  }
  const double rough = (hi - lo) / 6.0;
  const double power = std::pow(10.0, std::floor(std::log10(rough)));
  const double fraction = rough / power;
  axis.step = (fraction <= 1.0   ? 1.0
               : fraction <= 2.0 ? 2.0
               : fraction <= 5.0 ? 5.0
                                 : 10.0) *
              power;
  axis.low = std::floor(lo / axis.step) * axis.step;
  axis.high = std::ceil(hi / axis.step) * axis.step;
  if (axis.high <= axis.low)
  {
    axis.high = axis.low + axis.step;
  }
  axis.from = from;
  axis.to = to;
  return axis;
}

// A linear axis' label at VALUE: as many decimals as the step needs.
std::string stepLabel(double value, double step)
{
  const int decimals = std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", decimals, std::abs(value) < 0.5 * step ? 0.0 : value);
  return text;
}

std::string decadeLabel(int decade)
{
  if (decade >= -3 && decade <= 3)
  {
    char text[16];
    std::snprintf(text, sizeof text, "%.*f", std::max(0, -decade), std::pow(10.0, decade));
    return text;
  }
  return "1e" + std::to_string(decade);
}

void layoutPanel(const PlotPanel& panel, double x0, double y0, double width, double height,
                 Drawing& d)
{
  const double left = x0 + kLeft;
  const double right = x0 + width - kRight;
  const double top = y0 + kTop;
  const double bottom = y0 + height - kBottom;
  double xLo = std::numeric_limits<double>::infinity();
  double xHi = -std::numeric_limits<double>::infinity();
  double yLo = std::numeric_limits<double>::infinity();
  double yHi = -std::numeric_limits<double>::infinity();
  const auto usable = [](double v, bool log) { return std::isfinite(v) && (!log || v > 0.0); };
  for (const PlotSeries& s : panel.series)
  {
    for (const glm::dvec2& p : s.points)
    {
      if (usable(p.x, panel.logX) && usable(p.y, panel.logY))
      {
        xLo = std::min(xLo, p.x);
        xHi = std::max(xHi, p.x);
        yLo = std::min(yLo, p.y);
        yHi = std::max(yHi, p.y);
      }
    }
  }
  const Axis xAxis =
      panel.logX ? axisFor(xLo, xHi, left, right) : linearAxisFor(xLo, xHi, left, right);
  const Axis yAxis =
      panel.logY ? axisFor(yLo, yHi, bottom, top) : linearAxisFor(yLo, yHi, bottom, top);

  // Grid: on log axes minor lines at 2..9 of each decade, major lines and labels at the decades;
  // on linear ones lines and labels at each step, minor lines halfway.
  for (const Axis* axis : {&xAxis, &yAxis})
  {
    const bool horizontal = axis == &xAxis;
    if (!axis->log)
    {
      const int steps = static_cast<int>(std::lround((axis->high - axis->low) / axis->step));
      for (int k = 0; k <= 2 * steps; ++k)
      {
        const double value = axis->low + 0.5 * k * axis->step;
        const double at = axis->map(value);
        const glm::dvec3 color = k % 2 == 0 ? kGrid : kMinorGrid;
        if (horizontal)
        {
          d.lines.push_back({{at, top}, {at, bottom}, 1.0, color, 1.0});
        }
        else
        {
          d.lines.push_back({{left, at}, {right, at}, 1.0, color, 1.0});
        }
        if (k % 2 != 0)
        {
          continue;
        }
        const std::string label = stepLabel(value, axis->step);
        if (horizontal)
        {
          d.texts.push_back({{at, bottom + 16.0}, label, kTickSize, Anchor::Middle, false, kBlack});
        }
        else
        {
          d.texts.push_back({{left - 5.0, at + 4.0}, label, kTickSize, Anchor::End, false, kBlack});
        }
      }
      continue;
    }
    for (int decade = axis->lowDecade; decade <= axis->highDecade; ++decade)
    {
      for (int m = 1; m <= 9 && (m == 1 || decade < axis->highDecade); ++m)
      {
        const double at = axis->map(m * std::pow(10.0, decade));
        const glm::dvec3 color = m == 1 ? kGrid : kMinorGrid;
        if (horizontal)
        {
          d.lines.push_back({{at, top}, {at, bottom}, 1.0, color, 1.0});
        }
        else
        {
          d.lines.push_back({{left, at}, {right, at}, 1.0, color, 1.0});
        }
      }
      const double at = axis->map(std::pow(10.0, decade));
      if (horizontal)
      {
        d.texts.push_back(
            {{at, bottom + 16.0}, decadeLabel(decade), kTickSize, Anchor::Middle, false, kBlack});
      }
      else
      {
        d.texts.push_back(
            {{left - 5.0, at + 4.0}, decadeLabel(decade), kTickSize, Anchor::End, false, kBlack});
      }
    }
  }
  // Frame.
  d.lines.push_back({{left, top}, {right, top}, 1.0, kBlack, 1.0});
  d.lines.push_back({{left, bottom}, {right, bottom}, 1.0, kBlack, 1.0});
  d.lines.push_back({{left, top}, {left, bottom}, 1.0, kBlack, 1.0});
  d.lines.push_back({{right, top}, {right, bottom}, 1.0, kBlack, 1.0});

  d.texts.push_back(
      {{0.5 * (left + right), y0 + 17.0}, panel.title, kLabelSize, Anchor::Middle, false, kBlack});
  d.texts.push_back({{0.5 * (left + right), bottom + 34.0},
                     panel.xLabel,
                     kLabelSize,
                     Anchor::Middle,
                     false,
                     kBlack});
  d.texts.push_back(
      {{x0 + 16.0, 0.5 * (top + bottom)}, panel.yLabel, kLabelSize, Anchor::Middle, true, kBlack});

  auto inside = [&](const glm::dvec2& p) { return xAxis.holds(p.x) && yAxis.holds(p.y); };
  for (const PlotSeries& s : panel.series)
  {
    std::vector<glm::dvec2> mapped;
    for (const glm::dvec2& p : s.points)
    {
      if (inside(p))
      {
        mapped.push_back({xAxis.map(p.x), yAxis.map(p.y)});
      }
    }
    if (s.connect)
    {
      for (std::size_t i = 1; i < mapped.size(); ++i)
      {
        d.lines.push_back({mapped[i - 1], mapped[i], 2.0, s.color, s.opacity});
      }
    }
    if (s.marker != Marker::None)
    {
      for (const glm::dvec2& p : mapped)
      {
        d.dots.push_back({p, s.markerSize, s.marker, s.color, s.opacity});
      }
    }
  }
}

Drawing layout(const Figure& figure)
{
  Drawing d;
  const int columns = std::max(1, figure.columns);
  const int panels = static_cast<int>(figure.panels.size());
  const int rows = std::max(1, (panels + columns - 1) / columns);
  // One legend entry per distinct label, in order of appearance.
  std::vector<const PlotSeries*> legend;
  for (const PlotPanel& panel : figure.panels)
  {
    for (const PlotSeries& s : panel.series)
    {
      const bool known =
          std::any_of(legend.begin(), legend.end(),
                      [&](const PlotSeries* other) { return other->label == s.label; });
      if (!s.label.empty() && !known)
      {
        legend.push_back(&s);
      }
    }
  }
  d.width = columns * figure.panelWidth;
  // Legend entries flow in rows across the figure's width.
  std::vector<std::vector<const PlotSeries*>> legendRows(1);
  double used = 0.0;
  for (const PlotSeries* s : legend)
  {
    const double entry = 30.0 + textWidth(s->label, kLabelSize) + 18.0;
    if (used + entry > d.width - 20.0 && !legendRows.back().empty())
    {
      legendRows.emplace_back();
      used = 0.0;
    }
    legendRows.back().push_back(s);
    used += entry;
  }
  const double legendHeight =
      legend.empty() ? 0.0 : kLegendRowHeight * double(legendRows.size()) + 8.0;
  d.height = static_cast<int>(kFigureTitleHeight + rows * figure.panelHeight + legendHeight);

  d.texts.push_back(
      {{0.5 * d.width, 23.0}, figure.title, kTitleSize, Anchor::Middle, false, kBlack});
  for (int i = 0; i < panels; ++i)
  {
    layoutPanel(figure.panels[std::size_t(i)], (i % columns) * double(figure.panelWidth),
                kFigureTitleHeight + (i / columns) * double(figure.panelHeight), figure.panelWidth,
                figure.panelHeight, d);
  }
  double y = kFigureTitleHeight + rows * figure.panelHeight + 14.0;
  for (const auto& row : legendRows)
  {
    double x = 20.0;
    for (const PlotSeries* s : row)
    {
      if (s->connect)
      {
        d.lines.push_back({{x, y}, {x + 24.0, y}, 2.0, s->color, s->opacity});
      }
      if (s->marker != Marker::None)
      {
        d.dots.push_back({{x + 12.0, y}, s->markerSize, s->marker, s->color, s->opacity});
      }
      d.texts.push_back({{x + 30.0, y + 4.0}, s->label, kLabelSize, Anchor::Start, false, kBlack});
      x += 30.0 + textWidth(s->label, kLabelSize) + 18.0;
    }
    y += kLegendRowHeight;
  }
  return d;
}

std::string rgb(const glm::dvec3& c)
{
  char text[32];
  auto byte = [](double v) { return static_cast<int>(std::lround(std::clamp(v, 0.0, 1.0) * 255)); };
  std::snprintf(text, sizeof text, "rgb(%d,%d,%d)", byte(c.x), byte(c.y), byte(c.z));
  return text;
}

std::string escaped(const std::string& text)
{
  std::string out;
  for (char c : text)
  {
    switch (c)
    {
    case '&':
      out += "&amp;";
      break;
    case '<':
      out += "&lt;";
      break;
    case '>':
      out += "&gt;";
      break;
    case '"':
      out += "&quot;";
      break;
    default:
      out += c;
    }
  }
  return out;
}

// Pixel coverage of the image being drawn, blended in with a colour.
class Canvas
{
public:
  explicit Canvas(Image& image) : image_(image) {}

  void blend(int x, int y, const glm::dvec3& color, double alpha)
  {
    if (x < 0 || y < 0 || x >= image_.width || y >= image_.height || alpha <= 0.0)
    {
      return;
    }
    alpha = std::min(alpha, 1.0);
    for (int c = 0; c < 3; ++c)
    {
      float& v = image_.at(x, y, c);
      v = static_cast<float>(v * (1.0 - alpha) + color[c] * alpha);
    }
  }

  void line(const Line& l)
  {
    const double reach = 0.5 * l.width + 1.0;
    const glm::dvec2 lo = glm::min(l.a, l.b) - reach;
    const glm::dvec2 hi = glm::max(l.a, l.b) + reach;
    const glm::dvec2 ab = l.b - l.a;
    const double length2 = glm::dot(ab, ab);
    for (int y = static_cast<int>(std::floor(lo.y)); y <= static_cast<int>(hi.y); ++y)
    {
      for (int x = static_cast<int>(std::floor(lo.x)); x <= static_cast<int>(hi.x); ++x)
      {
        const glm::dvec2 p(x + 0.5, y + 0.5);
        const double t =
            length2 > 0.0 ? std::clamp(glm::dot(p - l.a, ab) / length2, 0.0, 1.0) : 0.0;
        const double distance = glm::length(p - (l.a + t * ab));
        blend(x, y, l.color, std::clamp(0.5 * l.width + 0.5 - distance, 0.0, 1.0) * l.opacity);
      }
    }
  }

  void dot(const Dot& d)
  {
    const int r = static_cast<int>(std::ceil(d.radius + 1.0));
    const int cx = static_cast<int>(std::floor(d.centre.x));
    const int cy = static_cast<int>(std::floor(d.centre.y));
    for (int y = cy - r; y <= cy + r; ++y)
    {
      for (int x = cx - r; x <= cx + r; ++x)
      {
        const glm::dvec2 p = glm::dvec2(x + 0.5, y + 0.5) - d.centre;
        double inside = 0.0;
        switch (d.marker)
        {
        case Marker::Square:
          inside = std::min(d.radius - std::abs(p.x), d.radius - std::abs(p.y));
          break;
        case Marker::Diamond:
          inside = (1.3 * d.radius - std::abs(p.x) - std::abs(p.y)) / std::sqrt(2.0);
          break;
        case Marker::Circle:
        case Marker::None:
          inside = d.radius - glm::length(p);
          break;
        }
        blend(x, y, d.color, std::clamp(inside + 0.5, 0.0, 1.0) * d.opacity);
      }
    }
  }

  // Each set glyph pixel is a square of side s = size / 10 (cap height 0.7 em, advance 0.6 em);
  // coverage is summed over the squares first, so neighbouring squares leave no seams.
  void text(const Text& t)
  {
    const double s = t.size / 10.0;
    const double advance = kEm * t.size;
    const double length = advance * double(t.text.size());
    double start = 0.0;
    if (t.anchor == Anchor::Middle)
    {
      start = -0.5 * length;
    }
    else if (t.anchor == Anchor::End)
    {
      start = -length;
    }
    // Local coordinates: u along the text, w downwards from the baseline's top of glyphs.
    const double glyphTop = -kGlyphHeight * s;
    auto toScreen = [&](double u, double w)
    {
      return t.vertical ? glm::dvec2(t.position.x + w, t.position.y - u)
                        : glm::dvec2(t.position.x + u, t.position.y + w);
    };
    const glm::dvec2 c0 = toScreen(start, glyphTop);
    const glm::dvec2 c1 = toScreen(start + length, 0.0);
    const int x0 = static_cast<int>(std::floor(std::min(c0.x, c1.x))) - 1;
    const int y0 = static_cast<int>(std::floor(std::min(c0.y, c1.y))) - 1;
    const int x1 = static_cast<int>(std::ceil(std::max(c0.x, c1.x))) + 1;
    const int y1 = static_cast<int>(std::ceil(std::max(c0.y, c1.y))) + 1;
    const int w = x1 - x0 + 1;
    std::vector<double> coverage(std::size_t(w) * (y1 - y0 + 1), 0.0);
    for (std::size_t i = 0; i < t.text.size(); ++i)
    {
      for (int row = 0; row < kGlyphHeight; ++row)
      {
        for (int column = 0; column < kGlyphWidth; ++column)
        {
          if (!glyphPixel(t.text[i], column, row))
          {
            continue;
          }
          const double u = start + double(i) * advance + column * s;
          const double v = glyphTop + row * s;
          const glm::dvec2 a = toScreen(u, v);
          const glm::dvec2 b = toScreen(u + s, v + s);
          const glm::dvec2 lo = glm::min(a, b);
          const glm::dvec2 hi = glm::max(a, b);
          for (int y = static_cast<int>(std::floor(lo.y)); y < hi.y; ++y)
          {
            for (int x = static_cast<int>(std::floor(lo.x)); x < hi.x; ++x)
            {
              const double ox = std::min(hi.x, x + 1.0) - std::max(lo.x, double(x));
              const double oy = std::min(hi.y, y + 1.0) - std::max(lo.y, double(y));
              if (ox > 0.0 && oy > 0.0 && x >= x0 && x <= x1 && y >= y0 && y <= y1)
              {
                coverage[std::size_t(y - y0) * w + (x - x0)] += ox * oy;
              }
            }
          }
        }
      }
    }
    for (int y = y0; y <= y1; ++y)
    {
      for (int x = x0; x <= x1; ++x)
      {
        blend(x, y, t.color, coverage[std::size_t(y - y0) * w + (x - x0)]);
      }
    }
  }

private:
  Image& image_;
};
} // namespace

double textWidth(const std::string& text, double size)
{
  return kEm * size * double(text.size());
}

std::string figureToSvg(const Figure& figure)
{
  const Drawing d = layout(figure);
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << d.width << "\" height=\""
      << d.height << "\" viewBox=\"0 0 " << d.width << " " << d.height << "\">\n";
  svg << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  for (const Line& l : d.lines)
  {
    svg << "<line x1=\"" << l.a.x << "\" y1=\"" << l.a.y << "\" x2=\"" << l.b.x << "\" y2=\""
        << l.b.y << "\" stroke=\"" << rgb(l.color) << "\" stroke-width=\"" << l.width
        << "\" stroke-linecap=\"round\"";
    if (l.opacity < 1.0)
    {
      svg << " stroke-opacity=\"" << l.opacity << "\"";
    }
    svg << "/>\n";
  }
  for (const Dot& m : d.dots)
  {
    const std::string fill =
        "fill=\"" + rgb(m.color) + "\"" +
        (m.opacity < 1.0 ? " fill-opacity=\"" + std::to_string(m.opacity) + "\"" : std::string());
    switch (m.marker)
    {
    case Marker::Square:
      svg << "<rect x=\"" << m.centre.x - m.radius << "\" y=\"" << m.centre.y - m.radius
          << "\" width=\"" << 2.0 * m.radius << "\" height=\"" << 2.0 * m.radius << "\" " << fill
          << "/>\n";
      break;
    case Marker::Diamond:
    {
      const double r = 1.3 * m.radius;
      svg << "<polygon points=\"" << m.centre.x << "," << m.centre.y - r << " " << m.centre.x + r
          << "," << m.centre.y << " " << m.centre.x << "," << m.centre.y + r << " "
          << m.centre.x - r << "," << m.centre.y << "\" " << fill << "/>\n";
      break;
    }
    case Marker::Circle:
    case Marker::None:
      svg << "<circle cx=\"" << m.centre.x << "\" cy=\"" << m.centre.y << "\" r=\"" << m.radius
          << "\" " << fill << "/>\n";
      break;
    }
  }
  for (const Text& t : d.texts)
  {
    const char* anchor =
        t.anchor == Anchor::Start ? "start" : (t.anchor == Anchor::Middle ? "middle" : "end");
    svg << "<text x=\"" << t.position.x << "\" y=\"" << t.position.y
        << "\" font-family=\"DejaVu Sans Mono, monospace\" font-size=\"" << t.size
        << "\" text-anchor=\"" << anchor << "\" fill=\"" << rgb(t.color) << "\"";
    if (t.vertical)
    {
      svg << " transform=\"rotate(-90 " << t.position.x << " " << t.position.y << ")\"";
    }
    svg << ">" << escaped(t.text) << "</text>\n";
  }
  svg << "</svg>\n";
  return svg.str();
}

Image figureToImage(const Figure& figure)
{
  const Drawing d = layout(figure);
  Image image(d.width, d.height, 4);
  std::fill(image.data.begin(), image.data.end(), 1.0f);
  Canvas canvas(image);
  for (const Line& l : d.lines)
  {
    canvas.line(l);
  }
  for (const Dot& m : d.dots)
  {
    canvas.dot(m);
  }
  for (const Text& t : d.texts)
  {
    canvas.text(t);
  }
  return image;
}
} // namespace aniso::bench
