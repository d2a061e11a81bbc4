  // Lit models: after gl_Position is known.
#ifdef LIT_HAVE_NORMALS
  litNormalWC = litNormalToWorld * litNormalMC;
#endif
#ifdef LIT_HAVE_TANGENTS
  litTangentWC = litDirectionToWorld * litTangentMC;
#endif
#ifdef LIT_HAVE_TCOORDS
  litTCoord = litTCoordMC;
#endif
  // Clip coordinates interpolate linearly, so the fragment recovers its exact view ray.
  litClipPosition = gl_Position;
