#include "app/gui/ReferenceView.h"

#include "core/background_priority.h"
#include "core/error.h"
#include "scene/LutScheduler.h"
#include "scene/SceneModel.h"
#include "vtkpasses/render/DisplaySettings.h"

#include <QLocale>
#include <QThreadPool>
#include <QTimer>
#include <chrono>
#include <cmath>
#include <glm/geometric.hpp>

namespace aniso
{
namespace
{
// Pixels integrated between two deliveries to the window, per hardware thread: a broad lobe's
// pixel takes a few milliseconds (`aniso render --reference`: 3959 pixels of n = 100 in 19 s on
// two threads), so the window hears of the progress several times a second.
constexpr int kChunkPerThread = 32;

QString percent(double value)
{
  return QString::number(100.0 * value, 'g', 2) + "%";
}

QString seconds(double s)
{
  return s < 10.0 ? QString::number(s, 'f', 1) + " s" : QString::number(std::lround(s)) + " s";
}
} // namespace

ReferenceOptions ReferenceView::defaultOptions()
{
  ReferenceOptions options;
  options.relativeTolerance = 1e-3;
  // `aniso render --reference`'s budget: 1 << 24 nodes resolve lobes up to the declared exponent
  // range in the bench's scenes; a pixel that needs more is counted as not converged.
  options.maxEvaluations = 1ull << 24;
  return options;
}

ReferenceView::ReferenceView(SceneModel* model, SceneView* view, LutScheduler* luts,
                             QObject* parent)
    : QObject(parent), model_(model), view_(view), luts_(luts), pool_(new QThreadPool(this)),
      refresh_(new QTimer(this)), options_(defaultOptions())
{
  // Two workers: a cancelled run still finishing its pixels in flight never holds up the next
  // (each run integrates on every hardware thread itself).
  pool_->setMaxThreadCount(2);
  refresh_->setSingleShot(true);
  refresh_->setInterval(0);
  connect(refresh_, &QTimer::timeout, this, &ReferenceView::refresh);
  // Whatever may change what the view shows, or whether it is still.
  connect(view_, &SceneView::frameRendered, this, &ReferenceView::scheduleRefresh);
  connect(view_, &SceneView::interactionChanged, this, &ReferenceView::scheduleRefresh);
  connect(view_, &SceneView::lightingBusyChanged, this, &ReferenceView::scheduleRefresh);
  connect(view_, &SceneView::partsDrawn, this, &ReferenceView::scheduleRefresh);
  connect(luts_, &LutScheduler::busyChanged, this, &ReferenceView::scheduleRefresh);
  connect(model_, &SceneModel::valueChanged, this, &ReferenceView::scheduleRefresh);
  connect(model_, &SceneModel::materialsChanged, this, &ReferenceView::scheduleRefresh);
  connect(model_, &SceneModel::partsChanged, this, &ReferenceView::scheduleRefresh);
  scheduleRefresh();
}

ReferenceView::~ReferenceView()
{
  if (cancel_)
  {
    cancel_->store(true);
  }
  pool_->waitForDone();
}

void ReferenceView::setEnabled(bool on)
{
  if (on == enabled_)
  {
    return;
  }
  enabled_ = on;
  if (!on)
  {
    stop();
  }
  scheduleRefresh();
}

void ReferenceView::setStride(int stride)
{
  if (stride != 1 && stride != 2 && stride != 4)
  {
    throw errorAbout("reference", "the grid is every pixel, every 2nd or every 4th");
  }
  if (stride != stride_)
  {
    stride_ = stride;
    stop();
    scheduleRefresh();
  }
}

void ReferenceView::setOptions(const ReferenceOptions& options)
{
  options_ = options;
  stop();
  scheduleRefresh();
}

bool ReferenceView::running() const
{
  return active_ && !complete_ && failure_.isEmpty();
}

double ReferenceView::secondsElapsed() const
{
  if (finalSeconds_ >= 0.0)
  {
    return finalSeconds_;
  }
  return active_ && clock_.isValid() ? castSeconds_ + 1e-3 * double(clock_.elapsed()) : 0.0;
}

double ReferenceView::secondsLeft() const
{
  if (complete_)
  {
    return 0.0;
  }
  const std::size_t done = pixelsDone();
  if (!active_ || done == 0 || !clock_.isValid())
  {
    return -1.0;
  }
  // The pixels of one run cost about the same: the time so far per pixel done.
  const double perPixel = 1e-3 * double(clock_.elapsed()) / double(done);
  return perPixel * double(pixelsTotal() - done);
}

DisplaySettings ReferenceView::display() const
{
  return displayFromParameters(model_->parameters());
}

void ReferenceView::scheduleRefresh()
{
  if (!refresh_->isActive())
  {
    refresh_->start();
  }
}

bool ReferenceView::viewStill() const
{
  return !view_->interacting() && !view_->lightingBusy() && !luts_->busy();
}

void ReferenceView::refresh()
{
  const QString why = QString::fromStdString(view_->referenceUnsupported());
  if (why != unsupported_)
  {
    unsupported_ = why;
    emit unsupportedChanged(why);
  }
  if (!enabled_)
  {
    stop();
    return;
  }
  if (!why.isEmpty() || !viewStill())
  {
    // Anything that moves the view makes what was computed stale at once.
    stop();
    emit changed(); // the state, or the display transform, may have changed
    return;
  }
  const SceneView::ReferenceKey key = view_->referenceKey();
  if (!active_ || key != key_)
  {
    start(key);
  }
  compare();
  emit changed();
}

void ReferenceView::start(const SceneView::ReferenceKey& key)
{
  stop();
  std::shared_ptr<const ReferenceInputs> inputs;
  try
  {
    inputs = std::make_shared<const ReferenceInputs>(view_->referenceInputs());
  }
  catch (const Error& e)
  {
    // Reported once: the view as it is stays without a reference until it changes.
    active_ = true;
    key_ = key;
    failure_ = QString::fromStdString(e.what());
    emit errorOccurred(failure_);
    return;
  }
  const int id = ++runId_;
  active_ = true;
  key_ = key;
  auto cancel = std::make_shared<std::atomic<bool>>(false);
  cancel_ = cancel;
  clock_.start();
  const int stride = stride_;
  const ReferenceOptions options = options_;
  const int chunk = kChunkPerThread * std::max(1, QThread::idealThreadCount());
  pool_->start(
      [this, id, inputs, cancel, stride, options, chunk]
      {
        // The window's own work, its renders above all (a CPU rasteriser draws on the same
        // cores), comes first; the reference takes what is left, all of it once the view has
        // converged.
        lowerThreadPriority();
        Run run;
        QString failure;
        try
        {
          run.pixels = runProgressiveReference(
              *inputs, stride, options, *cancel, chunk,
              [&](const ReferenceGrid& grid)
              {
                run.total = static_cast<long long>(grid.total());
                QMetaObject::invokeMethod(
                    this, [this, id, grid] { gridArrived(id, grid); }, Qt::QueuedConnection);
              },
              [&](const SceneReference& pixels)
              {
                QMetaObject::invokeMethod(
                    this, [this, id, pixels] { pixelsArrived(id, pixels); }, Qt::QueuedConnection);
              });
        }
        catch (const Error& e)
        {
          failure = QString::fromStdString(e.what());
        }
        catch (const std::bad_alloc&)
        {
          failure = tr("reference: not enough memory");
        }
        run.cancelled = cancel->load();
        QMetaObject::invokeMethod(
            this, [this, id, run, failure] { runEnded(id, run, failure); }, Qt::QueuedConnection);
      });
}

void ReferenceView::stop()
{
  if (cancel_)
  {
    cancel_->store(true);
    cancel_.reset();
  }
  ++runId_; // what the cancelled run still delivers is dropped
  const bool had = active_ || !reference_.pixels.empty() || error_ || !failure_.isEmpty();
  active_ = false;
  complete_ = false;
  failure_.clear();
  key_ = {};
  grid_ = {};
  reference_ = {};
  boundError_ = boundNorm_ = 0.0;
  castSeconds_ = 0.0;
  finalSeconds_ = -1.0;
  clock_.invalidate();
  error_.reset();
  errors_ = {};
  if (had)
  {
    emit changed();
  }
}

void ReferenceView::gridArrived(int id, const ReferenceGrid& grid)
{
  if (id != runId_ || !active_)
  {
    return; // a cancelled run's
  }
  grid_ = grid;
  reference_.width = grid.width;
  reference_.height = grid.height;
  castSeconds_ = 1e-3 * double(clock_.elapsed());
  clock_.start(); // the integration's own time, for the estimate
  if (grid_.total() == 0)
  {
    complete_ = true;
    finalSeconds_ = castSeconds_;
  }
  emit changed();
}

void ReferenceView::pixelsArrived(int id, const SceneReference& pixels)
{
  if (id != runId_ || !active_)
  {
    return;
  }
  reference_.pixels.insert(reference_.pixels.end(), pixels.pixels.begin(), pixels.pixels.end());
  reference_.evaluations += pixels.evaluations;
  reference_.unconverged += pixels.unconverged;
  // computeSceneReference's bound over the chunk, sqrt(sum e^2 / sum |ref|^2), folded into the
  // same bound over every pixel so far.
  double norm = 0.0;
  for (const ReferencePixel& p : pixels.pixels)
  {
    norm += glm::dot(p.value, p.value);
  }
  boundError_ += pixels.relativeErrorBound * pixels.relativeErrorBound * norm;
  boundNorm_ += norm;
  reference_.relativeErrorBound = boundNorm_ > 0.0 ? std::sqrt(boundError_ / boundNorm_) : 0.0;
  if (reference_.pixels.size() == grid_.total())
  {
    complete_ = true;
    finalSeconds_ = castSeconds_ + 1e-3 * double(clock_.elapsed());
    reference_.seconds = finalSeconds_;
  }
  compare();
  emit changed();
}

void ReferenceView::runEnded(int id, const Run& run, const QString& failure)
{
  finished_.push_back(run);
  if (id == runId_ && active_ && !failure.isEmpty())
  {
    failure_ = failure;
    emit errorOccurred(failure);
    emit changed();
  }
}

void ReferenceView::compare()
{
  if (!active_)
  {
    return;
  }
  if (!view_->converged())
  {
    // Refining again (another quality, say): compared once it has converged. (A frame that only
    // shows the mean anew, for another exposure, keeps the image.)
    if (view_->accumulatedSamples() < view_->targetSamples())
    {
      viewImage_ = {};
    }
  }
  else if (viewImage_.empty() || viewKey_ != key_)
  {
    // The view's mean once it stopped refining, at the size the reference is of.
    viewImage_ = view_->linearImage();
    viewKey_ = key_;
  }
  const bool comparable = viewKey_ == key_ && !viewImage_.empty() &&
                          viewImage_.width == key_.width && viewImage_.height == key_.height &&
                          !reference_.pixels.empty();
  if (!comparable)
  {
    error_.reset();
    errors_ = {};
    return;
  }
  error_ = compareToReference(viewImage_, reference_);
  errors_ = errorMap(viewImage_, reference_);
}

QString ReferenceView::progressText() const
{
  if (!enabled_)
  {
    return tr("The reference is off.");
  }
  if (!unsupported_.isEmpty())
  {
    return tr("No reference: %1.").arg(unsupported_);
  }
  if (!active_)
  {
    return tr("Waiting for the view to settle…");
  }
  if (!failure_.isEmpty())
  {
    return tr("No reference: %1").arg(failure_);
  }
  const QString grid = QString::fromStdString(referenceStrideText(stride_));
  if (pixelsTotal() == 0 && !complete_)
  {
    return tr("Casting the rays of %1…").arg(grid);
  }
  const QLocale locale;
  const QString counts = tr("%1 of %2 pixels (%3)")
                             .arg(locale.toString(qulonglong(pixelsDone())),
                                  locale.toString(qulonglong(pixelsTotal())), grid);
  if (complete_ && pixelsTotal() == 0)
  {
    return tr("No pixel of the view can be compared: none is covered with its 3 × 3 "
              "neighbourhood at %1.")
        .arg(grid);
  }
  if (complete_)
  {
    return tr("%1, complete in %2.").arg(counts, seconds(secondsElapsed()));
  }
  const double left = secondsLeft();
  return left < 0.0 ? tr("%1…").arg(counts) : tr("%1, about %2 left.").arg(counts, seconds(left));
}

QString ReferenceView::summary() const
{
  if (!enabled_)
  {
    return {};
  }
  if (!unsupported_.isEmpty())
  {
    return tr("No reference: %1").arg(unsupported_);
  }
  if (!failure_.isEmpty())
  {
    return tr("No reference: %1").arg(failure_);
  }
  // Short: the status bar holds it beside the samples and the predicted error.
  const int done =
      pixelsTotal() > 0 ? int(100.0 * double(pixelsDone()) / double(pixelsTotal())) : 0;
  if (!error_)
  {
    if (!active_)
    {
      return tr("Reference: waiting for the view to settle");
    }
    if (complete_)
    {
      return tr("Reference complete: waiting for the view to converge");
    }
    const double left = secondsLeft();
    return left < 0.0 ? tr("Reference: %1% done").arg(done)
                      : tr("Reference: %1% done, about %2 left").arg(done).arg(seconds(left));
  }
  const ImageError& e = *error_;
  const double bound = reference_.relativeErrorBound;
  QString text;
  if (!std::isfinite(e.relativeL2))
  {
    text = e.nonFinite > 0 ? tr("the view has NaN or infinite pixels where the reference has none")
                           : tr("the reference is black where compared");
  }
  else if (e.relativeL2 <= bound)
  {
    text = tr("the view is %1 from the reference, within its own %2 bound")
               .arg(percent(e.relativeL2), percent(bound));
  }
  else
  {
    text = tr("the view is %1 from the reference, beyond its own %2 bound")
               .arg(percent(e.relativeL2), percent(bound));
  }
  if (!complete_)
  {
    text += tr(" (on %1% of its pixels)").arg(done);
  }
  return text;
}
} // namespace aniso
