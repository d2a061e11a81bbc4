// Small-scale microstructure sampling (core/microstructure/microstructure.h): K x K points of
// the pixel's footprint in structure space, each finding the structure point it sees (normal,
// parallax or parallax occlusion mapping), optionally shadowed per light, shaded with GGX and
// Smith-Schlick or normalised Blinn-Phong around that point's normal.
uniform sampler2D microHeight; // R32F, bilinear, repeating: h in [0, 1], 1 at the top
uniform sampler2D microNormal; // RGB32F: unit tangent-space normal
uniform sampler2D microAlbedo; // RGB32F
uniform float microDepth;      // tile widths between h = 1 and h = 0
uniform float microTiles;      // structure tiles per unit of texture coordinate
uniform int microK;            // samples per axis
uniform int microJittered;
uniform int microFrameSeed;
uniform int microMasking; // 0 normal, 1 parallax, 2 parallax occlusion
uniform int microSelfShadowing;
uniform int microBrdf; // 0 GGX with Smith-Schlick, 1 normalised Blinn-Phong
uniform float microRoughness;
uniform float microBlinnExponent;
uniform vec3 microF0;
uniform int microMarchSteps;
#ifdef MICRO_TPR
// RG32F, bilinear, repeating: the brushing direction (x along t, y along b) the structure's y
// axis follows (core turnMicroPixel).
uniform sampler2D microTpr;
#endif

uint microHash(uint x)
{
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

// core hashedUniform(seed, a, 0).
float microUniform(uint seed, uint a)
{
  return float(microHash(seed ^ microHash(a ^ microHash(0x9e3779b9u)))) * (1.0 / 4294967296.0);
}

float microSurfaceDepth(vec2 p)
{
  return microDepth * (1.0 - textureLod(microHeight, p, 0.0).r);
}

// The first intersection of the view ray entering at p with the height field: a linear search
// in equal depth steps refined by regula falsi. Returns the hit point; depth below the top in
// hitDepth.
vec2 microMarch(vec2 p, vec3 v, out float hitDepth)
{
  vec2 drift = -v.xy / max(v.z, 1e-6);
  int steps = max(microMarchSteps, 1);
  float previous = 0.0;
  float previousGap = -microSurfaceDepth(p);
  hitDepth = 0.0;
  if (previousGap >= 0.0)
  {
    return p;
  }
  for (int i = 1; i <= steps; ++i)
  {
    float d = microDepth * float(i) / float(steps);
    float g = d - microSurfaceDepth(p + drift * d);
    if (g >= 0.0)
    {
      float a = previous;
      float ga = previousGap;
      float b = d;
      float gb = g;
      for (int k = 0; k < 8 && gb - ga > 0.0; ++k)
      {
        float c = a - ga * (b - a) / (gb - ga);
        float gc = c - microSurfaceDepth(p + drift * c);
        if (gc >= 0.0)
        {
          b = c;
          gb = gc;
        }
        else
        {
          a = c;
          ga = gc;
        }
        if (abs(gc) < 1e-7 * microDepth)
        {
          break;
        }
      }
      hitDepth = gb - ga > 0.0 ? a - ga * (b - a) / (gb - ga) : b;
      return p + drift * hitDepth;
    }
    previous = d;
    previousGap = g;
  }
  hitDepth = microDepth;
  return p + drift * microDepth;
}

// Whether the structure rises above the segment from (q, depth) towards l before the top.
bool microShadowed(vec2 q, float depth, vec3 l)
{
  if (!(l.z > 0.0) || !(depth > 0.0))
  {
    return false;
  }
  vec2 drift = l.xy / l.z;
  int n = max(1, int(ceil(float(max(microMarchSteps, 1)) * depth / microDepth)));
  float bias = 1e-4 * microDepth;
  for (int i = 1; i <= n; ++i)
  {
    float rise = depth * float(i) / float(n);
    if (microSurfaceDepth(q + drift * rise) < depth - rise - bias)
    {
      return true;
    }
  }
  return false;
}

// Specular f around the unit normal m (both BRDFs are isotropic: only cosines matter).
vec3 microSpecular(vec3 v, vec3 l, vec3 m)
{
  float vm = dot(v, m);
  float lm = dot(l, m);
  if (!(vm > 0.0) || !(lm > 0.0))
  {
    return vec3(0.0);
  }
  vec3 h = normalize(v + l);
  float hm = dot(h, m);
  if (microBrdf == 1)
  {
    if (!(hm > 0.0))
    {
      return vec3(0.0);
    }
    float e = microBlinnExponent;
    return microF0 * (0.25 * (e + 2.0) / (2.0 * leadrPi) * exp(e * log(hm)));
  }
  float alpha2 = microRoughness * microRoughness;
  float k = 0.5 * microRoughness;
  float g = vm / (vm * (1.0 - k) + k) * (lm / (lm * (1.0 - k) + k));
  float s = max(1.0 - hm * hm, 0.0) / alpha2 + hm * hm;
  float d = hm > 0.0 ? 1.0 / (leadrPi * alpha2 * s * s) : 0.0;
  return leadrSchlick(microF0, dot(v, h)) * (d * g / max(4.0 * vm * lm, 1e-30));
}
