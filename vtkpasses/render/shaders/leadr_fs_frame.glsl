    // The fragment's view ray from its clip coordinates and the interpolated frame (tangent made
    // orthogonal to the normal), as core Frame::fromNormalTangent builds it.
    vec2 ndc = leadrClipPosition.xy / leadrClipPosition.w;
    vec4 nearH = leadrClipToWorld * vec4(ndc, -1.0, 1.0);
    vec3 viewWC = normalize(nearH.xyz / nearH.w - leadrPositionWC);
    vec3 n = normalize(leadrNormalWC);
    if (!gl_FrontFacing)
    {
      n = -n;
    }
    vec3 t = leadrTangentWC - dot(leadrTangentWC, n) * n;
    t = dot(t, t) > 1e-12 ? normalize(t) : leadrAnyPerpendicular(n);
    vec3 b = cross(n, t);
    mat3 tbn = mat3(t, b, n);
    vec3 v = vec3(dot(viewWC, t), dot(viewWC, b), dot(viewWC, n));
