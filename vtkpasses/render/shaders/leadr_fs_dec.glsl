// LEADR mapping (core/leadr/leadr.h): slope moments, filtered by the texture hardware, define an
// anisotropic Beckmann distribution per fragment; lights, the environment on a slope-space grid
// (per-sample cube level) and SH9 irradiance for the rough diffuse part.
uniform sampler2D leadrMoments;   // RGBA32F mip chain: E[x], E[y], E[x^2], E[y^2]
uniform sampler2D leadrMomentsXY; // R32F mip chain: E[xy]
uniform vec2 leadrMomentsSize;    // texels of level 0
uniform float leadrMaxLevel;      // last level of the chain
uniform float leadrTiles;         // repeats of the map per unit of texture coordinate
uniform vec2 leadrBaseVariance;   // alpha^2 / 2 of the base roughness along t and b
uniform vec3 leadrF0;
uniform vec3 leadrDiffuse;
uniform int leadrPlainNormals; // 1: only the mean slope (a filtered normal map), no variance
uniform int leadrGridN;
// Standard-normal quantiles at (i + s) / n on each axis, s the frame's shift
// (core/leadr/leadr.h makeShiftedSlopeGrid, slopeGridShift): frame 0 the centred grid.
uniform float leadrQuantiles[16];
uniform float leadrQuantilesY[16];
uniform float leadrLog2FrameCount; // log2(k + 1) for progressive frame k
uniform int leadrUseEnvironment;
uniform samplerCube leadrEnvironment;
uniform mat3 leadrWorldToEnvironment;
uniform float leadrLog2TexelSolidAngle; // log2(4 pi / (6 size^2))
uniform float leadrMaxLod;
uniform vec3 leadrIrradianceSH[9]; // SH9 radiance coefficients times the cosine-lobe factors

struct LeadrStats
{
  vec2 mean;
  float varX;
  float varY;
  float cov;
};

LeadrStats leadrStatistics(vec4 m, float mxy)
{
  LeadrStats s;
  s.mean = m.xy;
  float vx = max(m.z - m.x * m.x, 0.0);
  float vy = max(m.w - m.y * m.y, 0.0);
  float limit = 0.999 * sqrt(vx * vy);
  s.cov = clamp(mxy - m.x * m.y, -limit, limit);
  s.varX = vx + leadrBaseVariance.x;
  s.varY = vy + leadrBaseVariance.y;
  return s;
}

float leadrVarianceAlong(LeadrStats s, vec2 d)
{
  return s.varX * d.x * d.x + 2.0 * s.cov * d.x * d.y + s.varY * d.y * d.y;
}

// D(m) = P22(slope of m) / (m.z)^4.
float leadrDistribution(LeadrStats s, vec3 m)
{
  // Below this the slope is beyond 1e6 and the density is 0 (z^4 would underflow first).
  if (!(m.z > 1e-6))
  {
    return 0.0;
  }
  float det = s.varX * s.varY - s.cov * s.cov;
  vec2 d = -m.xy / m.z - s.mean;
  float q = (s.varY * d.x * d.x - 2.0 * s.cov * d.x * d.y + s.varX * d.y * d.y) / det;
  float z2 = m.z * m.z;
  return exp(-0.5 * q) / (2.0 * leadrPi * sqrt(det) * z2 * z2);
}

// Smith G1 of the shifted Gaussian with Walter's approximation of Beckmann's Lambda.
float leadrMasking(LeadrStats s, vec3 w)
{
  if (!(w.z > 0.0))
  {
    return 0.0;
  }
  float r = length(w.xy);
  if (!(r > 0.0))
  {
    return 1.0;
  }
  vec2 d = w.xy / r;
  float a = (w.z / r - dot(s.mean, d)) / sqrt(2.0 * leadrVarianceAlong(s, d));
  if (!(a > 0.0))
  {
    return 0.0;
  }
  float lambda = a >= 1.6 ? 0.0 : (1.0 - 1.259 * a + 0.396 * a * a) / (3.535 * a + 2.181 * a * a);
  return 1.0 / (1.0 + lambda);
}

// A view at or below the geometric horizon lifted just above it, keeping its azimuth.
vec3 leadrLiftedView(vec3 v)
{
  const float minCosine = 1e-3;
  if (v.z >= minCosine)
  {
    return v;
  }
  float r = length(v.xy);
  float s = sqrt(1.0 - minCosine * minCosine);
  return r > 0.0 ? vec3(s * v.xy / r, minCosine) : vec3(s, 0.0, minCosine);
}

// The artificial micronormal: the mean slope moved towards the viewer just enough that the view
// stays above the mean microsurface and its mirror direction above the geometric horizon.
LeadrStats leadrMicronormal(LeadrStats s, vec3 v)
{
  float r = length(v.xy);
  if (!(r > 0.0) || !(v.z > 0.0))
  {
    return s;
  }
  vec2 d = v.xy / r;
  float cotTheta = v.z / r;
  float along = dot(s.mean, d);
  float across = s.mean.y * d.x - s.mean.x * d.y;
  float byMasking = cotTheta - 0.25 * sqrt(2.0 * leadrVarianceAlong(s, d));
  float q = max(0.0, 1.0 - across * across);
  float byReflection = cotTheta * q / (sqrt(1.0 + cotTheta * cotTheta * q) + 1.0);
  float limit = min(byMasking, byReflection);
  if (along > limit)
  {
    s.mean -= (along - limit) * d;
  }
  return s;
}

// Normal of grid point (z1, z2): slope mean + L z with L the Cholesky factor of the covariance.
vec3 leadrGridNormal(LeadrStats s, float z1, float z2)
{
  float l11 = sqrt(s.varX);
  float l21 = s.cov / l11;
  float l22 = sqrt(max(s.varY - l21 * l21, 0.0));
  vec2 slope = s.mean + vec2(l11 * z1, l21 * z1 + l22 * z2);
  return normalize(vec3(-slope, 1.0));
}

vec3 leadrSpecular(LeadrStats s, vec3 v, vec3 l)
{
  if (!(v.z > 0.0) || !(l.z > 0.0))
  {
    return vec3(0.0);
  }
  vec3 h = normalize(v + l);
  float g = leadrMasking(s, v) * leadrMasking(s, l);
  if (!(g > 0.0))
  {
    return vec3(0.0);
  }
  float value = leadrDistribution(s, h) * g / max(4.0 * v.z * l.z, 1e-30);
  return leadrSchlick(leadrF0, max(dot(v, h), 0.0)) * min(value, 1e30);
}

vec3 leadrIrradiance(vec3 normalWorld)
{
  vec3 d = leadrWorldToEnvironment * normalWorld;
  return leadrIrradianceSH[0] * 0.282094792 +
    leadrIrradianceSH[1] * (0.488602512 * d.y) + leadrIrradianceSH[2] * (0.488602512 * d.z) +
    leadrIrradianceSH[3] * (0.488602512 * d.x) + leadrIrradianceSH[4] * (1.092548431 * d.x * d.y) +
    leadrIrradianceSH[5] * (1.092548431 * d.y * d.z) +
    leadrIrradianceSH[6] * (0.315391565 * (3.0 * d.z * d.z - 1.0)) +
    leadrIrradianceSH[7] * (1.092548431 * d.x * d.z) +
    leadrIrradianceSH[8] * (0.546274215 * (d.x * d.x - d.y * d.y));
}
