#pragma once
// Low-discrepancy points for the per-fragment sample loops and the LUT bakers.
#include <cstdint>

#include <glm/vec2.hpp>

namespace aniso
{
// Base-2 radical inverse (van der Corput) of i, in [0, 1).
double radicalInverse2(uint32_t i);

// Point i of an n-point Hammersley set: (i / n, radicalInverse2(i)). Requires n > 0, i < n.
glm::dvec2 hammersley(uint32_t i, uint32_t n);

// Cranley-Patterson rotation: fract(p + shift), kept strictly below 1.
glm::dvec2 cranleyPatterson(const glm::dvec2& p, const glm::dvec2& shift);

// Shift of progressive frame k: frame 0 is (0, 0) (the unrotated set); later frames follow
// the R2 low-discrepancy sequence, so the union of frames stays well stratified.
glm::dvec2 frameShift(uint32_t frame);
} // namespace aniso
