#pragma once
// The Ashikhmin-Shirley anisotropic Phong model (docs/METHOD.md, source 1), in tangent space:
// t = +X (n_u acts along it), b = +Y (n_v), n = +Z. All vectors are unit length.
// Valid for n_u, n_v in [0, 1e6] and views down to grazing; never returns NaN or Inf.
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace aniso
{
struct AsLobe
{
  double nu = 100.0; // exponent along the tangent t
  double nv = 100.0; // exponent along the bitangent b
};

// Largest exponent the model is specified (and tested) for.
constexpr double kMaxExponent = 1e6;

// Throws aniso::Error ("n_u: ..." or "n_v: ...") unless both exponents are finite and in
// [0, kMaxExponent]. The evaluation functions below assume a valid lobe and do not check.
void validateLobe(const AsLobe& lobe);

// The Beckmann roughness alpha whose slope distribution matches a Blinn-Phong lobe of exponent n
// (Walter et al. 2007, "Microfacet models for refraction", eq. 32, used per axis for the
// anisotropic lobe): alpha = sqrt(2 / (n + 2)), n = 2 / alpha^2 - 2. n in [0, kMaxExponent]
// gives alpha in [0.0014142, 1]. The one place of this correspondence: the Material dock's
// roughness view, source 2's materials (sv_material) and glTF's roughness (gltf_material) use it.
double roughnessFromExponent(double n);
// Clamped to the exponent range [0, kMaxExponent]; alpha <= 0 (or NaN) gives kMaxExponent.
double exponentFromRoughness(double alpha);

// Exponent (n_u (t.h)^2 + n_v (b.h)^2) / (1 - (n.h)^2), written with the tangent-plane
// components so that h = n (0/0) is well defined (the mean of n_u and n_v there).
double asExponent(const AsLobe& lobe, const glm::dvec3& h);

// p_h(h): density of half vectors per unit solid angle; integrates to 1 over the upper
// hemisphere. 0 for h.z <= 0.
double pdfHalfVector(const AsLobe& lobe, const glm::dvec3& h);

// log2 p_h(h), finite for every h with h.z > 0 and exponents up to 1e6 (where p_h itself
// reaches ~1.6e5, beyond half-float range). -infinity is never returned: h.z <= 0 gives the
// lowest finite value kLog2PdfFloor.
constexpr double kLog2PdfFloor = -126.0;
double log2PdfHalfVector(const AsLobe& lobe, const glm::dvec3& h);

// Half vector from (xi1, xi2) in [0,1)^2 by the AS quadrant construction; unit, h.z >= 0.
// Robust at xi1 in {0, 1/4, 1/2, 3/4}, xi2 = 0 and xi2 -> 1, and exponents up to 1e6.
glm::dvec3 sampleHalfVector(const AsLobe& lobe, const glm::dvec2& xi);

// Inverse of sampleHalfVector for h.z > 0: returns (xi1, xi2) in [0,1)^2.
glm::dvec2 invertHalfVector(const AsLobe& lobe, const glm::dvec3& h);

// Mirror v about h: l = 2 (v.h) h - v.
glm::dvec3 reflectAbout(const glm::dvec3& v, const glm::dvec3& h);

// Density of l = reflectAbout(v, h) per unit solid angle: p_h / (4 v.h); 0 when v.h <= 0.
double pdfLight(const AsLobe& lobe, const glm::dvec3& v, const glm::dvec3& l);

// Schlick: F0 + (1 - F0)(1 - v.h)^5, per channel.
glm::dvec3 schlickFresnel(const glm::dvec3& f0, double vDotH);

// f_s(v, l) = p_h F(v.h) / (4 (v.h) max(n.v, n.l)); zero below either horizon.
glm::dvec3 evalSpecular(const AsLobe& lobe, const glm::dvec3& f0, const glm::dvec3& v,
                        const glm::dvec3& l);
} // namespace aniso
