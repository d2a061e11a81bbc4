#include "app/gui/ReferenceDock.h"

#include "app/gui/ProgressiveReference.h"
#include "app/gui/ReferenceView.h"
#include "core/fields/color_map.h"
#include "widgets/EnvironmentThumbnails.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QMouseEvent>
#include <QPainter>
#include <QTimer>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

namespace aniso
{
namespace
{
// What the reference does not cover shows the view at this share of its brightness.
constexpr float kDimmed = 0.35f;
constexpr int kBarWidth = 14;
constexpr int kBarRoom = 74; // the bar and its numbers, right of the error map

// As widgets/EnvironmentThumbnails' toQImage quantises (the view's image goes through it).
int byte(float value)
{
  return std::isfinite(value) ? int(std::lround(std::clamp(value, 0.0f, 1.0f) * 255.0f)) : 0;
}

// OVER's opaque pixels over BASE (display values), BASE dimmed elsewhere; BASE may be empty
// (black then).
QImage composed(const Image& base, const Image& over)
{
  QImage image(over.width, over.height, QImage::Format_RGB32);
  const bool withBase = base.width == over.width && base.height == over.height;
  for (int y = 0; y < over.height; ++y)
  {
    auto* line = reinterpret_cast<QRgb*>(image.scanLine(y));
    for (int x = 0; x < over.width; ++x)
    {
      if (over.at(x, y, 3) > 0.5f)
      {
        line[x] = qRgb(byte(over.at(x, y, 0)), byte(over.at(x, y, 1)), byte(over.at(x, y, 2)));
      }
      else if (withBase)
      {
        line[x] = qRgb(byte(kDimmed * base.at(x, y, 0)), byte(kDimmed * base.at(x, y, 1)),
                       byte(kDimmed * base.at(x, y, 2)));
      }
      else
      {
        line[x] = qRgb(0, 0, 0);
      }
    }
  }
  return image;
}

QString percentText(double value)
{
  return QString::number(100.0 * value, 'g', 2) + "%";
}
} // namespace

ReferenceCanvas::ReferenceCanvas(QWidget* parent) : QWidget(parent)
{
  setObjectName("referenceCanvas");
  setMinimumSize(160, 120);
  setCursor(Qt::SplitHCursor);
  setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
}

void ReferenceCanvas::setImages(const QImage& view, const QImage& reference, const QImage& errors,
                                double errorScale)
{
  view_ = view;
  reference_ = reference;
  errors_ = errors;
  scale_ = errorScale;
  update();
}

void ReferenceCanvas::setMode(Mode mode)
{
  mode_ = mode;
  setCursor(mode == Mode::Wipe ? Qt::SplitHCursor : Qt::ArrowCursor);
  update();
}

void ReferenceCanvas::setSplit(double split)
{
  split_ = std::clamp(split, 0.0, 1.0);
  update();
}

QRect ReferenceCanvas::imageRect() const
{
  const QImage& image = mode_ == Mode::Wipe ? (view_.isNull() ? reference_ : view_) : errors_;
  QRect area = rect().adjusted(2, 2, -2, -2);
  if (mode_ == Mode::Error)
  {
    area.setRight(area.right() - kBarRoom);
  }
  if (image.isNull() || area.width() <= 0 || area.height() <= 0)
  {
    return area;
  }
  const QSize size = image.size().scaled(area.size(), Qt::KeepAspectRatio);
  return QRect(area.left() + (area.width() - size.width()) / 2,
               area.top() + (area.height() - size.height()) / 2, size.width(), size.height());
}

void ReferenceCanvas::paintEvent(QPaintEvent*)
{
  QPainter painter(this);
  painter.fillRect(rect(), palette().window());
  const QRect target = imageRect();
  // Nearest: each reference pixel's block stays a block.
  painter.setRenderHint(QPainter::SmoothPixmapTransform, false);
  if (mode_ == Mode::Wipe)
  {
    if (view_.isNull() && reference_.isNull())
    {
      painter.drawText(rect(), Qt::AlignCenter, tr("No image yet"));
      return;
    }
    const int line = target.left() + int(std::lround(split_ * target.width()));
    painter.save();
    const QRect left(target.left(), target.top(), line - target.left(), target.height());
    painter.setClipRect(left);
    if (view_.isNull())
    {
      // Not the view's picture until it has converged.
      painter.fillRect(target, Qt::black);
      painter.setPen(Qt::gray);
      painter.drawText(left, Qt::AlignCenter, tr("refining"));
    }
    else
    {
      painter.drawImage(target, view_);
    }
    painter.setClipRect(QRect(line, target.top(), target.right() + 1 - line, target.height()));
    if (reference_.isNull())
    {
      painter.fillRect(target, Qt::black);
    }
    else
    {
      painter.drawImage(target, reference_);
    }
    painter.restore();
    painter.setPen(QPen(Qt::white, 2));
    painter.drawLine(line, target.top(), line, target.bottom());
    painter.setBrush(Qt::white);
    painter.drawEllipse(QPoint(line, target.center().y()), 5, 5);
    // White on a dark shadow: legible over a bright environment too.
    const QRect labels = target.adjusted(6, 4, -6, -4);
    for (const auto& [offset, colour] : {std::pair{1, Qt::black}, std::pair{0, Qt::white}})
    {
      painter.setPen(colour);
      const QRect at = labels.translated(offset, offset);
      painter.drawText(at, Qt::AlignLeft | Qt::AlignTop, tr("View"));
      painter.drawText(at, Qt::AlignRight | Qt::AlignTop, tr("Reference"));
    }
    return;
  }
  if (errors_.isNull())
  {
    painter.drawText(rect(), Qt::AlignCenter, tr("No comparison yet"));
    return;
  }
  painter.drawImage(target, errors_);
  // The colour bar: Viridis from 0 (bottom) to the scale (top), with three numbers.
  const QRect bar(target.right() + 10, target.top() + 8, kBarWidth,
                  std::max(20, target.height() - 16));
  for (int y = 0; y < bar.height(); ++y)
  {
    const double t = 1.0 - double(y) / std::max(1, bar.height() - 1);
    const glm::dvec3 c = colorMapColor(ColorMap::Viridis, t);
    painter.setPen(QColor(byte(float(c.x)), byte(float(c.y)), byte(float(c.z))));
    painter.drawLine(bar.left(), bar.top() + y, bar.right(), bar.top() + y);
  }
  painter.setPen(palette().windowText().color());
  painter.setBrush(Qt::NoBrush);
  painter.drawRect(bar);
  const QFontMetrics metrics(font());
  for (double t : {0.0, 0.5, 1.0})
  {
    const int y = bar.bottom() - int(std::lround(t * bar.height()));
    painter.drawLine(bar.right(), y, bar.right() + 3, y);
    painter.drawText(bar.right() + 6, y + metrics.ascent() / 2, percentText(t * scale_));
  }
}

void ReferenceCanvas::mousePressEvent(QMouseEvent* event)
{
  if (mode_ == Mode::Wipe && event->button() == Qt::LeftButton)
  {
    dragTo(event->pos().x());
  }
}

void ReferenceCanvas::mouseMoveEvent(QMouseEvent* event)
{
  if (mode_ == Mode::Wipe && (event->buttons() & Qt::LeftButton))
  {
    dragTo(event->pos().x());
  }
}

void ReferenceCanvas::dragTo(int x)
{
  const QRect target = imageRect();
  if (target.width() > 0)
  {
    setSplit(double(x - target.left()) / double(target.width()));
  }
}

ReferenceDock::ReferenceDock(ReferenceView* reference, QWidget* parent)
    : QDockWidget(tr("Reference"), parent), reference_(reference),
      canvas_(new ReferenceCanvas(this)), mode_(new QComboBox(this)), grid_(new QComboBox(this)),
      progress_(new QLabel(this)), redraw_(new QTimer(this))
{
  setObjectName("ReferenceDock");
  mode_->setObjectName("referenceMode");
  mode_->addItem(tr("Wipe"));
  mode_->addItem(tr("Error map"));
  mode_->setToolTip(tr("The view and the reference split by a line you drag, or the error map: "
                       "|view − reference| / rms(reference) per compared pixel"));
  grid_->setObjectName("referenceGrid");
  grid_->addItem(tr("Every pixel"), 1);
  grid_->addItem(tr("Every 2nd pixel (a quarter)"), 2);
  grid_->addItem(tr("Every 4th pixel (a sixteenth)"), 4);
  grid_->setCurrentIndex(grid_->findData(reference_->stride()));
  grid_->setToolTip(tr("The pixels the reference integrates, each shown over its block"));
  progress_->setObjectName("referenceProgress");
  progress_->setWordWrap(true);

  auto* body = new QWidget(this);
  auto* layout = new QVBoxLayout(body);
  auto* controls = new QHBoxLayout;
  controls->addWidget(mode_);
  controls->addWidget(grid_, 1);
  layout->addLayout(controls);
  layout->addWidget(canvas_, 1);
  layout->addWidget(progress_);
  setWidget(body);

  connect(mode_, qOverload<int>(&QComboBox::currentIndexChanged), this,
          [this](int index)
          {
            canvas_->setMode(index == 1 ? ReferenceCanvas::Mode::Error
                                        : ReferenceCanvas::Mode::Wipe);
          });
  connect(grid_, qOverload<int>(&QComboBox::currentIndexChanged), this,
          [this](int index) { reference_->setStride(grid_->itemData(index).toInt()); });
  // At most ten redraws a second: each builds images of the view's size.
  redraw_->setSingleShot(true);
  redraw_->setInterval(100);
  connect(redraw_, &QTimer::timeout, this, &ReferenceDock::refresh);
  connect(reference_, &ReferenceView::changed, this,
          [this]
          {
            if (!redraw_->isActive())
            {
              redraw_->start();
            }
          });
  refresh();
}

void ReferenceDock::setMode(ReferenceCanvas::Mode mode)
{
  mode_->setCurrentIndex(mode == ReferenceCanvas::Mode::Error ? 1 : 0);
}

void ReferenceDock::refresh()
{
  redraw_->stop();
  // The error in words is the status bar's (ReferenceView::summary).
  progress_->setText(reference_->progressText());
  const ReferenceGrid& grid = reference_->grid();
  const DisplaySettings display = reference_->display();
  const Image view =
      reference_->viewImage().empty() ? Image() : displayedImage(reference_->viewImage(), display);
  if (grid.width == 0)
  {
    canvas_->setImages(view.empty() ? QImage() : toQImage(view), QImage(), QImage(), 0.0);
    return;
  }
  const Image shown = displayedImage(referenceLayer(reference_->reference().pixels, grid), display);
  QImage errors;
  double scale = 0.0;
  if (reference_->error() && !reference_->errors().empty())
  {
    // The 99th percentile keeps a few outliers (a silhouette, a sharp reflection) from
    // darkening the rest of the map, as `aniso render --error-map` scales it.
    scale = reference_->error()->percentile99;
    scale = std::isfinite(scale) && scale > 0.0 ? scale : 1.0;
    errors = composed(
        view, errorLayer(reference_->errors(), reference_->reference().pixels, grid, scale));
  }
  canvas_->setImages(view.empty() ? QImage() : toQImage(view), composed(view, shown), errors,
                     scale);
}

void ReferenceDock::closeEvent(QCloseEvent* event)
{
  QDockWidget::closeEvent(event);
  emit closed();
}
} // namespace aniso
