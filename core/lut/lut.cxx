#include "core/lut/lut.h"

#include "core/error.h"
#include "core/sampling/hammersley.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <glm/geometric.hpp>
#include <string>
#include <system_error>
#include <thread>

namespace aniso
{
namespace
{
constexpr double kPi = 3.14159265358979323846;
constexpr std::size_t kLanes = 4;

void checkRange(const char* name, int value, int low, int high)
{
  if (value < low || value > high)
  {
    throw errorAbout(name, "must be in [" + std::to_string(low) + ", " + std::to_string(high) +
                               "], got " + std::to_string(value));
  }
}

void checkThreads(int threads)
{
  if (threads < 0)
  {
    throw errorAbout("threads",
                     "must be >= 0 (0: all hardware threads), got " + std::to_string(threads));
  }
}

// Runs rowFn(row) for every row in [0, rows), spread over `threads` threads (0: all hardware
// threads) that take rows one at a time. Each row is computed by one call, so the result does
// not depend on the schedule. Small jobs stay on the calling thread: starting a thread costs
// more than they do. If the system refuses a thread, the calling thread does its share.
// A set cancel flag makes the workers take no further row, and then throws BakeCancelled.
template <class RowFn>
void forEachRow(int rows, int threads, double workPerRow, const std::atomic<bool>* cancel,
                const RowFn& rowFn)
{
  int count = threads > 0 ? threads : static_cast<int>(std::thread::hardware_concurrency());
  constexpr double kWorkPerThread = 32768.0; // inner-loop iterations that justify a thread
  const double total = workPerRow * rows;
  count = std::max(1, std::min({count, rows, static_cast<int>(total / kWorkPerThread) + 1}));

  std::atomic<int> next{0};
  auto work = [&]()
  {
    for (int row = next.fetch_add(1); row < rows; row = next.fetch_add(1))
    {
      if (cancel && cancel->load(std::memory_order_relaxed))
      {
        return;
      }
      rowFn(row);
    }
  };
  std::vector<std::thread> pool;
  pool.reserve(static_cast<std::size_t>(count - 1));
  for (int k = 1; k < count; ++k)
  {
    try
    {
      pool.emplace_back(work);
    }
    catch (const std::system_error&)
    {
      break;
    }
  }
  work();
  for (std::thread& t : pool)
  {
    t.join();
  }
  if (cancel && cancel->load())
  {
    throw BakeCancelled("bake: cancelled");
  }
}

// The N half vectors of a bake, by component: they depend on the lobe only, not on the view.
struct HalfVectorSet
{
  std::vector<double> x, y, z;
};

HalfVectorSet halfVectorSamples(const AsLobe& lobe, int samples)
{
  HalfVectorSet set;
  const auto n = static_cast<uint32_t>(samples);
  // Padded to whole lanes with h = 0, which has v.h = 0 for every view and adds 0.
  const std::size_t padded = (std::size_t(n) + kLanes - 1) / kLanes * kLanes;
  set.x.assign(padded, 0.0);
  set.y.assign(padded, 0.0);
  set.z.assign(padded, 0.0);
  for (uint32_t k = 0; k < n; ++k)
  {
    const glm::dvec3 h = sampleHalfVector(lobe, hammersley(k, n));
    set.x[k] = h.x;
    set.y[k] = h.y;
    set.z[k] = h.z;
  }
  return set;
}

// sizeBiasAt over precomputed half vectors: kLanes partial sums in a fixed order (so the
// compiler can use SIMD without reassociating, and the result never depends on the machine
// schedule), branch-free body.
glm::dvec2 sizeBiasOver(const HalfVectorSet& h, int samples, const glm::dvec3& v)
{
  double s[kLanes] = {};
  double b[kLanes] = {};
  const std::size_t count = h.x.size();
  for (std::size_t k = 0; k < count; k += kLanes)
  {
    for (std::size_t lane = 0; lane < kLanes; ++lane)
    {
      const double hx = h.x[k + lane];
      const double hy = h.y[k + lane];
      const double hz = h.z[k + lane];
      const double vh = v.x * hx + v.y * hy + v.z * hz;
      const double nl = 2.0 * vh * hz - v.z;
      // n.l / max(n.v, n.l) where n.l > 0 and v.h > 0, else 0 (the floor only avoids 0/0).
      const double lit = vh > 0.0 ? std::max(nl, 0.0) : 0.0;
      const double weight = lit / std::max(std::max(v.z, lit), 1e-300);
      const double m = 1.0 - std::min(std::max(vh, 0.0), 1.0);
      const double m2 = m * m;
      const double chi = m2 * m2 * m;
      s[lane] += weight * (1.0 - chi);
      b[lane] += weight * chi;
    }
  }
  double sumS = 0.0;
  double sumB = 0.0;
  for (std::size_t lane = 0; lane < kLanes; ++lane)
  {
    sumS += s[lane];
    sumB += b[lane];
  }
  const double inv = 1.0 / static_cast<double>(samples);
  return {sumS * inv, sumB * inv};
}
} // namespace

void checkLutInputs(const AsLobe& lobe, int size, int samples)
{
  validateLobe(lobe);
  checkRange("size", size, kMinLutSize, kMaxLutSize);
  checkRange("samples", samples, 1, kMaxLutSamples);
}

glm::dvec2 brdfLutCoords(const glm::dvec3& view)
{
  const double u = (2.0 / kPi) * std::atan2(std::abs(view.y), std::abs(view.x));
  const double v = std::sqrt(std::max(view.z, 0.0));
  return {u, std::min(v, 1.0)};
}

glm::dvec3 brdfLutView(const glm::dvec2& uv)
{
  const double v = std::min(std::max(uv.y, 0.0), 1.0);
  const double nv = v * v;
  const double tangential = std::sqrt(std::max(0.0, 1.0 - nv * nv));
  const double phi = 0.5 * kPi * uv.x;
  return {std::cos(phi) * tangential, std::sin(phi) * tangential, nv};
}

glm::dvec2 sizeBiasAt(const AsLobe& lobe, const glm::dvec3& view, int samples)
{
  validateLobe(lobe);
  checkRange("samples", samples, 1, kMaxLutSamples);
  if (!(view.z >= 0.0))
  {
    return {0.0, 0.0}; // no reflection towards a view below the horizon
  }
  return sizeBiasOver(halfVectorSamples(lobe, samples), samples, view);
}

HalfVectorLut bakeHalfVectorLut(const AsLobe& lobe, int size, int threads,
                                const std::atomic<bool>* cancel)
{
  checkLutInputs(lobe, size);
  checkThreads(threads);
  HalfVectorLut lut;
  lut.size = size;
  lut.lobe = lobe;
  lut.rgba.resize(std::size_t(size) * size * 4);
  const double inv = 1.0 / size;
  forEachRow(size, threads, 64.0 * size, cancel,
             [&](int j)
             {
               float* row = lut.rgba.data() + std::size_t(j) * size * 4;
               for (int i = 0; i < size; ++i)
               {
                 const glm::dvec3 h = sampleHalfVector(lobe, {(i + 0.5) * inv, (j + 0.5) * inv});
                 row[4 * i + 0] = static_cast<float>(h.x);
                 row[4 * i + 1] = static_cast<float>(h.y);
                 row[4 * i + 2] = static_cast<float>(h.z);
                 row[4 * i + 3] = static_cast<float>(log2PdfHalfVector(lobe, h));
               }
             });
  return lut;
}

BrdfLut bakeBrdfLut(const AsLobe& lobe, int size, int samples, int threads,
                    const std::atomic<bool>* cancel)
{
  checkLutInputs(lobe, size, samples);
  checkThreads(threads);
  BrdfLut lut;
  lut.size = size;
  lut.samples = samples;
  lut.lobe = lobe;
  lut.rg.resize(std::size_t(size) * size * 2);
  const HalfVectorSet halfVectors = halfVectorSamples(lobe, samples);
  const double inv = 1.0 / size;
  forEachRow(size, threads, double(size) * samples, cancel,
             [&](int j)
             {
               float* row = lut.rg.data() + std::size_t(j) * size * 2;
               for (int i = 0; i < size; ++i)
               {
                 const glm::dvec3 view = brdfLutView({(i + 0.5) * inv, (j + 0.5) * inv});
                 const glm::dvec2 sb = sizeBiasOver(halfVectors, samples, view);
                 row[2 * i + 0] = static_cast<float>(sb.x);
                 row[2 * i + 1] = static_cast<float>(sb.y);
               }
             });
  return lut;
}
} // namespace aniso
