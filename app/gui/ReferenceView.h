#pragma once
// View > Reference: the CPU reference of what the window's view shows (core/reference), computed
// on a worker while the window answers, and the view's error against it.
//
// While on, each time the view is still (not moving, its lighting and lookup tables on screen)
// and what the reference depends on (SceneView::referenceKey: the size, the camera, the drawn
// parts and their materials, the environment and its rotation) differs from the run in flight,
// the run is cancelled (its pixels dropped) and a new one starts from SceneView::referenceInputs:
// the pixels are cast, then integrated on a grid of every pixel, every 2nd or every 4th in x and
// y (setStride), coarsest first (ProgressiveReference.h: every 8th cell of the grid, then every
// 4th, 2nd, then the rest), each computed pixel standing for its block until finer ones arrive.
// Anything that moves the view cancels the run at once. Once the view has converged, its linear
// image is compared with the pixels computed so far (compareToReference, errorMap). The latest
// run wins: a cancelled run stops within the pixels in flight and what it still delivers is
// dropped.
#include "app/gui/ProgressiveReference.h"
#include "app/gui/SceneView.h"
#include "core/image/image.h"
#include "core/reference/reference_image.h"

#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <atomic>
#include <memory>
#include <optional>
#include <string>
#include <vector>

class QThreadPool;
class QTimer;

namespace aniso
{
class LutScheduler;
class SceneModel;

class ReferenceView : public QObject
{
  Q_OBJECT

public:
  // The integrator's settings of the window's reference: `aniso render --reference`'s defaults
  // (a relative tolerance of 1e-3; at most 2^24 evaluations a pixel).
  static ReferenceOptions defaultOptions();

  ReferenceView(SceneModel* model, SceneView* view, LutScheduler* luts, QObject* parent = nullptr);
  ~ReferenceView() override;

  // On: runs as described above; off: cancels and forgets.
  void setEnabled(bool on);
  bool enabled() const { return enabled_; }
  // Every STRIDE-th pixel in x and y (1, 2 or 4; 2 by default: a quarter of the pixels, each
  // shown over its 2 x 2 block). A change starts the reference over.
  void setStride(int stride);
  int stride() const { return stride_; }
  // The integrator's tolerance and budget (tests take a coarser tolerance); a change starts the
  // reference over.
  void setOptions(const ReferenceOptions& options);
  const ReferenceOptions& options() const { return options_; }

  // Why the reference does not cover the view (SceneView::referenceUnsupported), or empty:
  // updated as the scene changes, whether on or off.
  const QString& unsupported() const { return unsupported_; }

  // The current run: its grid (empty until the pixels are cast), the pixels computed so far (in
  // the order they arrived; relativeErrorBound over them), whether all are, and an estimate of
  // the seconds left from the pixels done so far (negative while unknown).
  bool running() const;
  bool complete() const { return complete_; }
  const ReferenceGrid& grid() const { return grid_; }
  const ReferenceImage& reference() const { return reference_; }
  std::size_t pixelsDone() const { return reference_.pixels.size(); }
  std::size_t pixelsTotal() const { return grid_.total(); }
  double secondsElapsed() const;
  double secondsLeft() const;

  // The view's linear image the reference was compared with (empty until the view converged at
  // the reference's size), and the comparison over the pixels computed so far.
  const Image& viewImage() const { return viewImage_; }
  const std::optional<ImageError>& error() const { return error_; }
  // errorMap of the view's image against the pixels computed (empty without a comparison).
  const Image& errors() const { return errors_; }
  // The state in words: the view's error against the reference and whether it is within the
  // reference's own bound, or the progress, or why there is none.
  QString summary() const;
  // The progress in words: pixels, the grid, the time left or taken.
  QString progressText() const;

  // The display transform the view shows with (exposure, tone mapping).
  DisplaySettings display() const;

  // Each run that ended (completed, cancelled or failed), oldest first: the pixels it computed of
  // its grid's total (-1 before its grid was known).
  struct Run
  {
    std::size_t pixels = 0;
    long long total = -1;
    bool cancelled = false;
  };
  const std::vector<Run>& finishedRuns() const { return finished_; }

signals:
  // Progress, completion, a new comparison, a run started or dropped, the display transform.
  void changed();
  void unsupportedChanged(const QString& why);
  void errorOccurred(const QString& message);

private:
  // Brings the run in line with the view (soon: several requests make one).
  void scheduleRefresh();
  void refresh();
  bool viewStill() const;
  void start(const SceneView::ReferenceKey& key);
  // Cancels the run in flight and forgets what it computed.
  void stop();
  void gridArrived(int id, const ReferenceGrid& grid);
  void pixelsArrived(int id, const SceneReference& pixels);
  void runEnded(int id, const Run& run, const QString& failure);
  // The view's image, read when it converged at the reference's size, and the comparison.
  void compare();

  SceneModel* model_;
  SceneView* view_;
  LutScheduler* luts_;
  QThreadPool* pool_;
  QTimer* refresh_;
  bool enabled_ = false;
  int stride_ = 2;
  ReferenceOptions options_;
  QString unsupported_;

  int runId_ = 0;
  bool active_ = false; // a run is in flight or complete for key_
  SceneView::ReferenceKey key_;
  std::shared_ptr<std::atomic<bool>> cancel_;
  QElapsedTimer clock_;        // since the run's grid arrived
  double castSeconds_ = 0.0;   // casting the run's pixels
  double finalSeconds_ = -1.0; // the whole run, once complete
  ReferenceGrid grid_;
  ReferenceImage reference_;
  bool complete_ = false;
  QString failure_; // why the run for key_ failed (reported once), or empty
  // relativeErrorBound over the chunks: sums of the squared error estimates and of |ref|^2.
  double boundError_ = 0.0;
  double boundNorm_ = 0.0;

  Image viewImage_;
  SceneView::ReferenceKey viewKey_; // the view the image was read from
  std::optional<ImageError> error_;
  Image errors_;
  std::vector<Run> finished_;
};
} // namespace aniso
