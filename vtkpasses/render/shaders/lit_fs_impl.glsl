  // Lit models: replace VTK's lighting result with the chosen model under the lights.
  {
    vec2 litNdc = litClipPosition.xy / litClipPosition.w;
    vec4 litNearH = litClipToWorld * vec4(litNdc, -1.0, 1.0);
    vec3 litView = normalize(litNearH.xyz / litNearH.w - litPositionWC);

#ifdef LIT_HAVE_NORMALS
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
