#include "widgets/EnvironmentThumbnails.h"

#include "core/env/environment.h"
#include "core/error.h"
#include "widgets/ParameterControls.h"

#include <QColor>
#include <QPainter>
#include <QPen>
#include <QPointF>
#include <algorithm>
#include <cmath>
#include <vector>

namespace aniso
{
namespace
{
float channel(const Image& image, int x, int y, int c)
{
  // Grey images spread to RGB; a missing channel of a two-channel (grey + alpha) image too.
  const int source = image.channels >= 3 ? c : 0;
  const float v = image.at(x, y, source);
  return std::isfinite(v) && v > 0.0f ? v : 0.0f;
}

constexpr double kPi = 3.14159265358979323846;

QColor markColour(EnvSourceKind kind)
{
  switch (kind)
  {
  case EnvSourceKind::Sun:
    return QColor(255, 190, 0);
  case EnvSourceKind::Lamp:
    return QColor(0, 220, 255);
  case EnvSourceKind::Window:
    break;
  }
  return QColor(255, 0, 200);
}

double aces(double x)
{
  return std::clamp(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}
} // namespace

Image toneMappedThumbnail(const Image& hdr, int width)
{
  if (hdr.empty() || hdr.width < 1 || hdr.height < 1 || hdr.channels < 1)
  {
    throw errorAbout("thumbnail", "empty image");
  }
  const int w = std::clamp(width, 1, hdr.width);
  const int h = std::clamp(w / 2, 1, hdr.height);
  Image small(w, h, 3);
  for (int y = 0; y < h; ++y)
  {
    const int y0 = y * hdr.height / h;
    const int y1 = std::max(y0 + 1, (y + 1) * hdr.height / h);
    for (int x = 0; x < w; ++x)
    {
      const int x0 = x * hdr.width / w;
      const int x1 = std::max(x0 + 1, (x + 1) * hdr.width / w);
      double sum[3] = {0.0, 0.0, 0.0};
      for (int sy = y0; sy < y1; ++sy)
      {
        for (int sx = x0; sx < x1; ++sx)
        {
          for (int c = 0; c < 3; ++c)
          {
            sum[c] += channel(hdr, sx, sy, c);
          }
        }
      }
      const double n = double(x1 - x0) * double(y1 - y0);
      for (int c = 0; c < 3; ++c)
      {
        small.at(x, y, c) = static_cast<float>(sum[c] / n);
      }
    }
  }
  // Reinhard's log-average luminance; the small offset keeps black texels finite.
  double logSum = 0.0;
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      const double luminance =
          0.2126 * small.at(x, y, 0) + 0.7152 * small.at(x, y, 1) + 0.0722 * small.at(x, y, 2);
      logSum += std::log(1e-4 + luminance);
    }
  }
  const double average = std::exp(logSum / (double(w) * h));
  const double exposure = 0.18 / average;
  for (float& v : small.data)
  {
    v = static_cast<float>(swatchFromLinear(aces(exposure * v)));
  }
  return small;
}

QImage toQImage(const Image& rgb)
{
  QImage image(rgb.width, rgb.height, QImage::Format_RGB888);
  for (int y = 0; y < rgb.height; ++y)
  {
    uchar* line = image.scanLine(y);
    for (int x = 0; x < rgb.width; ++x)
    {
      for (int c = 0; c < 3; ++c)
      {
        const float v = rgb.channels >= 3 ? rgb.at(x, y, c) : rgb.at(x, y, 0);
        line[3 * x + c] = static_cast<uchar>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
      }
    }
  }
  return image;
}

QImage environmentThumbnail(const std::string& spec, int width)
{
  if (spec.rfind("builtin:", 0) == 0)
  {
    return environmentThumbnail(*openEnvironment(spec), width);
  }
  return toQImage(toneMappedThumbnail(readImage(spec), width));
}

QImage environmentThumbnail(const Environment& env, int width)
{
  if (const auto* equirect = dynamic_cast<const EquirectEnvironment*>(&env))
  {
    return toQImage(toneMappedThumbnail(equirect->image(), width));
  }
  const int w = std::max(width, 2);
  return toQImage(toneMappedThumbnail(renderEquirect(env, w, w / 2, 1), w));
}

QImage markedSources(const QImage& preview, const EnvAnalysis& analysis)
{
  QImage marked = preview.convertToFormat(QImage::Format_RGB32);
  if (marked.isNull() || analysis.sources.empty())
  {
    return marked;
  }
  const double w = marked.width();
  const double h = marked.height();
  QPainter painter(&marked);
  painter.setRenderHint(QPainter::Antialiasing);
  painter.setBrush(Qt::NoBrush);
  for (const EnvSource& source : analysis.sources)
  {
    const glm::dvec2 uv = directionToEquirect(source.direction);
    const QPointF centre(uv.x * w, (1.0 - uv.y) * h);
    const double cosElevation =
        std::sqrt(std::max(0.0, 1.0 - source.direction.z * source.direction.z));
    const double ry = std::max<double>(kMinimumMarkRadius, source.angularRadius * h / kPi);
    const double rx =
        std::clamp(source.angularRadius * h / kPi / std::max(cosElevation, 1e-6),
                   double(kMinimumMarkRadius), std::max(w / 2.0, double(kMinimumMarkRadius)));
    for (const double shift : {-w, 0.0, w})
    {
      const QPointF at(centre.x() + shift, centre.y());
      if (at.x() + rx < 0.0 || at.x() - rx > w)
      {
        continue;
      }
      painter.setPen(QPen(QColor(0, 0, 0, 160), 3.0));
      painter.drawEllipse(at, rx, ry);
      painter.setPen(QPen(markColour(source.kind), 1.5));
      painter.drawEllipse(at, rx, ry);
    }
  }
  return marked;
}
} // namespace aniso
