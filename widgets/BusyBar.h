#pragma once
// A busy indicator for work that reports no fraction (a bake, a file read): a block that steps
// along a bar and back, one step every kStepMs, repainting only while it is visible.
//
// Qt's own busy QProgressBar (range 0 to 0) animates at the display's rate, some 60 repaints a
// second. In a window that holds an OpenGL view every repaint of a child composes the whole
// window again with the view's picture, which on a software rasteriser costs the UI thread
// 10-20 ms each (docs/BENCHMARKS.md, "UI latency"): a bar animating through a bake kept the UI
// thread busy for most of it, and its repaints shared passes of the event loop with the view's
// renders. Four steps a second say as much that the work runs.
#include <QWidget>

class QTimer;

namespace aniso
{
class BusyBar : public QWidget
{
  Q_OBJECT

public:
  static constexpr int kStepMs = 250;
  // Positions of the block: it goes along the bar in kPositions steps, then back.
  static constexpr int kPositions = 6;

  explicit BusyBar(QWidget* parent = nullptr);

  // Steps taken since it was shown (each one repaint).
  int steps() const { return steps_; }
  bool animating() const;
  QSize sizeHint() const override;
  QSize minimumSizeHint() const override;

protected:
  void paintEvent(QPaintEvent* event) override;
  void showEvent(QShowEvent* event) override;
  void hideEvent(QHideEvent* event) override;

private:
  QTimer* timer_;
  int steps_ = 0;
};
} // namespace aniso
