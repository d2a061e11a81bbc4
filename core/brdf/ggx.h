#pragma once
// Anisotropic GGX (Trowbridge-Reitz) microfacet model with Smith height-correlated masking and
// Schlick Fresnel: the model behind VTK's physically based anisotropy, kept in the core so that
// VTK's own rendering can be measured against a converged reference of the same model.
// Tangent space as for Ashikhmin-Shirley: t = +X (alpha_x acts along it), b = +Y, n = +Z. All
// vectors are unit length.
//   D(h)   = 1 / (pi ax ay ((h.x/ax)^2 + (h.y/ay)^2 + h.z^2)^2)
//   L(w)   = (sqrt(1 + (ax^2 w.x^2 + ay^2 w.y^2) / w.z^2) - 1) / 2   (Smith Lambda)
//   G2     = 1 / (1 + L(v) + L(l))                                  (height-correlated)
//   f(v,l) = D(h) G2(v, l) F(v.h) / (4 (n.v)(n.l)),  h = normalize(v + l)
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace aniso
{
struct GgxLobe
{
  double alphaX = 0.3; // roughness along the tangent t
  double alphaY = 0.3; // roughness along the bitangent b
};

// Range the model is specified (and tested) for. Below 1e-4 the lobe is narrower than any
// environment texel; above 10 it is flatter than uniform and no renderer uses it.
constexpr double kGgxMinAlpha = 1e-4;
constexpr double kGgxMaxAlpha = 10.0;

// Throws aniso::Error ("alpha_x: ..." or "alpha_y: ...") unless both are finite and in
// [kGgxMinAlpha, kGgxMaxAlpha]. The functions below assume a valid lobe and do not check.
void validateGgxLobe(const GgxLobe& lobe);

// The mapping VTK 9.1 uses for vtkProperty Roughness r and Anisotropy a (both in [0, 1], as
// vtkProperty clamps them): aspect = sqrt(1 - 0.9 a), alpha_t = max(r^2 / aspect, 0.001),
// alpha_b = max(r^2 aspect, 0.001), alpha_t along the (rotated) tangent. Throws aniso::Error
// ("roughness: ..." or "anisotropy: ...") for values outside [0, 1].
GgxLobe ggxLobeFromVtk(double roughness, double anisotropy);

// Normal distribution D(h); D(h) (n.h) integrates to 1 over the hemisphere. 0 for h.z <= 0.
double ggxDistribution(const GgxLobe& lobe, const glm::dvec3& h);

// Smith Lambda(w) for w.z > 0; +infinity for w.z <= 0 (a direction at or below the horizon is
// fully masked).
double ggxLambda(const GgxLobe& lobe, const glm::dvec3& w);

// G1(w) = 1 / (1 + Lambda(w)); 0 for w.z <= 0.
double ggxMasking(const GgxLobe& lobe, const glm::dvec3& w);

// Height-correlated G2(v, l) = 1 / (1 + Lambda(v) + Lambda(l)); 0 when either is below the
// horizon. Never above min(G1(v), G1(l)).
double ggxMaskingShadowing(const GgxLobe& lobe, const glm::dvec3& v, const glm::dvec3& l);

// f(v, l) with Schlick Fresnel from F0 (per channel); zero below either horizon. Finite for
// every valid lobe and unit v, l.
glm::dvec3 evalSpecular(const GgxLobe& lobe, const glm::dvec3& f0, const glm::dvec3& v,
                        const glm::dvec3& l);

// Visible normal seen from v (v.z > 0), by the stretched-hemisphere construction (Heitz 2018,
// "Sampling the GGX distribution of visible normals"): unit h with h.z >= 0 and v.h >= 0, from
// xi in [0, 1)^2. A view with v.z <= 0 reflects nothing; it gets h = n.
glm::dvec3 sampleVisibleNormal(const GgxLobe& lobe, const glm::dvec3& v, const glm::dvec2& xi);

// Density of sampleVisibleNormal per unit solid angle of h: G1(v) max(0, v.h) D(h) / v.z.
// 0 for v.z <= 0 or h.z <= 0.
double pdfVisibleNormal(const GgxLobe& lobe, const glm::dvec3& v, const glm::dvec3& h);

// Density of l = reflectAbout(v, h) with h from sampleVisibleNormal, per unit solid angle of
// l: pdfVisibleNormal / (4 v.h) = G1(v) D(h) / (4 v.z), h = normalize(v + l); 0 when v.h <= 0.
double pdfLight(const GgxLobe& lobe, const glm::dvec3& v, const glm::dvec3& l);
} // namespace aniso
