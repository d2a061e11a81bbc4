  // LEADR and microstructure materials: screen-space derivatives, before any branch.
  vec4 leadrPositionH = leadrClipToWorld * leadrClipPosition;
  vec3 leadrPositionWC = leadrPositionH.xyz / leadrPositionH.w;
  vec2 leadrUvDx = dFdx(leadrTCoord);
  vec2 leadrUvDy = dFdy(leadrTCoord);
