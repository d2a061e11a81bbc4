#pragma once
// A part's placement in its scene: an affine 4x4 matrix, row-major, from the part's own frame
// (where its mesh file put it, and where its tangent model's axes are given) to the scene's.
#include "core/error.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace aniso
{
using PartMatrix = std::array<double, 16>;

constexpr PartMatrix kIdentityPlacement{1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0,
                                        0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0};

// Throws aniso::Error "SUBJECT: reason" unless every element is finite, the last row is
// 0 0 0 1 (affine) and the linear part is invertible (|det| above 1e-12 of its scale^3).
inline void checkPlacement(const PartMatrix& m, const std::string& subject)
{
  for (double v : m)
  {
    if (!std::isfinite(v))
    {
      throw errorAbout(subject, "a placement element is not a finite number");
    }
  }
  if (m[12] != 0.0 || m[13] != 0.0 || m[14] != 0.0 || m[15] != 1.0)
  {
    throw errorAbout(subject, "a placement's last row must be 0 0 0 1");
  }
  const double det = m[0] * (m[5] * m[10] - m[6] * m[9]) - m[1] * (m[4] * m[10] - m[6] * m[8]) +
                     m[2] * (m[4] * m[9] - m[5] * m[8]);
  double scale = 0.0;
  for (int i : {0, 1, 2, 4, 5, 6, 8, 9, 10})
  {
    scale = std::max(scale, std::abs(m[std::size_t(i)]));
  }
  if (!(std::abs(det) > 1e-12 * scale * scale * scale))
  {
    throw errorAbout(subject, "a placement that flattens the part (its matrix is singular)");
  }
}
} // namespace aniso
