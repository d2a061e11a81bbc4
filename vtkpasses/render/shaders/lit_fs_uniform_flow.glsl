  // Lit models: what needs screen-space derivatives, before any branch.
  vec4 litPositionH = litClipToWorld * litClipPosition;
  vec3 litPositionWC = litPositionH.xyz / litPositionH.w;
#if !defined(LIT_HAVE_NORMALS) && !defined(LIT_LINE)
  vec3 litFaceNormalWC = normalize(cross(dFdx(litPositionWC), dFdy(litPositionWC)));
#endif
