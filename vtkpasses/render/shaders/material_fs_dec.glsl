// Anisotropic material, fragment shader declarations: Ashikhmin-Shirley specular by importance
// sampling of the environment cubemap (docs/METHOD.md, source 1), Lambert diffuse from SH9
// irradiance, and the optional frame maps. The #define lines above this text select the variant.
#ifdef ANISO_LINE
// A line set (VSOut becomes GSOut here when VTK's wide-line geometry shader runs).
#define anisoTangentWC anisoTangentWCVSOut
#define anisoClipPosition anisoClipPositionVSOut
#endif
// The lobe's density evaluated here: half vectors built in the shader, or MIS weights. (GLSL
// before 4.20 has no line continuation: one condition a line.)
#if !defined(ANISO_HALF_VECTORS_FROM_LUT) || defined(ANISO_ENVIRONMENT_MIS)
#define ANISO_LOBE_DENSITY
#elif defined(ANISO_ENVIRONMENT_SOURCES)
#define ANISO_LOBE_DENSITY
#endif
#ifdef ANISO_HAVE_NORMALS
in vec3 anisoNormalWC;
#endif
#ifdef ANISO_HAVE_TANGENTS
in vec3 anisoTangentWC;
#endif
#ifdef ANISO_HAVE_TCOORDS
in vec2 anisoTCoord;
#endif
in vec4 anisoClipPosition;

uniform mat4 anisoClipToWorld;       // inverse of the camera's world-to-clip transform
uniform vec3 anisoF0;                // Schlick reflectance at normal incidence, linear RGB
uniform vec3 anisoAlbedo;            // Lambert albedo, linear RGB
uniform int anisoSampleCount;        // N, importance samples per fragment and frame
uniform vec2 anisoFrameShift;        // this frame's rotation of the Hammersley set
// Sets of 2 to 16 (kMaxSequenceCount) points are a block of a (0,2)-sequence (from frame 0 on
// for a power of two, else from frame 2 on: core/sampling/hammersley.h progressivePoint): N =
// anisoSequenceCount of them (0: the rotated Hammersley set instead), point i the sequence's
// point i XOR anisoSequenceBlock, the bits of the block's first point (as ints: the same bits),
// the first coordinate of point i from the four columns anisoSequenceColumns (sequenceColumns).
uniform int anisoSequenceCount;
uniform ivec2 anisoSequenceBlock;
uniform ivec4 anisoSequenceColumns;
uniform float anisoLog2FrameCount;   // log2(k + 1) for progressive frame k
uniform mat3 anisoWorldToEnvironment; // undoes the environment rotation about Z
uniform samplerCube anisoEnvironment;
uniform float anisoLog2TexelSolidAngle; // log2(4 pi / (6 size^2)) of mip level 0
uniform float anisoMaxLod;
#ifdef ANISO_FIELD_LOBE
float anisoLodAnisotropy; // per fragment, from the field's lobe (set before any sample)
#else
uniform float anisoLodAnisotropy; // 0.25 log2((n_max + 1) / (n_min + 1)), see anisoSampleLod
#endif
uniform float anisoLodBias;       // added to every filtered level
uniform float anisoPixelDecorrelation; // 1: each pixel shifts its sample set by a hash, 0: not
uniform vec3 anisoIrradianceSH[9]; // SH9 radiance coefficients times the cosine-lobe factors

#ifdef ANISO_HALF_VECTORS_FROM_LUT
uniform sampler2D anisoHalfVectorLut; // RGBA32F: h in tangent space, log2 p_h
uniform int anisoHalfVectorLutSize;
#endif
#ifdef ANISO_FIELD_LOBE
// The field changes the lobe per fragment: the material's exponents scaled (roughness) or
// drawn towards their geometric mean (anisotropy), core/fields/field_mapping.h's fieldLobe.
uniform vec2 anisoMaterialExponents; // the material's (n_u, n_v)
vec2 anisoExponents;                 // per fragment (set before any sample)
#elif defined(ANISO_LOBE_DENSITY)
uniform vec2 anisoExponents; // (n_u, n_v)
#endif
#ifdef ANISO_FIELD
in vec2 anisoField;             // the field's value, and 1 where it is NaN
uniform vec2 anisoFieldRange;   // the values mapped to t = 0 and t = 1
uniform vec2 anisoFieldTargets; // (low, high): the target's values at t = 0 and t = 1
#if defined(ANISO_FIELD_COLOR_ALBEDO) || defined(ANISO_FIELD_COLOR_F0)
uniform sampler2D anisoFieldColors; // W x 1, linear RGB of the colour map at t = i / (W - 1)
uniform int anisoFieldColorCount;   // W
uniform vec3 anisoFieldNanColor;    // linear RGB
#endif
#endif
#ifdef ANISO_ENVIRONMENT_MIS
// Environment importance sampling (core/env/env_sampling.h), in environment coordinates.
uniform sampler2D anisoEnvCdf; // R32F: row y < H the CDF of grid row y, row H the marginal
uniform sampler2D anisoEnvPdf; // RG32F, W x H: density per solid angle of each grid texel, and
                               // the coarsest cube level filtered lookups may read from it
uniform sampler2D anisoEnvGuide; // R32F, as anisoEnvCdf: entry j = the interval of u = j / count
uniform ivec2 anisoEnvGrid;    // (W, H)
uniform float anisoLobeFraction; // share of the lobe technique in the one-sample MIS
#endif
#ifdef ANISO_ENVIRONMENT_SOURCES
// The environment's sources split off (core/env/env_sources.h): anisoEnvironment holds the
// residual; the excess is an equirectangular texture (environment coordinates), sampled by
// groups (core/env/env_source_groups.h): each pixel chooses a group by its lobe, then a texel of
// the group by its excess power.
#define ANISO_SOURCE_GROUPS 8
uniform sampler2D anisoSourceRadiance; // RGB32F excess, bilinear as the whole image
// RGBA32F, 4096 wide: the groups' rows (cumulative within the group, grid row, first entry,
// entries), then the entries (cumulative within the row, texel index, guide), then the rows'
// guides from anisoSourceRowGuides on (EnvironmentLighting::uploadSourceTextures)
uniform sampler2D anisoSourceTables;
uniform int anisoSourceRowGuides;
// RG32F, W x H: a texel's probability within its group times W H / (2 pi^2), its group (-1)
uniform sampler2D anisoSourceDensity;
uniform ivec2 anisoSourceGrid;         // (W, H)
uniform int anisoSourceGroupCount;
uniform vec4 anisoSourceGroupCone[ANISO_SOURCE_GROUPS]; // direction (env), cos of its radius
// Its share of the sources' power, 1 / its solid angle, its first row, its row count.
uniform vec4 anisoSourceGroupInfo[ANISO_SOURCE_GROUPS];
uniform float anisoSourceDefensive; // share of the selection kept in proportion to the power
// A pixel's source samples per frame (core/env/env_source_groups.h, sourceSampleCount):
// anisoSourceSampleCount (M) times 2^k, k from 0 to anisoSourceSampleSteps, as its lobe sees
// sources smaller than itself (smallSourceShare; anisoSourceResidualShare the residual's mean
// luminance over the sources' power).
uniform int anisoSourceSampleCount;
uniform int anisoSourceSampleSteps;
uniform float anisoSourceResidualShare;
// A pixel takes no source samples, its lobe samples reading the sources at weight 1, where the
// second moment they have there is below this share (squared) of its light times N
// (lobeSamplesSuffice in core/env/env_source_groups.h); 0: never. Per group the integral of
// its excess luminance squared, over the sources' power squared.
uniform float anisoSourceLobeOnlyVariance;
uniform float anisoSourceGroupSquared[ANISO_SOURCE_GROUPS];
// The source samples' own blocks of the sequence, one per count M 2^k (as anisoSequenceBlock
// and anisoSequenceColumns for the lobe's): anisoSourceSequenceCounts[k] the count where this
// frame's set is a block (else 0: the rotated Hammersley set).
uniform int anisoSourceSequenceCounts[3];
uniform ivec2 anisoSourceSequenceBlocks[3];
uniform ivec4 anisoSourceSequenceColumns[3];
// The points a frame's pixels share (sourcePoints in core/env/env_source_groups.h; at most
// kMaxSourcePoints): world direction and K times its density (.w), the excess radiance there,
// and the selection they were drawn under. anisoSourcePointCount 0: each pixel draws its own
// source samples instead (a count fixed in the settings).
#define ANISO_SOURCE_POINTS 128
uniform int anisoSourcePointCount;
uniform vec4 anisoSourcePoints[ANISO_SOURCE_POINTS];
uniform vec3 anisoSourcePointRadiance[ANISO_SOURCE_POINTS];
uniform float anisoSourcePointSelection[ANISO_SOURCE_GROUPS];
// Each group's run of the points (first, count): they come ordered by group.
uniform ivec2 anisoSourcePointRuns[ANISO_SOURCE_GROUPS];
#endif
#ifdef ANISO_METHOD_SPLIT_SUM
uniform sampler2D anisoBrdfLut; // RG32F: s, b with F0 s + b the directional albedo
#endif
#ifdef ANISO_NORMAL_MAP
uniform sampler2D anisoNormalMap; // tangent-space normal, signed
#endif
#ifdef ANISO_QUATERNION_MAP
uniform sampler2D anisoQuaternionMap; // (a, b, c) per docs/METHOD.md
#endif
#ifdef ANISO_TPR_MAP
uniform sampler2D anisoTprMap; // (x, y): rotated tangent in the quaternion frame's plane
#endif
#ifdef ANISO_HEIGHT_MAP
uniform sampler2D anisoHeightMap; // R: height in [0, 1], 1 at the top surface
uniform float anisoHeightScale;     // depth of the relief in texture-coordinate units
#endif
#ifdef ANISO_ALBEDO_MAP
uniform sampler2D anisoAlbedoMap; // linear RGB, multiplies anisoAlbedo
#endif
#ifdef ANISO_OCCLUSION_MAP
uniform sampler2D anisoOcclusionMap; // R: ambient occlusion of diffuse and specular light
#endif
#ifdef ANISO_METALLIC_MAP
uniform sampler2D anisoMetallicMap; // R: 1 = the metal F0 and no diffuse, 0 = dielectric
#endif

const float anisoPi = 3.14159265358979;

#ifdef ANISO_FIELD
// t in [0, 1] of the field's value over its range, or -1 where it is NaN.
float anisoFieldParameter()
{
  if (anisoField.y > 0.5)
  {
    return -1.0;
  }
  float span = anisoFieldRange.y - anisoFieldRange.x;
  return span > 0.0 ? clamp((anisoField.x - anisoFieldRange.x) / span, 0.0, 1.0) : 0.5;
}
#if defined(ANISO_FIELD_COLOR_ALBEDO) || defined(ANISO_FIELD_COLOR_F0)
// The colour map at t, read between the table's entries (entry i at its texel's centre).
vec3 anisoFieldColor(float t)
{
  if (t < 0.0)
  {
    return anisoFieldNanColor;
  }
  float w = float(anisoFieldColorCount);
  return textureLod(anisoFieldColors, vec2((t * (w - 1.0) + 0.5) / w, 0.5), 0.0).rgb;
}
#endif
#ifdef ANISO_FIELD_LOBE
// b^e without GLSL's undefined pow(0, 0) and pow of a negative base.
float anisoPower(float b, float e)
{
  return e == 0.0 ? 1.0 : (b <= 0.0 ? 0.0 : pow(b, e));
}

// The exponents at t (fieldLobe in core/fields/field_mapping.cxx); NaN keeps the material's.
vec2 anisoFieldLobe(vec2 n, float t)
{
  if (t < 0.0)
  {
    return n;
  }
  float s = mix(anisoFieldTargets.x, anisoFieldTargets.y, t);
#ifdef ANISO_FIELD_ANISOTROPY
  s = clamp(s, 0.0, 1.0);
  float mean = sqrt(n.x * n.y);
  float towards = anisoPower(mean, 1.0 - s);
  return vec2(towards * anisoPower(n.x, s), towards * anisoPower(n.y, s));
#else
  return clamp(n * s, vec2(0.0), vec2(1e6));
#endif
}
#endif
#endif

// Van der Corput radical inverse in base 2 (bit reversal), as a 32-bit binary fraction.
uint anisoRadicalInverse2Bits(uint bits)
{
  bits = (bits << 16u) | (bits >> 16u);
  bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
  bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
  bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
  bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
  return bits;
}

float anisoRadicalInverse2(uint bits)
{
  return float(anisoRadicalInverse2Bits(bits)) * 2.3283064365386963e-10;
}

// A per-pixel Cranley-Patterson shift (integer hash of the pixel): neighbouring pixels use
// differently rotated point sets, so the error of a few samples shows as fine noise that
// progressive frames average out, not as bands that follow the environment.
vec2 anisoPixelShift()
{
  uvec2 p = uvec2(gl_FragCoord.xy);
  uint h = p.x * 1597334677u ^ p.y * 3812015801u;
  h = (h ^ (h >> 16u)) * 0x7feb352du;
  h = (h ^ (h >> 15u)) * 0x846ca68bu;
  h ^= h >> 16u;
  return anisoPixelDecorrelation * vec2(float(h & 0xffffu), float(h >> 16u)) * (1.0 / 65536.0);
}

// The sequence's first coordinate of i < 16 as a 32-bit binary fraction: the XOR of the columns
// of i's bits (core/sampling/hammersley.h sequenceColumns, the first four).
uint anisoSequenceBits16(uint i, uvec4 columns)
{
  return (columns.x & (0u - (i & 1u))) ^ (columns.y & (0u - ((i >> 1u) & 1u))) ^
         (columns.z & (0u - ((i >> 2u) & 1u))) ^ (columns.w & (0u - ((i >> 3u) & 1u)));
}

// Point i of this frame's set of count points, rotated by the pixel's shift and kept strictly
// below 1: for 2 to 16 points, the frame's block of the (0,2)-sequence (when count is the set's
// sequenceCount, whose block's first point has the bits of block, and columns its generator's
// first four columns), else the Hammersley set rotated by the frame's shift.
vec2 anisoSamplePoint(int i, int count, vec2 shift, int sequenceCount, ivec2 block,
                      ivec4 columns)
{
  vec2 p;
  if (count == sequenceCount)
  {
    uvec2 bits = uvec2(block) ^
      uvec2(anisoSequenceBits16(uint(i), uvec4(columns)), anisoRadicalInverse2Bits(uint(i)));
    p = vec2(bits >> 8u) * (1.0 / 16777216.0);
  }
  else
  {
    p = fract(vec2(float(i) / float(count), anisoRadicalInverse2(uint(i))) + anisoFrameShift);
  }
  return min(fract(p + shift), vec2(0.99999994));
}

// 1 - 2^x for x <= 0, without the cancellation of 1 - exp2(x) near 0 (sin^2 of the sharp
// lobes of large exponents).
float anisoOneMinusExp2(float x)
{
  float y = x * 0.69314718055994531;
  if (y > -0.01)
  {
    return -y * (1.0 + y * (0.5 + y * (1.0 / 6.0)));
  }
  return 1.0 - exp2(x);
}

#ifdef ANISO_HALF_VECTORS_FROM_LUT
vec4 anisoHalfVector(vec2 xi)
{
  ivec2 texel = min(ivec2(xi * float(anisoHalfVectorLutSize)), ivec2(anisoHalfVectorLutSize - 1));
  return texelFetch(anisoHalfVectorLut, texel, 0);
}
#else
// The AS quadrant construction: phi = atan(sqrt((n_u+1)/(n_v+1)) tan(pi x / 2)) in atan2 form
// (no tan(pi/2)), mirrored into four quadrants; cos(theta) = (1 - xi2)^(1/(e + 1)) with
// e = n_u cos^2 phi + n_v sin^2 phi, in log2 so that neither the power nor the density
// overflows. Returns h in tangent space and log2 p_h(h).
vec4 anisoHalfVector(vec2 xi)
{
  float nu = anisoExponents.x;
  float nv = anisoExponents.y;
  float quadrant = min(floor(4.0 * xi.x), 3.0);
  float x = 4.0 * xi.x - quadrant;
  bool mirrored = quadrant == 1.0 || quadrant == 3.0;
  if (mirrored)
  {
    x = 1.0 - x;
  }
  float a = 0.5 * anisoPi * x;
  float phi = atan(sqrt(nu + 1.0) * sin(a), sqrt(nv + 1.0) * cos(a));
  float cosPhi = cos(phi);
  float sinPhi = sin(phi);
  if (quadrant == 1.0 || quadrant == 2.0)
  {
    cosPhi = -cosPhi;
  }
  if (quadrant >= 2.0)
  {
    sinPhi = -sinPhi;
  }
  float e = nu * cosPhi * cosPhi + nv * sinPhi * sinPhi;
  float log2CosTheta = log2(max(1.0 - xi.y, 1e-30)) / (e + 1.0);
  float cosTheta = exp2(log2CosTheta);
  float sinTheta = sqrt(max(anisoOneMinusExp2(2.0 * log2CosTheta), 0.0));
  float log2Norm = 0.5 * (log2(nu + 1.0) + log2(nv + 1.0)) - log2(2.0 * anisoPi);
  return vec4(sinTheta * cosPhi, sinTheta * sinPhi, cosTheta, log2Norm + e * log2CosTheta);
}
#endif

vec3 anisoEnvironmentRadiance(vec3 directionWorld, float lod)
{
  return textureLod(anisoEnvironment, anisoWorldToEnvironment * directionWorld, lod).rgb;
}

// Filtered importance sampling: the level whose texels match the solid angle the sample
// stands for, Omega_s = 1 / (N p_l) (p_l the density of l per solid angle), against Omega_p of
// level 0. An anisotropic lobe's samples spread along its broad axis only: Omega_s is an
// ellipse whose short side, sqrt(Omega_s / r) with r = sqrt((n_max + 1) / (n_min + 1)) the
// ratio of the lobe's widths, is the extent a texel must not exceed, hence the
// anisoLodAnisotropy = 0.5 log2 r term (an isotropic footprint blurs the sharp axis).
// Progressive frame k counts the N (k + 1) samples the mean then holds, so the blur (a bias)
// fades as the view converges instead of staying at the first frame's.
float anisoSampleLod(float log2PdfLight, int count)
{
#ifdef ANISO_FILTERED
  float log2SampleSolidAngle = -log2PdfLight - log2(float(count)) - anisoLog2FrameCount;
  float lod = 0.5 * (log2SampleSolidAngle - anisoLog2TexelSolidAngle) - anisoLodAnisotropy;
  return clamp(lod + anisoLodBias, 0.0, anisoMaxLod);
#else
  return 0.0;
#endif
}

#ifdef ANISO_LOBE_DENSITY
// log2 of the density's normalisation sqrt((n_u+1)(n_v+1))/(2 pi), for the fragment's
// exponents: set once by anisoSpecular before any density below.
float anisoLog2HalfVectorNorm;

void anisoSetHalfVectorNorm()
{
  anisoLog2HalfVectorNorm =
    0.5 * (log2(anisoExponents.x + 1.0) + log2(anisoExponents.y + 1.0)) - log2(2.0 * anisoPi);
}

// log2 of the AS half-vector density sqrt((n_u+1)(n_v+1))/(2 pi) (n.h)^e for h in tangent
// space, e = (n_u h_t^2 + n_v h_b^2) / (1 - h_n^2); -inf below the surface.
float anisoLog2HalfVectorPdf(vec3 h)
{
  if (h.z <= 0.0)
  {
    return -1e30;
  }
  float nu = anisoExponents.x;
  float nv = anisoExponents.y;
  float tangential = h.x * h.x + h.y * h.y;
  float e = tangential > 0.0 ? (nu * h.x * h.x + nv * h.y * h.y) / tangential : 0.5 * (nu + nv);
  return anisoLog2HalfVectorNorm + e * log2(h.z);
}
#endif

#ifdef ANISO_ENVIRONMENT_MIS
// Index i in [0, count) with cdf(i) <= x < cdf(i + 1) in row `row` of the CDF table, by
// bisection between the guide table's entries for floor(x count) and the next (few steps or
// none, instead of log2(count)): never an interval of zero width.
int anisoFindInterval(sampler2D cdf, sampler2D guide, int row, int count, float x)
{
  int j = min(int(x * float(count)), count - 1);
  int lo = int(texelFetch(guide, ivec2(j, row), 0).r);
  int hi = int(texelFetch(guide, ivec2(j + 1, row), 0).r) + 1;
  while (hi - lo > 1)
  {
    int mid = (lo + hi) / 2;
    if (texelFetch(cdf, ivec2(mid, row), 0).r <= x)
    {
      lo = mid;
    }
    else
    {
      hi = mid;
    }
  }
  return lo;
}

// A direction (environment coordinates) of a distribution's tables (the environment's) and its
// density: a row from the marginal CDF, a column from the row's CDF, then
// uniform in (phi, cos theta) inside the texel, as EnvironmentDistribution::sample does.
vec4 anisoSampleTables(sampler2D cdf, sampler2D guide, sampler2D pdf, ivec2 grid, vec2 xi)
{
  int w = grid.x;
  int h = grid.y;
  int y = anisoFindInterval(cdf, guide, h, h, xi.y);
  float r0 = texelFetch(cdf, ivec2(y, h), 0).r;
  float r1 = texelFetch(cdf, ivec2(y + 1, h), 0).r;
  float t = clamp((xi.y - r0) / max(r1 - r0, 1e-30), 0.0, 1.0);
  int x = anisoFindInterval(cdf, guide, y, w, xi.x);
  float c0 = texelFetch(cdf, ivec2(x, y), 0).r;
  float c1 = texelFetch(cdf, ivec2(x + 1, y), 0).r;
  float s = clamp((xi.x - c0) / max(c1 - c0, 1e-30), 0.0, 1.0);
  float zTop = cos(anisoPi * float(y) / float(h));
  float zBottom = cos(anisoPi * float(y + 1) / float(h));
  float z = clamp(mix(zTop, zBottom, t), -1.0, 1.0);
  float sinTheta = sqrt(max(1.0 - z * z, 0.0));
  float phi = anisoPi - 2.0 * anisoPi * (float(x) + s) / float(w);
  return vec4(sinTheta * cos(phi), sinTheta * sin(phi), z, texelFetch(pdf, ivec2(x, y), 0).r);
}
#endif

#if defined(ANISO_ENVIRONMENT_MIS) || defined(ANISO_ENVIRONMENT_SOURCES)
// (u, theta / pi) of direction d (environment coordinates, need not be unit): the
// equirectangular coordinates, texture t = 0 at the zenith.
vec2 anisoEquirectCoords(vec3 d)
{
  float u = fract(0.5 - atan(d.y, d.x) * (0.5 / anisoPi));
  return vec2(u, acos(clamp(d.z / max(length(d), 1e-30), -1.0, 1.0)) * (1.0 / anisoPi));
}

#endif

#ifdef ANISO_ENVIRONMENT_MIS
vec4 anisoSampleEnvironment(vec2 xi)
{
  return anisoSampleTables(anisoEnvCdf, anisoEnvGuide, anisoEnvPdf, anisoEnvGrid, xi);
}

// Density of the environment distribution at direction d (environment coordinates) and the
// coarsest cube level a lookup there may read (EnvironmentDistribution::lodBoundTable): above it
// the blur would spread a source into directions of low density, counting it once more.
vec2 anisoEnvironmentPdfAndLodBound(vec3 d)
{
  ivec2 texel = clamp(ivec2(anisoEquirectCoords(d) * vec2(anisoEnvGrid)), ivec2(0), anisoEnvGrid - 1);
  return texelFetch(anisoEnvPdf, texel, 0).rg;
}

float anisoEnvironmentPdf(vec3 d)
{
  return anisoEnvironmentPdfAndLodBound(d).x;
}
#endif

#ifdef ANISO_METHOD_SPLIT_SUM
// BRDF LUT coordinates: u = (2/pi) atan(|b.v| / |t.v|), v = sqrt(n.v).
vec2 anisoBrdfLutCoords(vec3 t, vec3 b, vec3 n, vec3 v)
{
  float tv = abs(dot(t, v));
  float bv = abs(dot(b, v));
  float u = tv + bv > 0.0 ? atan(bv, tv) * (2.0 / anisoPi) : 0.0;
  return vec2(u, sqrt(max(dot(n, v), 0.0)));
}
#endif

#ifdef ANISO_ENVIRONMENT_SOURCES
// The pixel's choice between the source groups (lobeAwareSelection in
// core/env/env_source_groups.h): group g weighs P_g min(p_lobe(l_g), 1 / solid angle_g), l_g the
// direction of its cap nearest to the mirror direction (p_lobe zero below the surface), and
// q_g = (1 - d) w_g / sum w + d P_g / P (by power alone when no group is seen); and its count
// of source samples (smallSourceShare, sourceSampleCount), -1 where its N lobe samples alone
// suffice (lobeSamplesSuffice: sum_g p_lobe(l_g) integral_g L^2 below
// anisoSourceLobeOnlyVariance N (sum w + residual)^2).
void anisoSourceSelection(vec3 t, vec3 b, vec3 n, vec3 v, int lobeCount,
                          out float q[ANISO_SOURCE_GROUPS], out int sampleSteps)
{
  float small = 0.0;
  float secondMoment = 0.0;
  float groupMoment[ANISO_SOURCE_GROUPS];
  mat3 environmentToWorld = transpose(anisoWorldToEnvironment);
  vec3 r = anisoWorldToEnvironment * (2.0 * dot(n, v) * n - v);
  float w[ANISO_SOURCE_GROUPS];
  float sum = 0.0;
  for (int g = 0; g < ANISO_SOURCE_GROUPS; ++g)
  {
    w[g] = 0.0;
    groupMoment[g] = 0.0;
    if (g >= anisoSourceGroupCount)
    {
      continue;
    }
    vec3 c = anisoSourceGroupCone[g].xyz;
    float cosRadius = anisoSourceGroupCone[g].w;
    float cosAngle = clamp(dot(c, r), -1.0, 1.0);
    vec3 nearest = r;
    if (cosAngle < cosRadius)
    {
      vec3 across = r - cosAngle * c;
      float len = length(across);
      nearest = cosRadius * c +
        sqrt(max(1.0 - cosRadius * cosRadius, 0.0)) * (len > 0.0 ? across / len : vec3(0.0));
    }
    vec3 l = environmentToWorld * nearest;
    vec3 h = v + l;
    float hLength = length(h);
    if (dot(n, l) <= 0.0 || hLength <= 0.0)
    {
      continue;
    }
    h /= hLength;
    float vDotH = dot(v, h);
    if (vDotH <= 0.0)
    {
      continue;
    }
    float pdf =
      exp2(anisoLog2HalfVectorPdf(vec3(dot(h, t), dot(h, b), dot(h, n))) - log2(4.0 * vDotH));
    float seen = min(pdf, anisoSourceGroupInfo[g].y);
    w[g] = anisoSourceGroupInfo[g].x * seen;
    sum += w[g];
    // Down by its solid angle against the lobe's where the lobe fits inside it.
    small += w[g] * min(anisoSourceGroupInfo[g].y / pdf, 1.0);
    groupMoment[g] = pdf * anisoSourceGroupSquared[g];
    secondMoment += groupMoment[g];
  }
  float whole = sum + anisoSourceResidualShare;
  if (secondMoment < anisoSourceLobeOnlyVariance * float(lobeCount) * whole * whole)
  {
    sampleSteps = -1;
    for (int g = 0; g < ANISO_SOURCE_GROUPS; ++g)
    {
      q[g] = 0.0;
    }
    return;
  }
  float share = clamp(small / max(whole, 1e-30), 0.0, 1.0);
  sampleSteps = clamp(int(round(log2(1.0 + 3.0 * share))), 0, anisoSourceSampleSteps);
  if (anisoSourcePointCount > 0)
  {
    // The shared points, group by group: a group whose part of the moment is within its share
    // of the same budget is left to the lobe samples (its q 0: weight 1 there), the others
    // take their points at the frame's selection.
    float groupBudget = anisoSourceLobeOnlyVariance * float(lobeCount) * whole * whole /
      float(max(anisoSourceGroupCount, 1));
    for (int g = 0; g < ANISO_SOURCE_GROUPS; ++g)
    {
      q[g] = groupMoment[g] < groupBudget ? 0.0 : anisoSourcePointSelection[g];
    }
    return;
  }
  for (int g = 0; g < ANISO_SOURCE_GROUPS; ++g)
  {
    float share = g < anisoSourceGroupCount ? anisoSourceGroupInfo[g].x : 0.0;
    q[g] = sum > 0.0 ? (1.0 - anisoSourceDefensive) * w[g] / sum + anisoSourceDefensive * share
                     : share;
  }
}

vec4 anisoSourceTable(int i)
{
  return texelFetch(anisoSourceTables, ivec2(i % 4096, i / 4096), 0);
}

// The first cell in [first, first + count) whose cumulative end (.r) exceeds u, and where u
// falls inside it (.y), found from the run's guide (guidedSearch in
// core/env/env_source_groups.h): the guide of u's bin is component `channel` of cell
// guides + floor(u count); one step back while the cell before already exceeds u, then forward.
vec2 anisoSourcePick(int first, int count, float u, int guides, int channel)
{
  int last = first + count - 1;
  int k = clamp(int(u * float(count)), 0, count - 1);
  int lo = int(anisoSourceTable(guides + k)[channel] + 0.5);
  while (lo > first && anisoSourceTable(lo - 1).r > u)
  {
    --lo;
  }
  while (lo < last && !(anisoSourceTable(lo).r > u))
  {
    ++lo;
  }
  float c0 = lo == first ? 0.0 : anisoSourceTable(lo - 1).r;
  float c1 = anisoSourceTable(lo).r;
  return vec2(float(lo), clamp((u - c0) / max(c1 - c0, 1e-30), 0.0, 1.0));
}

// The inverse of the tent's cumulative distribution on [-1, 1] at s in [0, 1].
float anisoTentOffset(float s)
{
  return s < 0.5 ? sqrt(2.0 * s) - 1.0 : 1.0 - sqrt(2.0 * (1.0 - s));
}

// Density of anisoSampleSources under q at equirectangular coordinates uv (SourceGroups::pdf):
// the texels' densities interpolated as the excess is (bilinear, wrapping in u, clamped in v),
// over sin theta.
float anisoSourcePdf(float q[ANISO_SOURCE_GROUPS], vec2 uv)
{
  vec2 f = uv * vec2(anisoSourceGrid) - 0.5;
  vec2 corner = floor(f);
  vec2 a = f - corner;
  ivec2 c0 = ivec2(corner);
  float sum = 0.0;
  for (int j = 0; j <= 1; ++j)
  {
    int y = clamp(c0.y + j, 0, anisoSourceGrid.y - 1);
    for (int k = 0; k <= 1; ++k)
    {
      int x = c0.x + k;
      x = x < 0 ? x + anisoSourceGrid.x : (x >= anisoSourceGrid.x ? x - anisoSourceGrid.x : x);
      vec2 densityGroup = texelFetch(anisoSourceDensity, ivec2(x, y), 0).rg;
      if (densityGroup.g > -0.5)
      {
        int g = clamp(int(densityGroup.g + 0.5), 0, ANISO_SOURCE_GROUPS - 1);
        sum += (k == 1 ? a.x : 1.0 - a.x) * (j == 1 ? a.y : 1.0 - a.y) * q[g] * densityGroup.r;
      }
    }
  }
  float sinTheta = sin(anisoPi * clamp(uv.y, 0.0, 1.0));
  return sum > 0.0 ? sum / max(sinTheta, 1e-30) : 0.0;
}

// A direction (environment coordinates) of the source groups under the selection q and its
// density (SourceGroups::sample): xi.x picks the group by q's cumulative sum, then, rescaled,
// the texel of the row and where in u; xi.y the row and where in v: a point of the texel's
// tent. w = 0 when no group has a share (or the point is its tent's edge).
vec4 anisoSampleSources(float q[ANISO_SOURCE_GROUPS], vec2 xi, out vec2 uv)
{
  uv = vec2(0.0);
  int g = -1;
  float start = 0.0;
  float cumulative = 0.0;
  for (int k = 0; k < ANISO_SOURCE_GROUPS; ++k)
  {
    if (k >= anisoSourceGroupCount)
    {
      break;
    }
    if (q[k] > 0.0)
    {
      g = k;
      start = cumulative;
      if (xi.x < cumulative + q[k])
      {
        break;
      }
    }
    cumulative += q[k];
  }
  if (g < 0)
  {
    return vec4(0.0, 0.0, 1.0, 0.0);
  }
  float within = clamp((xi.x - start) / q[g], 0.0, 1.0);
  int firstRow = int(anisoSourceGroupInfo[g].z);
  vec2 rowPick = anisoSourcePick(firstRow, int(anisoSourceGroupInfo[g].w), xi.y,
                                 anisoSourceRowGuides + firstRow, 0);
  vec4 row = anisoSourceTable(int(rowPick.x));
  int firstEntry = int(row.b + 0.5);
  vec2 entryPick = anisoSourcePick(firstEntry, int(row.a + 0.5), within, firstEntry, 2);
  int texel = int(anisoSourceTable(int(entryPick.x)).g + 0.5);
  vec2 grid = vec2(anisoSourceGrid);
  // A point of the texel's tent (grid units), wrapped in u, reflected at the poles.
  vec2 p = vec2(float(texel % anisoSourceGrid.x), float(texel / anisoSourceGrid.x)) + 0.5 +
    vec2(anisoTentOffset(entryPick.y), anisoTentOffset(rowPick.y));
  p.x -= grid.x * floor(p.x / grid.x);
  p.y = p.y < 0.0 ? -p.y : (p.y > grid.y ? 2.0 * grid.y - p.y : p.y);
  uv = p / grid;
  float theta = anisoPi * uv.y;
  float phi = anisoPi - 2.0 * anisoPi * uv.x;
  float sinTheta = sin(theta);
  return vec4(sinTheta * cos(phi), sinTheta * sin(phi), cos(theta), anisoSourcePdf(q, uv));
}

// The sources' radiance in direction l (world), unfiltered, and where it was read.
vec3 anisoSourceRadianceAt(vec3 l, out vec2 uv)
{
  uv = anisoEquirectCoords(anisoWorldToEnvironment * l);
  return textureLod(anisoSourceRadiance, uv, 0.0).rgb;
}

// The sources' light by multi-sample MIS of the N lobe samples and the M source samples
// (balance heuristic): a sample of either technique in direction l adds
// f (n.l) L_s(l) / (N p_lobe(l) + M p_s(l)) to the estimate, both densities per solid angle,
// p_lobe the lobe's own (its half vector's, log2 p_h, over 4 v.h) in either case so the
// weights of a direction sum to 1. The residual (anisoEnvironment) is integrated by the lobe
// samples alone. This returns the weight N p_lobe / (N p_lobe + M p_s) of a lobe sample read
// at uv (the caller multiplies L_s by it and by its AS weight, f (n.l) / p_lobe, and the sum
// is divided by N).
float anisoSourceLobeWeight(vec2 uv, float log2PdfLobe, int count, float q[ANISO_SOURCE_GROUPS],
                            int sourceCount)
{
  float lobe = float(count) * exp2(log2PdfLobe);
  return lobe / (lobe + float(sourceCount) * anisoSourcePdf(q, uv));
}
#endif

// Outgoing specular radiance towards v from the frame (t, b, n), by N importance samples of
// the half vector: `exact` weights each by F(v.h)(n.l)/max(n.l, n.v) / N; `split-sum`
// normalises sum L (n.l) / sum (n.l) and multiplies by F0 s + b from the BRDF LUT.
// With environment MIS (`exact` only), point i takes the lobe technique when its first
// coordinate is below c = anisoLobeFraction, the environment's otherwise (so the Hammersley set
// splits in proportion), and every sample is weighted by f (n.l) / (c p_lobe + (1 - c) p_env)
// (one-sample MIS, balance heuristic), where f (n.l) = AS weight x p_lobe(l).
vec3 anisoSpecular(vec3 t, vec3 b, vec3 n, vec3 v, vec3 f0)
{
#ifdef ANISO_LOBE_DENSITY
  anisoSetHalfVectorNorm();
#endif
  int count = max(anisoSampleCount, 1);
  float nDotV = dot(n, v);
  vec2 shift = anisoPixelShift();
  vec3 sum = vec3(0.0);
#ifdef ANISO_METHOD_SPLIT_SUM
  float weight = 0.0;
#endif
#ifdef ANISO_ENVIRONMENT_MIS
  float c = anisoLobeFraction;
  mat3 tbn = mat3(t, b, n);
  mat3 environmentToWorld = transpose(anisoWorldToEnvironment);
#endif
#ifdef ANISO_ENVIRONMENT_SOURCES
  float selection[ANISO_SOURCE_GROUPS];
  int sourceSteps;
  anisoSourceSelection(t, b, n, v, count, selection, sourceSteps);
  int sourceCount = sourceSteps < 0 ? 0 : max(anisoSourceSampleCount, 1) << sourceSteps;
  // With the shared points a pixel that takes sources takes the points of each group its
  // selection keeps (anisoSourceSelection), and the lobe samples' weights read the density the
  // points were drawn with (the frame's selection, 0 for the groups left to them).
  bool points = anisoSourcePointCount > 0 && sourceCount > 0;
  if (points)
  {
    sourceCount = anisoSourcePointCount;
  }
  // A pixel without source samples takes the sources in this loop, at weight 1; one with them
  // in the loop after it, at their MIS weight. Two loops, not a branch in one: a software
  // rasteriser runs both sides of a branch for a block of pixels, but leaves a loop as soon as
  // none of the block is in it (docs/BENCHMARKS.md, "Lobe samples alone where they suffice").
  int lobeOnlyCount = sourceCount == 0 ? count : 0;
#else
  int lobeOnlyCount = count;
#endif
  for (int i = 0; i < lobeOnlyCount; ++i)
  {
    vec2 xi = anisoSamplePoint(i, count, shift, anisoSequenceCount, anisoSequenceBlock,
                               anisoSequenceColumns);
#ifdef ANISO_ENVIRONMENT_MIS
    vec3 l;
    vec3 h;
    float pdfEnvironment;
    if (xi.x < c)
    {
      vec4 hs = anisoHalfVector(vec2(min(xi.x / c, 0.99999994), xi.y));
      h = tbn * hs.xyz;
      l = 2.0 * dot(v, h) * h - v;
      pdfEnvironment = anisoEnvironmentPdf(anisoWorldToEnvironment * l);
    }
    else
    {
      vec4 ls = anisoSampleEnvironment(vec2(min((xi.x - c) / (1.0 - c), 0.99999994), xi.y));
      l = environmentToWorld * ls.xyz;
      h = normalize(v + l);
      pdfEnvironment = ls.w;
    }
    float vDotH = dot(v, h);
    float nDotL = dot(n, l);
    if (vDotH <= 0.0 || nDotL <= 0.0)
    {
      continue;
    }
    // p_lobe(l) = p_h / (4 v.h); the lobe's own samples use the analytic density as well, so
    // both techniques weigh every direction alike.
    float log2PdfLobe =
      anisoLog2HalfVectorPdf(vec3(dot(h, t), dot(h, b), dot(h, n))) - log2(4.0 * vDotH);
    float pdfLobe = exp2(log2PdfLobe);
    float pdfMixture = c * pdfLobe + (1.0 - c) * pdfEnvironment;
    if (!(pdfMixture > 0.0))
    {
      continue;
    }
    float lod = anisoSampleLod(log2(pdfMixture), count);
#ifdef ANISO_FILTERED
    lod = min(lod, anisoEnvironmentPdfAndLodBound(anisoWorldToEnvironment * l).y);
#endif
    vec3 radiance = anisoEnvironmentRadiance(l, lod);
    float m = clamp(1.0 - vDotH, 0.0, 1.0);
    float chi = m * m * m * m * m;
    sum += radiance * (f0 + (1.0 - f0) * chi) * (nDotL / max(nDotL, nDotV)) *
      (pdfLobe / pdfMixture);
#else
    vec4 hs = anisoHalfVector(xi);
    vec3 h = hs.x * t + hs.y * b + hs.z * n;
    float vDotH = dot(v, h);
    if (vDotH <= 0.0)
    {
      continue;
    }
    vec3 l = 2.0 * vDotH * h - v;
    float nDotL = dot(n, l);
    if (nDotL <= 0.0)
    {
      continue;
    }
    vec3 radiance = anisoEnvironmentRadiance(l, anisoSampleLod(hs.w - log2(4.0 * vDotH), count));
#ifdef ANISO_ENVIRONMENT_SOURCES
    vec2 uv;
    radiance += anisoSourceRadianceAt(l, uv);
#endif
#ifdef ANISO_METHOD_SPLIT_SUM
    sum += radiance * nDotL;
    weight += nDotL;
#else
    float m = clamp(1.0 - vDotH, 0.0, 1.0);
    float chi = m * m * m * m * m;
    sum += radiance * (f0 + (1.0 - f0) * chi) * (nDotL / max(nDotL, nDotV));
#endif
#endif
  }
#ifdef ANISO_ENVIRONMENT_SOURCES
  // The lobe samples of a pixel with source samples: the residual, and the sources at the
  // samples' MIS weight.
  int lobeMisCount = sourceCount > 0 ? count : 0;
  for (int i = 0; i < lobeMisCount; ++i)
  {
    vec4 hs = anisoHalfVector(anisoSamplePoint(i, count, shift, anisoSequenceCount,
                                               anisoSequenceBlock, anisoSequenceColumns));
    vec3 h = hs.x * t + hs.y * b + hs.z * n;
    float vDotH = dot(v, h);
    vec3 l = 2.0 * vDotH * h - v;
    float nDotL = dot(n, l);
    if (vDotH <= 0.0 || nDotL <= 0.0)
    {
      continue;
    }
    float log2PdfLobe = hs.w - log2(4.0 * vDotH);
    vec3 radiance = anisoEnvironmentRadiance(l, anisoSampleLod(log2PdfLobe, count));
    vec2 uv;
    vec3 source = anisoSourceRadianceAt(l, uv);
    if (source != vec3(0.0))
    {
      radiance +=
        source * anisoSourceLobeWeight(uv, log2PdfLobe, count, selection, sourceCount);
    }
    float m = clamp(1.0 - vDotH, 0.0, 1.0);
    float chi = m * m * m * m * m;
    sum += radiance * (f0 + (1.0 - f0) * chi) * (nDotL / max(nDotL, nDotV));
  }
  // The shared points: each adds f (n.l) L / (N p_lobe + K p_s), as a source sample does.
  int pointGroups = points ? anisoSourceGroupCount : 0;
  for (int g = 0; g < pointGroups; ++g)
  {
    ivec2 run = selection[g] > 0.0 ? anisoSourcePointRuns[g] : ivec2(0);
    for (int j = run.x; j < run.x + run.y; ++j)
    {
      vec3 l = anisoSourcePoints[j].xyz;
      float nDotL = dot(n, l);
      vec3 h = normalize(v + l);
      float vDotH = dot(v, h);
      if (nDotL <= 0.0 || vDotH <= 0.0)
      {
        continue;
      }
      float pdfLobe =
        exp2(anisoLog2HalfVectorPdf(vec3(dot(h, t), dot(h, b), dot(h, n))) - log2(4.0 * vDotH));
      float n0 = float(count);
      float m = clamp(1.0 - vDotH, 0.0, 1.0);
      float chi = m * m * m * m * m;
      sum += anisoSourcePointRadiance[j] * (f0 + (1.0 - f0) * chi) * (nDotL / max(nDotL, nDotV)) *
        (n0 * pdfLobe / (n0 * pdfLobe + anisoSourcePoints[j].w));
    }
  }
  // Or the pixel's own source samples: M points of the sources' distribution under its
  // selection, stratified and taken from frame to frame as the lobe's are (their own block of
  // the sequence), each weighted as anisoSourceLobeWeight says for the lobe's (times N, as the
  // lobe's sum is divided by N).
  int sampledCount = points ? 0 : sourceCount;
  mat3 sourceToWorld = transpose(anisoWorldToEnvironment);
  int sourceBlock = max(sourceSteps, 0);
  int sourceSequenceCount = anisoSourceSequenceCounts[sourceBlock];
  for (int j = 0; j < sampledCount; ++j)
  {
    vec2 uv;
    vec4 ls = anisoSampleSources(selection,
                                 anisoSamplePoint(j, sourceCount, shift, sourceSequenceCount,
                                                  anisoSourceSequenceBlocks[sourceBlock],
                                                  anisoSourceSequenceColumns[sourceBlock]),
                                 uv);
    vec3 l = sourceToWorld * ls.xyz;
    float nDotL = dot(n, l);
    vec3 h = normalize(v + l);
    float vDotH = dot(v, h);
    if (!(ls.w > 0.0) || nDotL <= 0.0 || vDotH <= 0.0)
    {
      continue;
    }
    vec3 source = textureLod(anisoSourceRadiance, uv, 0.0).rgb;
    float pdfLobe =
      exp2(anisoLog2HalfVectorPdf(vec3(dot(h, t), dot(h, b), dot(h, n))) - log2(4.0 * vDotH));
    float n0 = float(count);
    float m = clamp(1.0 - vDotH, 0.0, 1.0);
    float chi = m * m * m * m * m;
    sum += source * (f0 + (1.0 - f0) * chi) * (nDotL / max(nDotL, nDotV)) *
      (n0 * pdfLobe / (n0 * pdfLobe + float(sourceCount) * ls.w));
  }
#endif
#ifdef ANISO_METHOD_SPLIT_SUM
  vec3 prefiltered = weight > 0.0 ? sum / weight : vec3(0.0);
  vec2 sizeBias = textureLod(anisoBrdfLut, anisoBrdfLutCoords(t, b, n, v), 0.0).rg;
  return prefiltered * (f0 * sizeBias.x + sizeBias.y);
#else
  return sum / float(count);
#endif
}

// E(n) from the SH9 coefficients (real basis, order Y00, Y1-1, Y10, Y11, Y2-2, Y2-1, Y20, Y21,
// Y22), already multiplied by the cosine-lobe factors pi, 2pi/3, pi/4.
vec3 anisoIrradiance(vec3 normalWorld)
{
  vec3 d = anisoWorldToEnvironment * normalWorld;
  return anisoIrradianceSH[0] * 0.282094792 +
    anisoIrradianceSH[1] * (0.488602512 * d.y) + anisoIrradianceSH[2] * (0.488602512 * d.z) +
    anisoIrradianceSH[3] * (0.488602512 * d.x) + anisoIrradianceSH[4] * (1.092548431 * d.x * d.y) +
    anisoIrradianceSH[5] * (1.092548431 * d.y * d.z) +
    anisoIrradianceSH[6] * (0.315391565 * (3.0 * d.z * d.z - 1.0)) +
    anisoIrradianceSH[7] * (1.092548431 * d.x * d.z) +
    anisoIrradianceSH[8] * (0.546274215 * (d.x * d.x - d.y * d.y));
}

// A unit vector orthogonal to n, the same choice as the core's Frame::fromNormalTangent.
vec3 anisoAnyPerpendicular(vec3 n)
{
  vec3 axis = abs(n.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
  return normalize(axis - dot(axis, n) * n);
}

#ifdef ANISO_HEIGHT_MAP
float anisoDepthAt(vec2 uv, vec2 duvdx, vec2 duvdy)
{
  return 1.0 - textureGrad(anisoHeightMap, uv, duvdx, duvdy).r;
}

// Parallax occlusion mapping: march the view ray (tangent space, towards the eye) down through
// the height field in layers, then interpolate between the last two layers.
vec2 anisoParallaxOcclusion(vec2 uv, vec3 viewTangent, vec2 duvdx, vec2 duvdy)
{
  float layers = mix(32.0, 8.0, clamp(viewTangent.z, 0.0, 1.0));
  float layerDepth = 1.0 / layers;
  vec2 delta = viewTangent.xy / max(viewTangent.z, 0.05) * anisoHeightScale / layers;
  float depth = 0.0;
  float mapDepth = anisoDepthAt(uv, duvdx, duvdy);
  for (int i = 0; i < 64 && depth < mapDepth; ++i)
  {
    uv -= delta;
    depth += layerDepth;
    mapDepth = anisoDepthAt(uv, duvdx, duvdy);
  }
  vec2 previous = uv + delta;
  float after = mapDepth - depth;
  float before = anisoDepthAt(previous, duvdx, duvdy) - depth + layerDepth;
  float w = after - before != 0.0 ? after / (after - before) : 0.0;
  return mix(uv, previous, clamp(w, 0.0, 1.0));
}
#endif
