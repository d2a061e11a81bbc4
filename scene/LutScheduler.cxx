#include "scene/LutScheduler.h"

#include "core/background_priority.h"
#include "core/error.h"
#include "core/lut/lut_cache.h"

#include <QFutureWatcher>
#include <QThreadPool>
#include <QTimer>
#include <QtConcurrent>
#include <algorithm>
#include <chrono>
#include <cmath>

namespace aniso
{
namespace
{
struct Outcome
{
  LutResult result;
  QString error;
  bool cancelled = false;
};

uchar byte(double v)
{
  return static_cast<uchar>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
}

// Dark blue -> purple -> orange -> pale yellow, monotonic in brightness so the order of values
// reads without a legend.
QRgb falseColour(double t)
{
  static const double stops[5][3] = {{0.02, 0.02, 0.20},
                                     {0.35, 0.05, 0.50},
                                     {0.80, 0.25, 0.30},
                                     {0.98, 0.60, 0.10},
                                     {1.00, 1.00, 0.75}};
  const double x = std::clamp(t, 0.0, 1.0) * 4.0;
  const int k = std::min(3, static_cast<int>(x));
  const double f = x - k;
  double c[3];
  for (int i = 0; i < 3; ++i)
  {
    c[i] = stops[k][i] + f * (stops[k + 1][i] - stops[k][i]);
  }
  return qRgb(byte(c[0]), byte(c[1]), byte(c[2]));
}

// LUT row j (xi2 or v growing with j) drawn from the bottom up, so the image reads like a plot.
int displayRow(int size, int j)
{
  return size - 1 - j;
}
} // namespace

QImage halfVectorPreview(const HalfVectorLut& lut)
{
  QImage image(lut.size, lut.size, QImage::Format_RGB32);
  for (int j = 0; j < lut.size; ++j)
  {
    auto* line = reinterpret_cast<QRgb*>(image.scanLine(displayRow(lut.size, j)));
    for (int i = 0; i < lut.size; ++i)
    {
      const float* h = &lut.rgba[(std::size_t(j) * lut.size + i) * 4];
      line[i] = qRgb(byte((h[0] + 1.0) / 2.0), byte((h[1] + 1.0) / 2.0), byte((h[2] + 1.0) / 2.0));
    }
  }
  return image;
}

QImage pdfPreview(const HalfVectorLut& lut, double range[2])
{
  double lo = INFINITY;
  double hi = -INFINITY;
  for (std::size_t t = 0; t < std::size_t(lut.size) * lut.size; ++t)
  {
    lo = std::min(lo, double(lut.rgba[t * 4 + 3]));
    hi = std::max(hi, double(lut.rgba[t * 4 + 3]));
  }
  range[0] = lo;
  range[1] = hi;
  const double span = hi > lo ? hi - lo : 1.0;
  QImage image(lut.size, lut.size, QImage::Format_RGB32);
  for (int j = 0; j < lut.size; ++j)
  {
    auto* line = reinterpret_cast<QRgb*>(image.scanLine(displayRow(lut.size, j)));
    for (int i = 0; i < lut.size; ++i)
    {
      line[i] = falseColour((lut.rgba[(std::size_t(j) * lut.size + i) * 4 + 3] - lo) / span);
    }
  }
  return image;
}

QImage brdfPreview(const BrdfLut& lut, double* maxBias)
{
  double top = 0.0;
  for (std::size_t t = 0; t < std::size_t(lut.size) * lut.size; ++t)
  {
    top = std::max(top, double(lut.rg[t * 2 + 1]));
  }
  *maxBias = top;
  QImage image(lut.size, lut.size, QImage::Format_RGB32);
  for (int j = 0; j < lut.size; ++j)
  {
    auto* line = reinterpret_cast<QRgb*>(image.scanLine(displayRow(lut.size, j)));
    for (int i = 0; i < lut.size; ++i)
    {
      const float* sb = &lut.rg[(std::size_t(j) * lut.size + i) * 2];
      line[i] = qRgb(byte(sb[0]), byte(top > 0.0 ? sb[1] / top : 0.0), 0);
    }
  }
  return image;
}

LutScheduler::LutScheduler(SceneModel* model, LutCache* cache, QObject* parent)
    : QObject(parent), model_(model), cache_(cache ? cache : &LutCache::shared()),
      debounce_(new QTimer(this)), pool_(new QThreadPool(this))
{
  qRegisterMetaType<LutRequest>();
  qRegisterMetaType<LutResult>();
  debounce_->setSingleShot(true);
  debounce_->setInterval(kDefaultDebounceMs);
  // Two workers: a stale bake that is still finishing never holds up the latest one.
  pool_->setMaxThreadCount(2);
  connect(debounce_, &QTimer::timeout, this, &LutScheduler::requestNow);
  connect(model_, &SceneModel::valueChanged, this, &LutScheduler::modelChanged);
}

LutScheduler::~LutScheduler()
{
  if (cancelLatest_)
  {
    cancelLatest_->store(true);
  }
  pool_->waitForDone();
}

void LutScheduler::setDebounceMs(int ms)
{
  debounce_->setInterval(ms);
}

bool LutScheduler::busy() const
{
  return busy_;
}

void LutScheduler::waitForIdle()
{
  pool_->waitForDone();
}

void LutScheduler::modelChanged(const QString& key)
{
  if (sceneKeyAffects(key.toStdString(), Affects::Luts))
  {
    setBusy(true);
    debounce_->start();
  }
}

void LutScheduler::setBusy(bool busy)
{
  if (busy != busy_)
  {
    busy_ = busy;
    emit busyChanged(busy);
  }
}

void LutScheduler::requestNow()
{
  debounce_->stop();
  LutRequest request;
  request.lobe = model_->parameters().lobe();
  request.size = model_->integer("lut-size");
  request.samples = model_->integer("lut-samples");
  if (haveLatest_ && request == latest_)
  {
    // Already asked for (a drag that came back to where it started): nothing new to bake.
    if (current_.id == latestId_)
    {
      setBusy(false);
    }
    return;
  }
  if (cancelLatest_)
  {
    cancelLatest_->store(true);
  }
  const int id = ++latestId_;
  latest_ = request;
  haveLatest_ = true;
  auto cancel = std::make_shared<std::atomic<bool>>(false);
  cancelLatest_ = cancel;
  setBusy(true);
  emit bakeStarted(request);

  auto* watcher = new QFutureWatcher<Outcome>(this);
  connect(watcher, &QFutureWatcher<Outcome>::finished, this,
          [this, watcher]
          {
            const Outcome outcome = watcher->result();
            watcher->deleteLater();
            if (outcome.result.id != latestId_ || outcome.cancelled)
            {
              return; // a newer request is on its way
            }
            if (!debounce_->isActive())
            {
              setBusy(false);
            }
            if (!outcome.error.isEmpty())
            {
              emit bakeFailed(outcome.error);
              return;
            }
            current_ = outcome.result;
            emit lutsReady(current_);
          });
  LutCache* cache = cache_;
  watcher->setFuture(QtConcurrent::run(
      pool_,
      [cache, request, id, cancel]
      {
        lowerThreadPriority();
        Outcome outcome;
        outcome.result.id = id;
        outcome.result.request = request;
        const auto start = std::chrono::steady_clock::now();
        try
        {
          const uint64_t bakesBefore = cache->stats().bakes;
          LutResult& r = outcome.result;
          r.halfVector = cache->halfVector(request.lobe, request.size, cancel.get());
          r.brdf = cache->brdf(request.lobe, request.size, request.samples, cancel.get());
          r.baked = cache->stats().bakes != bakesBefore;
          r.halfVectorImage = halfVectorPreview(*r.halfVector);
          r.pdfImage = pdfPreview(*r.halfVector, r.pdfRange);
          r.brdfImage = brdfPreview(*r.brdf, &r.maxBias);
        }
        catch (const BakeCancelled&)
        {
          outcome.cancelled = true;
        }
        catch (const Error& e)
        {
          outcome.error = QString::fromStdString(e.what());
        }
        catch (const std::bad_alloc&)
        {
          outcome.error = QObject::tr("lookup tables: not enough memory");
        }
        outcome.result.seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return outcome;
      }));
}
} // namespace aniso
