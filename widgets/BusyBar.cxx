#include "widgets/BusyBar.h"

#include <QPainter>
#include <QPalette>
#include <QTimer>
#include <algorithm>

namespace aniso
{
BusyBar::BusyBar(QWidget* parent) : QWidget(parent), timer_(new QTimer(this))
{
  setObjectName("busyBar");
  setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
  timer_->setInterval(kStepMs);
  connect(timer_, &QTimer::timeout, this,
          [this]
          {
            ++steps_;
            update();
          });
}

bool BusyBar::animating() const
{
  return timer_->isActive();
}

QSize BusyBar::sizeHint() const
{
  return {120, 8};
}

QSize BusyBar::minimumSizeHint() const
{
  return {3 * kPositions, 6};
}

void BusyBar::showEvent(QShowEvent* event)
{
  QWidget::showEvent(event);
  steps_ = 0;
  timer_->start();
}

void BusyBar::hideEvent(QHideEvent* event)
{
  QWidget::hideEvent(event);
  timer_->stop();
}

void BusyBar::paintEvent(QPaintEvent*)
{
  QPainter painter(this);
  const QRect frame = rect().adjusted(0, 0, -1, -1);
  painter.setPen(palette().color(QPalette::Mid));
  painter.setBrush(palette().color(QPalette::Base));
  painter.drawRect(frame);
  // Position 0, 1, ..., kPositions - 1, then back: a period of 2 (kPositions - 1) steps.
  const int period = 2 * (kPositions - 1);
  const int phase = steps_ % period;
  const int position = phase < kPositions ? phase : period - phase;
  const int inner = std::max(frame.width() - 1, 1);
  const int block = std::max(inner / kPositions, 1);
  const int x = frame.left() + 1 + (inner - block) * position / (kPositions - 1);
  painter.fillRect(QRect(x, frame.top() + 1, block, std::max(frame.height() - 1, 1)),
                   palette().color(QPalette::Highlight));
}
} // namespace aniso
