#pragma once
// Built-in sample materials for the lit models (docs/METHOD.md, source 2), made procedurally and
// deterministically (the same maps on every machine): a plate scratched along both axes, metal
// brushed along the parallels or the meridians of the built-in sphere, and marble with raised
// veins. All maps tile.
#include "core/models/sv_material.h"

#include <cstdint>

namespace aniso
{
// Brushing on the built-in sphere, whose tangent (+u) runs along the parallels:
// Latitudinal brushing follows the parallels (tangent +u), Longitudinal the meridians (+v).
enum class BrushDirection
{
  Latitudinal,
  Longitudinal
};

// Brushed steel: smooth along the brushing (alpha 0.05), rough across it (0.35), k_s 0.9, a dark
// diffuse 0.02.
SvTexel brushedMetal(BrushDirection direction);

// A polished steel plate (isotropic alpha 0.08) with straight scratches, half of them along u and
// half along v: inside a scratch the tangent follows it, alpha is 0.03 along and 0.4 across, and
// the surface is carved (height below 0, normals from the groove profile). size x size texels,
// size in [16, 4096]; otherwise aniso::Error "scratched plate: reason".
SvMaps scratchedPlate(int size = 512, std::uint32_t seed = 1);

// Marble: a warm white base with faint clouding and darker grey-green veins that stand out of the
// surface (height up to veinHeight texture units, >= 0 everywhere, 0 on the base); polished
// (alpha 0.06) with slightly rougher veins (0.15); dielectric k_s 0.04. size in [16, 4096],
// veinHeight in [0, 0.1]; otherwise aniso::Error "marble: reason".
SvMaps veinedMarble(int size = 512, double veinHeight = 0.004, std::uint32_t seed = 1);
} // namespace aniso
