#pragma once
// Keeps the lookup tables of the current material baked, off the UI thread.
//
// It watches n_u, n_v, LUT size and LUT samples in the model. A change restarts a debounce
// timer, so a slider drag asks for exactly one bake, once the values have stayed put for the
// debounce interval. Each request goes to a worker thread that takes the half-vector and BRDF
// LUTs from the LutCache (baking what is missing) and makes their preview images there too.
// The latest request wins: a newer one sets the cancel flag of the one in flight (the bakers
// stop within a few rows), and results of stale requests are dropped. Returning to earlier values
// is a memory hit of the cache.
#include "core/brdf/ashikhmin_shirley.h"
#include "core/lut/lut.h"
#include "scene/SceneModel.h"

#include <QImage>
#include <QObject>
#include <QString>
#include <atomic>
#include <memory>

class QThreadPool;
class QTimer;

namespace aniso
{
class LutCache;

struct LutRequest
{
  AsLobe lobe;
  int size = 0;
  int samples = 0;

  bool operator==(const LutRequest& o) const
  {
    return lobe.nu == o.lobe.nu && lobe.nv == o.lobe.nv && size == o.size && samples == o.samples;
  }
};

struct LutResult
{
  int id = 0; // the request's sequence number
  LutRequest request;
  std::shared_ptr<const HalfVectorLut> halfVector;
  std::shared_ptr<const BrdfLut> brdf;
  double seconds = 0.0;   // wall time of the request on the worker, previews included
  bool baked = false;     // the cache computed at least one of them (else memory or disk)
  QImage halfVectorImage; // h as colour: RGB = (h + 1) / 2
  QImage pdfImage;        // log2 p_h, false colour between pdfRange
  QImage brdfImage;       // R = s, G = b / max b
  double pdfRange[2] = {0.0, 0.0};
  double maxBias = 0.0;
};

class LutScheduler : public QObject
{
  Q_OBJECT

public:
  static constexpr int kDefaultDebounceMs = 150;

  // CACHE null: LutCache::shared(), the one the renderer uses.
  explicit LutScheduler(SceneModel* model, LutCache* cache = nullptr, QObject* parent = nullptr);
  ~LutScheduler() override;

  void setDebounceMs(int ms);
  // True from a change of the inputs until its LUTs are ready (or failed).
  bool busy() const;
  // The LUTs of the latest finished request (empty before the first).
  const LutResult& current() const { return current_; }
  LutCache& cache() const { return *cache_; }

  // Asks now for the model's current inputs, without waiting for the debounce.
  void requestNow();
  // Blocks until the worker threads are idle (tests and shutdown).
  void waitForIdle();

signals:
  void bakeStarted(const aniso::LutRequest& request);
  void lutsReady(const aniso::LutResult& result);
  void bakeFailed(const QString& message);
  void busyChanged(bool busy);

private:
  void modelChanged(const QString& key);
  void setBusy(bool busy);

  SceneModel* model_;
  LutCache* cache_;
  QTimer* debounce_;
  QThreadPool* pool_;
  int latestId_ = 0;
  LutRequest latest_;
  bool haveLatest_ = false;
  std::shared_ptr<std::atomic<bool>> cancelLatest_;
  LutResult current_;
  bool busy_ = false;
};

// Preview images of LUTs (also used by LutScheduler's workers).
QImage halfVectorPreview(const HalfVectorLut& lut);
QImage pdfPreview(const HalfVectorLut& lut, double range[2]);
QImage brdfPreview(const BrdfLut& lut, double* maxBias);
} // namespace aniso

Q_DECLARE_METATYPE(aniso::LutRequest)
Q_DECLARE_METATYPE(aniso::LutResult)
