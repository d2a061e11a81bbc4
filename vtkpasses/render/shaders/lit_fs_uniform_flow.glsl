  // Lit models: what needs screen-space derivatives, before any branch.
  vec4 litPositionH = litClipToWorld * litClipPosition;
  vec3 litPositionWC = litPositionH.xyz / litPositionH.w;
#ifndef LIT_HAVE_NORMALS
  vec3 litFaceNormalWC = normalize(cross(dFdx(litPositionWC), dFdy(litPositionWC)));
#endif
