  // Anisotropic material: runs after gl_Position is known.
#ifdef ANISO_HAVE_NORMALS
  anisoNormalWC = anisoNormalToWorld * anisoNormalMC;
#endif
#ifdef ANISO_HAVE_TANGENTS
  anisoTangentWC = anisoDirectionToWorld * anisoTangentMC;
#endif
#ifdef ANISO_HAVE_TCOORDS
  anisoTCoord = anisoTCoordMC;
#endif
#ifdef ANISO_FIELD
  anisoField = anisoFieldMC;
#endif
  // Clip coordinates interpolate linearly on the triangle, so the fragment recovers its exact
  // view ray (perspective or parallel) from them.
  anisoClipPosition = gl_Position;
