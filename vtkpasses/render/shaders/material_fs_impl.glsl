  // Anisotropic material: replaces VTK's lighting result with the image-based shading (frozen
  // pixels discarded before it: frozen_pixels_impl.glsl).
  {
    // The view ray of this fragment from its own clip coordinates: exact for perspective and
    // parallel projections alike.
    vec2 ndc = anisoClipPosition.xy / anisoClipPosition.w;
    vec4 nearH = anisoClipToWorld * vec4(ndc, -1.0, 1.0);
    vec3 v = normalize(nearH.xyz / nearH.w - anisoPositionWC);

#ifdef ANISO_LINE
    // An illuminated line (docs/METHOD.md, "Lines"): t along the line, n the normal of the thin
    // cylinder around it that faces the viewer, v's part perpendicular to t.
    vec3 t = normalize(anisoTangentWC);
    vec3 n = v - dot(v, t) * t;
    n = dot(n, n) > 1e-12 ? normalize(n) : anisoAnyPerpendicular(t);
#else
#ifdef ANISO_HAVE_NORMALS
    vec3 n = normalize(anisoNormalWC);
    if (!gl_FrontFacing)
    {
      n = -n;
    }
#else
    vec3 n = dot(anisoFaceNormalWC, v) < 0.0 ? -anisoFaceNormalWC : anisoFaceNormalWC;
#endif
    // Interpolated tangents are renormalised and made orthogonal to n (Gram-Schmidt).
#ifdef ANISO_HAVE_TANGENTS
    vec3 t = anisoTangentWC - dot(anisoTangentWC, n) * n;
    t = dot(t, t) > 1e-12 ? normalize(t) : anisoAnyPerpendicular(n);
#else
    vec3 t = anisoAnyPerpendicular(n);
#endif
#endif
    vec3 b = cross(n, t);

#ifdef ANISO_HAVE_TCOORDS
    vec2 uv = anisoTCoord;
#ifdef ANISO_HEIGHT_MAP
    uv = anisoParallaxOcclusion(
      uv, vec3(dot(v, t), dot(v, b), dot(v, n)), anisoTCoordDx, anisoTCoordDy);
#endif
#endif

    // The perturbed frame: normal or quaternion map, then the tangent-plane rotation in it.
    vec3 ft = t;
    vec3 fb = b;
    vec3 fn = n;
#ifdef ANISO_NORMAL_MAP
    vec3 mapped = textureGrad(anisoNormalMap, uv, anisoTCoordDx, anisoTCoordDy).xyz;
    if (dot(mapped, mapped) > 1e-12)
    {
      fn = normalize(mat3(t, b, n) * mapped);
      vec3 projected = t - dot(t, fn) * fn;
      ft = dot(projected, projected) > 1e-12 ? normalize(projected) : anisoAnyPerpendicular(fn);
      fb = cross(fn, ft);
    }
#endif
#ifdef ANISO_QUATERNION_MAP
    vec3 q = textureGrad(anisoQuaternionMap, uv, anisoTCoordDx, anisoTCoordDy).xyz;
    q = dot(q, q) > 1e-12 ? normalize(q) : vec3(1.0, 0.0, 0.0);
    mat3 tbn = mat3(t, b, n);
    ft = tbn * vec3(q.x * q.x + q.y * q.y - q.z * q.z, 2.0 * q.y * q.z, 2.0 * q.x * q.z);
    fb = tbn * vec3(2.0 * q.y * q.z, q.x * q.x - q.y * q.y + q.z * q.z, -2.0 * q.x * q.y);
    fn = tbn * vec3(-2.0 * q.x * q.z, 2.0 * q.x * q.y, q.x * q.x - q.y * q.y - q.z * q.z);
#endif
#ifdef ANISO_TPR_MAP
    vec2 r = textureGrad(anisoTprMap, uv, anisoTCoordDx, anisoTCoordDy).xy;
    float rLength = length(r);
    if (rLength > 1e-6)
    {
      r /= rLength;
      vec3 rotated = r.x * ft + r.y * fb;
      fb = -r.y * ft + r.x * fb; // b = J t, the quarter turn in the tangent plane
      ft = rotated;
    }
#endif

    vec3 f0 = anisoF0;
    vec3 albedo = anisoAlbedo;
#ifdef ANISO_FIELD
    float fieldT = anisoFieldParameter();
#ifdef ANISO_FIELD_COLOR_ALBEDO
    albedo = anisoFieldColor(fieldT);
#endif
#ifdef ANISO_FIELD_COLOR_F0
    f0 = anisoFieldColor(fieldT);
#endif
#ifdef ANISO_FIELD_LOBE
    anisoExponents = anisoFieldLobe(anisoMaterialExponents, fieldT);
    anisoLodAnisotropy = 0.25 * log2((max(anisoExponents.x, anisoExponents.y) + 1.0) /
                                     (min(anisoExponents.x, anisoExponents.y) + 1.0));
#endif
#endif
#ifdef ANISO_ALBEDO_MAP
    albedo *= textureGrad(anisoAlbedoMap, uv, anisoTCoordDx, anisoTCoordDy).rgb;
#endif
#ifdef ANISO_METALLIC_MAP
    float metallic = textureGrad(anisoMetallicMap, uv, anisoTCoordDx, anisoTCoordDy).r;
    f0 = mix(vec3(0.04), f0, metallic);
    albedo *= 1.0 - metallic;
#endif

    vec3 specular = anisoSpecular(ft, fb, fn, v, f0);
    // Diffuse: k_d = 1 - F(n.v), Schlick at the view angle, as in the source.
    float m = clamp(1.0 - dot(fn, v), 0.0, 1.0);
    vec3 fresnelView = f0 + (1.0 - f0) * (m * m * m * m * m);
    vec3 diffuse = (1.0 - fresnelView) * albedo * (1.0 / anisoPi) * max(anisoIrradiance(fn), 0.0);
    vec3 radiance = specular + diffuse;
#ifdef ANISO_OCCLUSION_MAP
    radiance *= textureGrad(anisoOcclusionMap, uv, anisoTCoordDx, anisoTCoordDy).r;
#endif
    gl_FragData[0] = vec4(radiance, opacity);
  }
