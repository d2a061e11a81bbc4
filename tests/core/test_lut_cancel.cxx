// Cancelling LUT bakes (the flag an interactive caller sets when newer inputs make a bake
// stale): a set flag stops the bakers with BakeCancelled, the cache stores nothing for it, and
// a caller waiting for the same LUT from a cancelled bake still gets it, bit-identical to a
// direct bake (the reference).
#include "core/lut/lut.h"
#include "core/lut/lut_cache.h"

#include <atomic>
#include <chrono>
#include <cstring>
#include <future>
#include <gtest/gtest.h>
#include <thread>

namespace
{
const aniso::AsLobe kLobe{2000.0, 60.0};

// A set flag before the bake: nothing is computed, both bakers throw BakeCancelled.
TEST(LutCancel, SetFlagStopsBothBakers)
{
  std::atomic<bool> cancel{true};
  EXPECT_THROW(aniso::bakeHalfVectorLut(kLobe, 32, 0, &cancel), aniso::BakeCancelled);
  EXPECT_THROW(aniso::bakeBrdfLut(kLobe, 32, 64, 0, &cancel), aniso::BakeCancelled);
  std::atomic<bool> go{false};
  const aniso::BrdfLut lut = aniso::bakeBrdfLut(kLobe, 8, 16, 0, &go);
  const aniso::BrdfLut reference = aniso::bakeBrdfLut(kLobe, 8, 16);
  EXPECT_EQ(0, std::memcmp(lut.rg.data(), reference.rg.data(), lut.rg.size() * sizeof(float)));
}

// A flag set from another thread during a bake that would take minutes stops it.
TEST(LutCancel, FlagSetDuringABakeStopsIt)
{
  std::atomic<bool> cancel{false};
  std::thread canceller(
      [&]
      {
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        cancel = true;
      });
  EXPECT_THROW(aniso::bakeBrdfLut(kLobe, 1024, 1 << 16, 0, &cancel), aniso::BakeCancelled);
  canceller.join();
}

// The cache: a cancelled request stores nothing (the next one bakes); a second caller that was
// waiting on the cancelled bake makes the LUT itself and gets the right one.
TEST(LutCancel, CacheKeepsNothingAndWaitersCarryOn)
{
  aniso::LutCache cache("none");
  std::atomic<bool> cancel{true};
  EXPECT_THROW(cache.brdf(kLobe, 16, 64, &cancel), aniso::BakeCancelled);
  EXPECT_EQ(cache.stats().bakes, 0u);
  EXPECT_NE(cache.brdf(kLobe, 16, 64), nullptr);
  EXPECT_EQ(cache.stats().bakes, 1u);

  // First caller: a long bake, cancelled once the second caller is waiting on it.
  const int size = 128;
  const int samples = 1 << 14;
  std::atomic<bool> first{false};
  auto cancelled = std::async(std::launch::async,
                              [&]
                              {
                                try
                                {
                                  cache.brdf(kLobe, size, samples, &first);
                                  return false;
                                }
                                catch (const aniso::BakeCancelled&)
                                {
                                  return true;
                                }
                              });
  std::this_thread::sleep_for(std::chrono::milliseconds(30));
  std::atomic<bool> second{false};
  auto waiter = std::async(std::launch::async,
                           [&]
                           {
                             try
                             {
                               return cache.brdf(kLobe, size, samples, &second) != nullptr ? 1 : 0;
                             }
                             catch (const aniso::BakeCancelled&)
                             {
                               return 2; // only its own flag may stop it
                             }
                           });
  std::this_thread::sleep_for(std::chrono::milliseconds(30));
  first = true;
  EXPECT_TRUE(cancelled.get());
  // The waiter now bakes on its own; stop it too (a full bake would take seconds) and check
  // it was still going, i.e. it had not taken the first caller's cancellation as its own.
  EXPECT_EQ(waiter.wait_for(std::chrono::milliseconds(100)), std::future_status::timeout);
  second = true;
  EXPECT_EQ(waiter.get(), 2);

  // A waiter whose first caller is cancelled completes with the same bits as a direct bake.
  std::atomic<bool> third{false};
  auto slow = std::async(std::launch::async,
                         [&]
                         {
                           try
                           {
                             cache.halfVector(kLobe, 512, &third);
                           }
                           catch (const aniso::BakeCancelled&)
                           {
                           }
                         });
  std::this_thread::sleep_for(std::chrono::milliseconds(5));
  auto other = std::async(std::launch::async, [&] { return cache.halfVector(kLobe, 512); });
  third = true;
  slow.get();
  const auto lut = other.get();
  const aniso::HalfVectorLut reference = aniso::bakeHalfVectorLut(kLobe, 512);
  ASSERT_EQ(lut->rgba.size(), reference.rgba.size());
  EXPECT_EQ(0, std::memcmp(lut->rgba.data(), reference.rgba.data(),
                           reference.rgba.size() * sizeof(float)));
}
} // namespace
