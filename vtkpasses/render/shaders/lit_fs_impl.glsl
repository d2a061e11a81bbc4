  // Lit models: replace VTK's lighting result with the chosen model under the lights.
  {
    vec2 litNdc = litClipPosition.xy / litClipPosition.w;
    vec4 litNearH = litClipToWorld * vec4(litNdc, -1.0, 1.0);
    vec3 litView = normalize(litNearH.xyz / litNearH.w - litPositionWC);

#ifdef LIT_LINE
    // An illuminated line (docs/METHOD.md, "Lines"): n the viewer-facing normal of the thin
    // cylinder around the line, v's part perpendicular to the tangent (the hint below).
    vec3 litLineT = normalize(litTangentWC);
    vec3 litN = litView - dot(litView, litLineT) * litLineT;
    litN = dot(litN, litN) > 1e-12 ? normalize(litN)
                                   : normalize(cross(litLineT, abs(litLineT.z) < 0.9
                                                                 ? vec3(0.0, 0.0, 1.0)
                                                                 : vec3(1.0, 0.0, 0.0)));
#elif defined(LIT_HAVE_NORMALS)
    vec3 litN = normalize(litNormalWC);
    if (!gl_FrontFacing)
    {
      litN = -litN;
    }
#else
    vec3 litN = dot(litFaceNormalWC, litView) < 0.0 ? -litFaceNormalWC : litFaceNormalWC;
#endif
#ifdef LIT_HAVE_TANGENTS
    vec3 litHint = litTangentWC;
#else
    vec3 litHint = vec3(1.0, 0.0, 0.0);
#endif
#ifdef LIT_HAVE_TCOORDS
    vec2 litUv = litTCoord;
#else
    vec2 litUv = vec2(0.0);
#endif
    // Interpolated vectors are renormalised (and t made orthogonal) before the maps tilt them.
    LitTexel litTexel = litSampleTexel(litUv);
    mat3 litShadingFrame =
      litPerturbedFrame(litFrame(litN, litHint), litTexel.normal, litTexel.tangent);
    gl_FragData[0] = vec4(litShade(litTexel, litShadingFrame, litPositionWC, litView), opacity);
  }
