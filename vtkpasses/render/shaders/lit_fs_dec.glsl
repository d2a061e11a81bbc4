// Lit models, fragment shader declarations (docs/METHOD.md, source 2): the shift-variant material's
// texel, the per-pixel frame, point and directional lights, and one model chosen by a #define
// (LIT_MODEL_ASHIKHMIN_SHIRLEY, _BANKS, _BLINN_PHONG, _WARD or _HEIDRICH_SEIDEL). Each function
// mirrors its CPU twin in core/brdf (same names in the comments).
#ifdef LIT_LINE
// A line set: varyings with VTK's VSOut suffix, passed on by its wide-line geometry shader
// (ShaderHook.h, lineGeometryCode).
#define litTangentWC litTangentWCVSOut
#define litClipPosition litClipPositionVSOut
#endif
#ifdef LIT_HAVE_NORMALS
in vec3 litNormalWC;
#endif
#ifdef LIT_HAVE_TANGENTS
in vec3 litTangentWC;
#endif
#ifdef LIT_HAVE_TCOORDS
in vec2 litTCoord;
#endif
in vec4 litClipPosition;

uniform mat4 litClipToWorld; // inverse of the camera's world-to-clip transform
// Lights: xyz = direction towards the light (w = 0) or position (w = 1), world space.
uniform int litLightCount;
uniform vec4 litLightVector[LIT_MAX_LIGHTS];
uniform vec3 litLightIntensity[LIT_MAX_LIGHTS]; // irradiance (dir) or intensity (point)
// The material (core/models/sv_material.h), tiling texture space:
uniform sampler2D litTangentAlpha;   // tangent x, y, alpha_x, alpha_y
uniform sampler2D litAlbedoSpecular; // diffuse albedo RGB, k_s in alpha
uniform sampler2D litNormalMap;      // tangent-space normal, signed

const float litPi = 3.14159265358979;
const float litMinAlpha = 1e-3;
const float litMaxAlpha = 10.0;
const float litMaxExponent = 1e6;
const float litFibreMaxSpecular = 1e3;

vec3 litAnyPerpendicular(vec3 n)
{
  vec3 axis = abs(n.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
  return normalize(axis - dot(axis, n) * n);
}

// Frame::fromNormalTangent: t is the hint made orthogonal to unit n.
mat3 litFrame(vec3 n, vec3 hint)
{
  vec3 t = hint - dot(hint, n) * n;
  t = dot(t, t) > 1e-12 ? normalize(t) : litAnyPerpendicular(n);
  return mat3(t, cross(n, t), n);
}

// perturbedFrame: the base frame tilted by the smallest rotation taking its normal to the map
// normal (the quaternion frame of source 1), then t turned to the map tangent in that plane.
mat3 litPerturbedFrame(mat3 base, vec3 mapNormal, vec2 mapTangent)
{
  float rxy = length(mapNormal.xy);
  float a = sqrt(max(0.5 * (mapNormal.z + 1.0), 0.0));
  float halfSine = sqrt(max(0.5 * (1.0 - mapNormal.z), 0.0));
  vec2 bc = rxy > 0.0 ? vec2(mapNormal.y, -mapNormal.x) / rxy * halfSine
                      : (mapNormal.z < 0.0 ? vec2(1.0, 0.0) : vec2(0.0));
  float b = bc.x;
  float c = bc.y;
  vec3 t = normalize(base * vec3(a * a + b * b - c * c, 2.0 * b * c, 2.0 * a * c));
  vec3 bt = normalize(base * vec3(2.0 * b * c, a * a - b * b + c * c, -2.0 * a * b));
  vec3 n = normalize(base * vec3(-2.0 * a * c, 2.0 * a * b, a * a - b * b - c * c));
  if (mapTangent != vec2(0.0))
  {
    t = mapTangent.x * t + mapTangent.y * bt;
  }
  return litFrame(n, t);
}

// ln(n.h) for unit h with h.z > 0 (sv::logCosTheta): near the pole 1 - (n.h)^2 comes from the
// tangent components, with a series for ln(1 - x) where float's 1 - x would lose it.
float litLogCosTheta(vec3 h)
{
  float x = h.x * h.x + h.y * h.y;
  if (x < 1e-2)
  {
    return -0.5 * x * (1.0 + x * (0.5 + x * (1.0 / 3.0 + x * 0.25)));
  }
  return x < 0.5 ? 0.5 * log(1.0 - x) : log(h.z);
}

// w_x cos^2(phi) + w_y sin^2(phi) of the tangent-plane direction (x, y); the mean at (0, 0).
float litAzimuthalBlend(float wx, float wy, float x, float y)
{
  float m = max(abs(x), abs(y));
  if (!(m > 0.0))
  {
    return 0.5 * (wx + wy);
  }
  float a = x / m;
  float b = y / m;
  return (wx * a * a + wy * b * b) / (a * a + b * b);
}

// The shift-variant texel (sampleSvMaps), in the tangent space of the texture.
struct LitTexel
{
  vec3 normal;
  vec2 tangent;
  float alphaX;
  float alphaY;
  vec3 diffuse;
  float specular;
};

LitTexel litSampleTexel(vec2 uv)
{
  LitTexel s;
  vec4 ta = texture(litTangentAlpha, uv);
  float len = length(ta.xy);
  s.tangent = len > 1e-12 ? ta.xy / len : vec2(1.0, 0.0);
  s.alphaX = clamp(ta.z, litMinAlpha, litMaxAlpha);
  s.alphaY = clamp(ta.w, litMinAlpha, litMaxAlpha);
  vec4 as = texture(litAlbedoSpecular, uv);
  s.diffuse = clamp(as.rgb, 0.0, 1.0);
  s.specular = clamp(as.a, 0.0, 1.0);
  vec3 n = texture(litNormalMap, uv).xyz;
  float nlen = length(n);
  s.normal = nlen > 1e-12 ? n / nlen : vec3(0.0, 0.0, 1.0);
  return s;
}

// V.R' of a fibre along +X (fibreSpecularCosine).
float litFibreSpecularCosine(vec3 v, vec3 l)
{
  float value = sqrt(max(1.0 - l.x * l.x, 0.0)) * sqrt(max(1.0 - v.x * v.x, 0.0)) - l.x * v.x;
  return clamp(value, -1.0, 1.0);
}

// Fibre parameters of a texel (toBanks, toHeidrichSeidel): e = 1 / (2 alpha_x^2) and k_s
// scaled to a specular albedo of about k_s.
float litFibreExponent(LitTexel s)
{
  return min(1.0 / (2.0 * s.alphaX * s.alphaX), litMaxExponent);
}
float litFibreSpecular(LitTexel s, float e)
{
  return min(s.specular * sqrt(e / (2.0 * litPi)) / litPi, litFibreMaxSpecular);
}
float litFibreHighlight(float cosR, float e)
{
  return cosR > 0.0 ? exp2(e * log2(cosR)) : 0.0;
}

// Radiance per unit irradiance in tangent space (v, l unit, both above the horizon), cosine
// included: the model's term of sumOverLights.
vec3 litTerm(LitTexel s, vec3 v, vec3 l)
{
#if defined(LIT_MODEL_BANKS)
  // evalBanks (n.l)
  float e = litFibreExponent(s);
  float ks = litFibreSpecular(s, e);
  float f = ks * litFibreHighlight(litFibreSpecularCosine(v, l), e);
  return (s.diffuse * (sqrt(max(1.0 - l.x * l.x, 0.0)) / litPi) + f) * l.z;
#elif defined(LIT_MODEL_HEIDRICH_SEIDEL)
  // heidrichSeidelTerm: the fibre highlight is not attenuated by n.l
  float e = litFibreExponent(s);
  float ks = litFibreSpecular(s, e);
  return s.diffuse * (l.z / litPi) + ks * litFibreHighlight(litFibreSpecularCosine(v, l), e);
#elif defined(LIT_MODEL_BLINN_PHONG)
  // evalBlinnPhongAniso (n.l), the exponent from the scaled tangents t/alpha_x, b/alpha_y
  vec3 h = normalize(v + l);
  vec3 tScaled = vec3(1.0 / s.alphaX, 0.0, 0.0);
  vec3 bScaled = vec3(0.0, 1.0 / s.alphaY, 0.0);
  float ht = dot(h, tScaled);
  float hb = dot(h, bScaled);
  float sin2 = h.x * h.x + h.y * h.y;
  float ex = 1.0 / (s.alphaX * s.alphaX);
  float ey = 1.0 / (s.alphaY * s.alphaY);
  float exponent = sin2 > 0.0 ? (ht * ht + hb * hb) / sin2 : 0.5 * (ex + ey);
  float d = sqrt((ex + 2.0) * (ey + 2.0)) / (2.0 * litPi) * exp(exponent * litLogCosTheta(h));
  return (s.diffuse / litPi + vec3(s.specular * 0.25 * d)) * l.z;
#elif defined(LIT_MODEL_WARD)
  // evalWardFactored (n.l): S(p) = 1/sqrt(p), E(m, d) = exp(-2 m / (1 + d))
  vec3 h = normalize(v + l);
  float ht = h.x / s.alphaX;
  float hb = h.y / s.alphaY;
  float m = ht * ht + hb * hb;
  float gaussian = exp(-2.0 * m / (1.0 + h.z));
  float lobe = 1.0 / (4.0 * litPi * s.alphaX * s.alphaY) * inversesqrt(max(l.z * v.z, 1e-30)) *
               gaussian;
  return (s.diffuse / litPi + vec3(s.specular * lobe)) * l.z;
#else
  // evalAshikhminShirley (n.l): evalSpecular + evalAsDiffuse, n = 2 / alpha^2 - 2
  float nu = clamp(2.0 / (s.alphaX * s.alphaX) - 2.0, 0.0, litMaxExponent);
  float nv = clamp(2.0 / (s.alphaY * s.alphaY) - 2.0, 0.0, litMaxExponent);
  vec3 h = normalize(v + l);
  float vh = 0.5 * (dot(v, h) + dot(l, h));
  vec3 f0 = vec3(s.specular);
  vec3 specular = vec3(0.0);
  if (vh > 0.0)
  {
    float exponent = litAzimuthalBlend(nu, nv, h.x, h.y);
    float ph = sqrt((nu + 1.0) * (nv + 1.0)) / (2.0 * litPi) * exp(exponent * litLogCosTheta(h));
    float mf = 1.0 - clamp(vh, 0.0, 1.0);
    float chi = mf * mf * mf * mf * mf;
    specular = (f0 + (1.0 - f0) * chi) * (ph / max(4.0 * vh * max(v.z, l.z), 1e-30));
  }
  float ml = 1.0 - 0.5 * l.z;
  float mv = 1.0 - 0.5 * v.z;
  float diffuseScale = 28.0 / (23.0 * litPi) * (1.0 - ml * ml * ml * ml * ml) *
                       (1.0 - mv * mv * mv * mv * mv);
  return (specular + s.diffuse * (1.0 - f0) * diffuseScale) * l.z;
#endif
}

// sumOverLights at a world-space point: lights below the frame's horizon (or a view below it)
// contribute nothing; point lights fall off as 1 / distance^2.
vec3 litShade(LitTexel s, mat3 frame, vec3 position, vec3 viewWorld)
{
  vec3 radiance = vec3(0.0);
  vec3 v = viewWorld * frame;
  if (!(v.z > 0.0))
  {
    return radiance;
  }
  for (int i = 0; i < litLightCount; ++i)
  {
    vec3 direction = litLightVector[i].xyz;
    vec3 irradiance = litLightIntensity[i];
    if (litLightVector[i].w > 0.5)
    {
      vec3 toLight = direction - position;
      float distance = length(toLight);
      if (!(distance > 1e-9))
      {
        continue;
      }
      direction = toLight / distance;
      irradiance /= distance * distance;
    }
    vec3 l = direction * frame;
    if (!(l.z > 0.0))
    {
      continue;
    }
    radiance += litTerm(s, v, l) * irradiance;
  }
  return radiance;
}
