#pragma once
// An MTL material (mtl.h) as the project's Ashikhmin-Shirley material (material_library.h).
//
// With any key of the PBR extension (Pr, Pm, aniso, anisor, map_Pr, map_Pm) the material is
// metallic-roughness, mapped as glTF's KHR_materials_anisotropy is (gltfToAs,
// core/models/gltf_material.h, with rotation 0 and the default dielectric F0 0.04): base colour Kd,
// metallic Pm (0 when absent, 1 when only a map_Pm that exists gives it), roughness Pr (absent: the
// roughness of the Blinn-Phong exponent Ns, alpha = sqrt(2 / (Ns + 2)); neither: 1), anisotropy
// strength aniso (0 when absent). Without them it is Phong: albedo = Kd, F0 = Ks, n_u = n_v = Ns.
// Ns is a Phong exponent in the specification, whose lobe about the mirror direction matches a
// Blinn-Phong lobe (the AS material with n_u = n_v) of about four times the exponent; writers
// differ (Blender writes its own function of roughness), so Ns is taken as the Blinn-Phong exponent
// as it is. Absent: Kd 0.8 grey (the value writers put in a new material), Ks 0.04 (a dielectric's
// F0), Ns 0. Colours are clamped to [0, 1], exponents to the declared range of nu and nv.
//
// Textures: map_Kd -> "albedo-map" (it multiplies the albedo, as in the MTL specification);
// map_Bump / bump -> "height-map" (heights, as the specification has them; -bm multiplies
// height-scale); norm -> "normal-map" with bump mapping "normal"; map_Pm -> "metallic-map"
// (the shader mixes F0 from 0.04 to the uniform F0 by the map and scales the albedo by one minus
// it, so F0 is set to mix(0.04, Kd, Pm) and the albedo to Kd: metallic = Pm times the map,
// exactly for F0, and for the albedo when Pm is 1). A relative file name is read against the
// .mtl's directory; a file that does not exist is left out with a warning naming the .mtl, the
// line and the texture. Warnings (never an error) also tell what is read and not applied:
// map_Ks, map_Ns and map_Pr (the material has no such maps), -o/-s/-t texture transforms, and
// anisor (the anisotropy's rotation about the normal: the material has no rotation of its
// tangent field, so the tangents stay the part's own). Opacity (d, Tr) and sheen (Ps) are read
// and not used: the material is opaque and has no sheen.
#include "core/formats/mtl.h"
#include "core/parameters/material_library.h"

#include <string>
#include <vector>

namespace aniso
{
// MTL's material, named as there, as above. MTL_PATH is the .mtl's path (texture files are read
// against its directory; it names the file in WARNINGS, "MTL_PATH:LINE: reason").
Material materialFromMtl(const MtlMaterial& mtl, const std::string& mtlPath,
                         std::vector<std::string>& warnings);
} // namespace aniso
