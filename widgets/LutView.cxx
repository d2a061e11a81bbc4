#include "widgets/LutView.h"

#include "core/parameters/parameters.h"
#include "scene/LutScheduler.h"
#include "widgets/BusyBar.h"

#include <QGridLayout>
#include <QLabel>
#include <QPixmap>
#include <QVBoxLayout>

namespace aniso
{
namespace
{
constexpr int kPreviewSide = 112;

QLabel* imageLabel(const QString& name, QWidget* parent)
{
  auto* label = new QLabel(parent);
  label->setObjectName(name);
  label->setFixedSize(kPreviewSide, kPreviewSide);
  label->setAlignment(Qt::AlignCenter);
  label->setFrameShape(QFrame::StyledPanel);
  return label;
}

QString number(double v)
{
  return QString::fromStdString(formatNumber(v));
}

QString duration(double seconds)
{
  return seconds < 1.0 ? QString("%1 ms").arg(seconds * 1e3, 0, 'f', seconds < 0.01 ? 2 : 0)
                       : QString("%1 s").arg(seconds, 0, 'f', 2);
}
} // namespace

LutView::LutView(LutScheduler* scheduler, QWidget* parent)
    : QWidget(parent), scheduler_(scheduler), halfVectors_(imageLabel("lut-half-vectors", this)),
      pdf_(imageLabel("lut-pdf", this)), brdf_(imageLabel("lut-brdf", this)),
      info_(new QLabel(this)), progress_(new BusyBar(this))
{
  setObjectName("LutView");
  auto* grid = new QGridLayout();
  const QString captions[3] = {tr("Half vectors h (RGB = (h + 1) / 2)"),
                               tr("log2 p_h (false colour)"),
                               tr("BRDF LUT (R = s, G = b / max b)")};
  QLabel* images[3] = {halfVectors_, pdf_, brdf_};
  for (int i = 0; i < 3; ++i)
  {
    auto* caption = new QLabel(captions[i], this);
    caption->setWordWrap(true);
    caption->setMaximumWidth(kPreviewSide);
    grid->addWidget(images[i], 0, i);
    grid->addWidget(caption, 1, i);
  }
  auto* axes = new QLabel(tr("Horizontal: ξ1 (half vectors) or u = (2/π) atan(|b·v| / |t·v|) "
                             "(BRDF); vertical, upwards: ξ2 or v = √(n·v)."),
                          this);
  axes->setWordWrap(true);
  axes->setEnabled(false);
  info_->setObjectName("lut-info");
  info_->setWordWrap(true);
  info_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  // A busy bar: the bakers report no fraction, only that they are working.
  progress_->setVisible(scheduler->busy());

  auto* layout = new QVBoxLayout(this);
  layout->addLayout(grid);
  layout->addWidget(axes);
  layout->addWidget(progress_);
  layout->addWidget(info_);
  layout->addStretch(1);

  connect(scheduler, &LutScheduler::busyChanged, progress_, &QWidget::setVisible);
  connect(scheduler, &LutScheduler::bakeStarted, this,
          [this](const LutRequest& r)
          {
            info_->setText(tr("Baking n_u = %1, n_v = %2, %3 × %3, %4 samples per texel…")
                               .arg(number(r.lobe.nu), number(r.lobe.nv))
                               .arg(r.size)
                               .arg(r.samples));
          });
  connect(scheduler, &LutScheduler::lutsReady, this, &LutView::show);
  connect(scheduler, &LutScheduler::bakeFailed, this,
          [this](const QString& message) { info_->setText(tr("Failed: %1").arg(message)); });
  if (scheduler->current().halfVector)
  {
    show(scheduler->current());
  }
}

QString LutView::infoText() const
{
  return info_->text();
}

void LutView::show(const LutResult& r)
{
  const auto pixmap = [](const QImage& image)
  {
    // Nearest neighbour: the texels of a small LUT stay visible as squares.
    return QPixmap::fromImage(
        image.scaled(kPreviewSide, kPreviewSide, Qt::IgnoreAspectRatio, Qt::FastTransformation));
  };
  halfVectors_->setPixmap(pixmap(r.halfVectorImage));
  pdf_->setPixmap(pixmap(r.pdfImage));
  brdf_->setPixmap(pixmap(r.brdfImage));
  info_->setText(tr("n_u = %1, n_v = %2; %3 × %3 texels, %4 samples per BRDF texel.\n"
                    "log2 p_h from %5 to %6; max b = %7.\n%8 in %9.")
                     .arg(number(r.request.lobe.nu), number(r.request.lobe.nv))
                     .arg(r.request.size)
                     .arg(r.request.samples)
                     .arg(r.pdfRange[0], 0, 'f', 2)
                     .arg(r.pdfRange[1], 0, 'f', 2)
                     .arg(r.maxBias, 0, 'g', 3)
                     .arg(r.baked ? tr("Baked") : tr("From the cache"))
                     .arg(duration(r.seconds)));
}
} // namespace aniso
