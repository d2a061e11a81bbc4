#pragma once
// The Reference dock (View > Reference): the view beside its CPU reference (ReferenceView),
// either as a wipe, the view left of a line the mouse drags and the reference right of it, or as
// the error map, |view - reference| / rms(reference) per compared pixel in Viridis over
// [0, its 99th percentile] with a colour bar and its numbers. Both are shown through the view's
// display transform (exposure, tone mapping); what the reference has not computed (the
// background, silhouettes, pixels still to come) shows the view dimmed. The grid (every pixel,
// every 2nd, every 4th) is chosen here, and the progress with its time estimate is shown.
// Closing the dock turns the reference off (closed).
#include "core/image/image.h"

#include <QDockWidget>
#include <QImage>
#include <QWidget>

class QComboBox;
class QLabel;
class QTimer;

namespace aniso
{
class ReferenceView;

// What the dock draws: the two images split by a vertical line at a fraction of the width, or
// the error map with its colour bar.
class ReferenceCanvas : public QWidget
{
  Q_OBJECT

public:
  enum class Mode
  {
    Wipe,
    Error
  };
  explicit ReferenceCanvas(QWidget* parent = nullptr);

  void setImages(const QImage& view, const QImage& reference, const QImage& errors,
                 double errorScale);
  void setMode(Mode mode);
  Mode mode() const { return mode_; }
  // The line's place, 0 (all reference) to 1 (all view).
  void setSplit(double split);
  double split() const { return split_; }
  const QImage& viewImage() const { return view_; }
  const QImage& referenceImage() const { return reference_; }
  const QImage& errorImage() const { return errors_; }
  double errorScale() const { return scale_; }

  QSize sizeHint() const override { return {360, 300}; }

protected:
  void paintEvent(QPaintEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;

private:
  // Where the images are drawn (their aspect kept), leaving room for the colour bar in error
  // mode.
  QRect imageRect() const;
  void dragTo(int x);

  QImage view_;
  QImage reference_;
  QImage errors_;
  double scale_ = 0.0;
  Mode mode_ = Mode::Wipe;
  double split_ = 0.5;
};

class ReferenceDock : public QDockWidget
{
  Q_OBJECT

public:
  ReferenceDock(ReferenceView* reference, QWidget* parent = nullptr);

  ReferenceCanvas* canvas() const { return canvas_; }
  QComboBox* modeBox() const { return mode_; }
  QComboBox* gridBox() const { return grid_; }
  void setMode(ReferenceCanvas::Mode mode);
  // Redraws the images from the reference's state now (otherwise at most ten times a second).
  void refresh();

signals:
  // The dock was closed by its title bar's button.
  void closed();

protected:
  void closeEvent(QCloseEvent* event) override;

private:
  ReferenceView* reference_;
  ReferenceCanvas* canvas_;
  QComboBox* mode_;
  QComboBox* grid_;
  QLabel* progress_;
  QTimer* redraw_;
};
} // namespace aniso
