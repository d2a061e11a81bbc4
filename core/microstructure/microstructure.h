#pragma once
// Small-scale microstructure (docs/METHOD.md, source 4): a small repeating structure (albedo, normal,
// height) far finer than a pixel, shaded by sampling it K x K times inside each pixel's footprint
// and averaging. Each sample finds the structure point it sees (normal mapping, parallax
// mapping or parallax occlusion mapping), optionally tests its shadowing towards each light, and
// evaluates a microfacet BRDF (GGX with Smith-Schlick masking, or normalised Blinn-Phong) around
// that point's normal. Cost grows linearly with K^2.
//
// Structure space: one tile is [0, 1)^2 (x along the tangent t, y along b) and repeats; heights
// h in [0, 1] put a point depth * (1 - h) below the mesh surface (h = 1 is the top, in tile
// widths), so normals follow from the slopes depth * grad(h). Image row 0 is y = 1.
#include "core/frame.h"
#include "core/image/image.h"
#include "core/lights/light.h"

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

namespace aniso
{
struct Microstructure
{
  double depth = 0.1; // tile widths between h = 1 and h = 0
  Image albedo;       // RGB in [0, 1]
  Image normal;       // RGB, unit, tangent space (from the height and depth)
  Image height;       // R in [0, 1]
};

enum class MicroPattern
{
  Pyramids,         // square pyramids, apex at the tile centre
  InvertedPyramids, // square pits with a flat, coloured bottom
  Grooves,          // parallel V-grooves along y, one per tile (with a circular TPR: brushed disk)
  Silk              // plain weave of round threads, golden warp along x over/under crimson weft
};

// Depth range of a structure (tile widths).
constexpr double kMicroMaxDepth = 2.0;

// size x size texels (size in [4, 1024]), depth in (0, kMicroMaxDepth]; otherwise aniso::Error
// "microstructure: reason". Heights are the analytic profiles sampled at texel centres; normals
// are central differences of the heights (wrapping), so they match what the ray march sees.
Microstructure makeMicrostructure(MicroPattern pattern, int size = 64, double depth = 0.1);

// From images: height (channel 0, clamped to [0, 1]) and albedo (RGB, or grey from 1 channel),
// both tiling and of the same size. Throws aniso::Error "microstructure: reason".
Microstructure microstructureFromImages(const Image& height, const Image& albedo, double depth);

struct MicroTexel
{
  glm::dvec3 albedo{0.0};
  glm::dvec3 normal{0.0, 0.0, 1.0}; // unit
  double height = 1.0;
};

// Bilinear lookup with wrapping at structure point p (the normal renormalised).
MicroTexel sampleMicrostructure(const Microstructure& structure, const glm::dvec2& p);

// Where the view ray through structure point p (entering at the top, travelling along -v, v in
// tangent space with v.z > 0) meets the height field: a linear search of `steps` equal depth
// steps, refined by regula falsi. depth is the hit's depth below the top.
struct MicroHit
{
  glm::dvec2 point{0.0};
  double depth = 0.0;
};
MicroHit marchParallaxOcclusion(const Microstructure& structure, const glm::dvec2& p,
                                const glm::dvec3& v, int steps);

// Whether the structure rises above the segment from (q, depth) towards the light l (tangent
// space, l.z > 0) before the segment reaches the top; `steps` equal steps over the full depth.
bool shadowedTowards(const Microstructure& structure, const glm::dvec2& q, double depth,
                     const glm::dvec3& l, int steps);

enum class MicroMasking
{
  Normal,           // the sample sees the point straight below it
  Parallax,         // shifted by the depth at the sample (one step)
  ParallaxOcclusion // the first intersection along the view ray
};

enum class MicroBrdf
{
  GgxSmithSchlick, // GGX D (brdf/ggx.h), G1 = n.w / (n.w (1 - k) + k), k = alpha / 2, Schlick F
  BlinnPhong       // normalised Blinn-Phong (brdf/blinn_phong_aniso.h), exponent e, F0 as k_s
};

struct MicroShadingOptions
{
  int samplesPerAxis = 4; // K, in [1, 64]
  bool jittered = false;  // one uniform random point per grid cell instead of its centre
  std::uint32_t seed = 0; // jitter sequence (vary it per pixel)
  MicroMasking masking = MicroMasking::ParallaxOcclusion;
  bool selfShadowing = false;
  MicroBrdf brdf = MicroBrdf::GgxSmithSchlick;
  double roughness = 0.3;       // GGX alpha, in [1e-3, 1]
  double blinnExponent = 100.0; // in [0, 1e6]
  glm::dvec3 f0{0.04};          // specular reflectance at normal incidence, in [0, 1]
  int marchSteps = 32;          // in [1, 1024]
};

// Throws aniso::Error naming the option ("samples per axis: ...", "roughness: ...", ...).
void validateMicroOptions(const MicroShadingOptions& options);

// The pixel's footprint in structure space: the parallelogram centre + a axisU + b axisV,
// a, b in [-1/2, 1/2] (from the screen-space derivatives of the structure coordinates).
struct PixelFootprint
{
  glm::dvec2 centre{0.5, 0.5};
  glm::dvec2 axisU{1.0, 0.0};
  glm::dvec2 axisV{0.0, 1.0};
};

// Tangent-plane rotation (TPR, core/maps/tpr_map.h) of the structure: a TPR map gives per pixel
// the brushing direction r = (x, y) in the tangent plane (x along t, y along b), as it does for
// the Ashikhmin-Shirley material, and the structure turns so that its y axis, the direction its
// grooves run along, follows r. The turned frame is (r.y t - r.x b, r.x t + r.y b, n) and a
// structure point p becomes (r.y p.x - r.x p.y, r.x p.x + r.y p.y); r = (0, 1) turns nothing.
// With the circular pattern the grooves run around the centre: a brushed disk.

// The map's unit direction at texture coordinate uv: the wrapping bilinear lookup of its first
// two channels (the shader's), normalised; (0, 1), no turn, where it vanishes (a circular
// pattern's centre) or the map is empty.
glm::dvec2 sampleTprDirection(const Image& tprMap, const glm::dvec2& uv);

struct TurnedPixel
{
  Frame frame;
  PixelFootprint footprint;
};

// FRAME and FOOTPRINT of a pixel turned so the structure's y axis follows DIRECTION (unit, in the
// frame's tangent plane); shadeMicroPixel of the result shades the turned structure.
TurnedPixel turnMicroPixel(const Frame& frame, const PixelFootprint& footprint,
                           const glm::dvec2& direction);

// Average over the K x K samples of sum over lights of f(v, l) E (n_k . l)+ [unshadowed], with
// f = albedo / pi + f_spec in the frame of the sample's normal n_k. Samples whose normal faces
// away from the view, lights below the pixel frame's horizon and views below it contribute
// nothing. The sum of the two terms is not energy-bounded by itself (each term is).
glm::dvec3 shadeMicroPixel(const Microstructure& structure, const MicroShadingOptions& options,
                           const PixelFootprint& footprint, const Frame& frame,
                           const glm::dvec3& position, const glm::dvec3& viewWorld,
                           const std::vector<Light>& lights);
} // namespace aniso
