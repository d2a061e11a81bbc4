  // Anisotropic material: everything that needs screen-space derivatives, before any branch.
  vec4 anisoPositionH = anisoClipToWorld * anisoClipPosition;
  vec3 anisoPositionWC = anisoPositionH.xyz / anisoPositionH.w;
#if !defined(ANISO_HAVE_NORMALS) && !defined(ANISO_LINE)
  vec3 anisoFaceNormalWC = normalize(cross(dFdx(anisoPositionWC), dFdy(anisoPositionWC)));
#endif
#ifdef ANISO_HAVE_TCOORDS
  vec2 anisoTCoordDx = dFdx(anisoTCoord);
  vec2 anisoTCoordDy = dFdy(anisoTCoord);
#endif
