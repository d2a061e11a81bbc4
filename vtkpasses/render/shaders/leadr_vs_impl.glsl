  // LEADR and microstructure materials: runs after gl_Position is known.
  leadrNormalWC = leadrNormalToWorld * leadrNormalMC;
  leadrTangentWC = leadrDirectionToWorld * leadrTangentMC;
  leadrTCoord = leadrTCoordMC;
  // Clip coordinates interpolate linearly, so the fragment recovers its exact view ray.
  leadrClipPosition = gl_Position;
