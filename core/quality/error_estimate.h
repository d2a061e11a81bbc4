#pragma once
// The error of a progressive mean, estimated from its own frames: a still view that stops when
// its image is as close to converged as asked, whatever the environment and the lobe, instead of
// after a sample count chosen beforehand.
//
// The mean M_F of F frames is compared with the mean M_{F/2} of its first half. With A and B the
// means of the first and the second half, M_F - M_{F/2} = (B - A) / 2. Were the frames
// independent and alike, E|M_F - M_{F/2}|^2 = E|M_F - E M_F|^2 per pixel: an unbiased estimate
// of the mean's variance. The renderer's frames are not independent: from frame 2 on they are
// blocks of one (0, 2)-sequence, and frames [0, 2^a) and [2^a, 2^(a+1)) are each one net
// (docs/METHOD.md, "Progressive frames"), so each half is as well stratified as the frames allow
// and the whole better still: the estimate then errs high, by at most about sqrt(2) where the
// error falls as 1/N (the view refines somewhat longer than it needs). Comparing even frames
// with odd ones instead would compare halves that are not nets, and errs high by far more (4x
// on the default scene). What changes from frame to frame on purpose (filtered sampling's blur
// shrinking with the frame index) shows as error too; a bias common to all frames (a split sum's
// approximation) does not. GL-free and Qt-free.
#include "core/image/image.h"

#include <vector>

namespace aniso
{
// Frame counts after which the mean is kept for a later estimate: 2^k and 3 x 2^k from 2 on
// (2, 3, 4, 6, 8, 12, 16, 24, ...). Each is half a later one.
bool isErrorSnapshot(int frames);

// Frame counts at which the error is estimated: the snapshots from 4 on, each twice an earlier
// snapshot. A view that reaches its target between two of them stops at the next, at most 1.5
// times the frames it needed.
bool isErrorCheckpoint(int frames);

// The fewest samples per pixel before an estimate may stop a view: 256, the fixed count the
// still view took before it stopped by its error. Fewer frames make too few halves to trust:
// under Blender's city HDRI, for the lobe (20000, 70), the estimate after 8 and 12 frames of 16
// samples was half and two thirds of the error against the reference (after 16 to 64 frames
// the estimate was again at or above the error less the reference's own floor).
constexpr int kMinimumErrorStopSamples = 256;
// The frames of SAMPLES_PER_FRAME samples that make kMinimumErrorStopSamples (rounded up).
int minimumErrorStopFrames(int samplesPerFrame);

// A view stops when its estimate is at most this share of its error target. From 16 frames on
// the estimate measured 0.73 to 2.3 times the error against the CPU reference (the sphere under
// the studio and Blender's eight HDRIs, four lobes, docs/BENCHMARKS.md "The still view stops by
// its own error"): the error can be a third above the estimate where it sits in a few pixels
// (a sun's or a lamp's reflection) that two halves of 8 frames sample alike.
constexpr double kErrorStopShare = 0.75;
// Whether ESTIMATE (estimatedRelativeError; negative: none) lets a view with error target
// TARGET stop: a known estimate at most kErrorStopShare x TARGET.
bool errorTargetReached(double estimate, double target);

// The estimated relative L2 error of MEAN (RGBA, alpha the surfaces' coverage), the mean of F
// frames, from HALF, the mean of its first F / 2 frames: sqrt(sum c |M_rgb - H_rgb|^2 / sum c
// |M_rgb|^2) over the pixels, each weighed by its coverage c in MEAN (the background is not the
// material's error). Negative when no pixel is covered, the covered pixels are black or a value
// is not finite. Throws aniso::Error "error estimate: reason" when the images differ in size or
// lack four channels.
double estimatedRelativeError(const Image& mean, const Image& half);

// Pixels that stop refining before the view does (adaptive sampling per pixel): at a
// checkpoint, a covered pixel whose squared difference |M_F - M_{F/2}|^2, averaged over its 3 x 3
// neighbourhood, is below kFreezeShare x (kErrorStopShare x target)^2 x the mean signal
// c |M|^2 of the covered pixels is frozen: the renderer draws it no more (the material discards
// it, the accumulation keeps its mean) and its error stays what was estimated when it froze. Were
// every pixel frozen at that level, the image's estimate would be sqrt(kFreezeShare) of the
// stopping level. Only pixels fully covered, with their eight neighbours fully covered too, freeze:
// an edge keeps refining its anti-aliasing. Frozen pixels are each the mean of their own frames,
// so the image stays unbiased where the halves are independent (for a Gaussian mean the
// difference of the halves is independent of the mean they average to).
constexpr double kFreezeShare = 0.25;
// The first checkpoint at which pixels may freeze: 16 frames (halves of 8), where a view of 16
// samples a frame may stop (kMinimumErrorStopSamples). Freezing from 4 frames on, the still
// view of the sphere under Blender's sunrise, lobe (20000, 70), stopped at 24 frames 1.5% from
// the reference (0.84% without freezing) with an estimate of 0.7%: pixels frozen on halves of 2
// frames held more error than their halves showed.
constexpr int kFreezeFromFrames = 16;
// Pixels freeze in tiles of this side, aligned in GL's rows (from the bottom), all of a tile's
// pixels that meet the level or none.
constexpr int kFreezeTile = 4;

struct FrozenPixels
{
  int width = 0;
  int height = 0;
  std::vector<unsigned char> mask; // width x height, row 0 at the top (as Image); 1 = frozen
  std::vector<float> error;        // a frozen pixel's squared error, as estimated at freezing
  int count = 0;                   // pixels frozen

  bool frozen(int x, int y) const { return !mask.empty() && mask[std::size_t(y) * width + x] != 0; }
};

// Freezes (adds to FROZEN, sized to MEAN on first use) the pixels of MEAN and HALF (as
// estimatedRelativeError's) that meet kFreezeShare for the error target TARGET; returns how many
// froze now. Pixels frozen before stay frozen. Throws as estimatedRelativeError.
int freezeConvergedPixels(const Image& mean, const Image& half, double target,
                          FrozenPixels& frozen);

// estimatedRelativeError with FROZEN's pixels counted by their errors at freezing (their means
// no longer change, so M_F - M_{F/2} says nothing of them).
double estimatedRelativeError(const Image& mean, const Image& half, const FrozenPixels& frozen);
} // namespace aniso
