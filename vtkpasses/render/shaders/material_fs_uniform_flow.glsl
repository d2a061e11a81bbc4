  // Anisotropic material: everything that needs screen-space derivatives, before any branch.
  vec4 anisoPositionH = anisoClipToWorld * anisoClipPosition;
  vec3 anisoPositionWC = anisoPositionH.xyz / anisoPositionH.w;
#ifndef ANISO_HAVE_NORMALS
  vec3 anisoFaceNormalWC = normalize(cross(dFdx(anisoPositionWC), dFdy(anisoPositionWC)));
#endif
#ifdef ANISO_HAVE_TCOORDS
  vec2 anisoTCoordDx = dFdx(anisoTCoord);
  vec2 anisoTCoordDy = dFdy(anisoTCoord);
#endif
