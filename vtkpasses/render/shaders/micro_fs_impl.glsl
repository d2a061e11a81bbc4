  // Small-scale microstructure: replaces VTK's lighting result.
  {
//LEADR_FRAME
    vec2 microCentre = leadrTCoord * microTiles;
    vec2 microAxisU = leadrUvDx * microTiles;
    vec2 microAxisV = leadrUvDy * microTiles;
#ifdef MICRO_TPR
    {
      // The structure turned so its y axis follows the map's direction r (core turnMicroPixel).
      vec2 r = textureLod(microTpr, leadrTCoord, 0.0).xy;
      r = dot(r, r) > 1e-24 ? normalize(r) : vec2(0.0, 1.0);
      vec3 turnedT = r.y * t - r.x * b;
      b = r.x * t + r.y * b;
      t = turnedT;
      tbn = mat3(t, b, n);
      v = vec3(dot(viewWC, t), dot(viewWC, b), dot(viewWC, n));
      mat2 turn = mat2(r.y, r.x, -r.x, r.y); // columns: images of (1, 0) and (0, 1)
      microCentre = turn * microCentre;
      microAxisU = turn * microAxisU;
      microAxisV = turn * microAxisV;
    }
#endif
    vec3 radiance = vec3(0.0);
    // The lights in the pixel's frame (the structure is far smaller than their distance).
    vec3 lightLocal[leadrMaxLights];
    vec3 lightIrradiance[leadrMaxLights];
    int lights = 0;
    for (int i = 0; i < leadrLightCount && i < leadrMaxLights; ++i)
    {
      vec3 irradiance;
      vec3 l = transpose(tbn) * leadrLightArrival(i, leadrPositionWC, irradiance);
      if (l.z > 0.0)
      {
        lightLocal[lights] = l;
        lightIrradiance[lights] = irradiance;
        ++lights;
      }
    }
    if (v.z > 0.0)
    {
      // The footprint: centre + a axisU + b axisV, a and b in [-1/2, 1/2].
      vec2 centre = microCentre;
      vec2 axisU = microAxisU;
      vec2 axisV = microAxisV;
      int k = clamp(microK, 1, 64);
      uint seed = (uint(gl_FragCoord.x) | (uint(gl_FragCoord.y) << 16)) ^ uint(microFrameSeed);
      for (int j = 0; j < k; ++j)
      {
        for (int i = 0; i < k; ++i)
        {
          uint index = uint(j * k + i);
          float a = microJittered != 0 ? microUniform(seed, 2u * index) : 0.5;
          float c = microJittered != 0 ? microUniform(seed, 2u * index + 1u) : 0.5;
          vec2 p = centre + ((float(i) + a) / float(k) - 0.5) * axisU +
            ((float(j) + c) / float(k) - 0.5) * axisV;
          vec2 q = p;
          float depth;
          if (microMasking == 2)
          {
            q = microMarch(p, v, depth);
          }
          else
          {
            depth = microSurfaceDepth(p);
            if (microMasking == 1)
            {
              q = p - v.xy / v.z * depth;
              depth = microSurfaceDepth(q);
            }
          }
          vec3 m = textureLod(microNormal, q, 0.0).xyz;
          m = dot(m, m) > 1e-24 ? normalize(m) : vec3(0.0, 0.0, 1.0);
          vec3 albedo = textureLod(microAlbedo, q, 0.0).rgb;
          if (!(dot(v, m) > 0.0))
          {
            continue;
          }
          for (int n = 0; n < lights; ++n)
          {
            vec3 l = lightLocal[n];
            float lm = dot(l, m);
            if (!(lm > 0.0))
            {
              continue;
            }
            if (microSelfShadowing != 0 && microShadowed(q, depth, l))
            {
              continue;
            }
            radiance += (albedo / leadrPi + microSpecular(v, l, m)) * lm * lightIrradiance[n];
          }
        }
      }
      radiance /= float(k * k);
    }
    gl_FragData[0] = vec4(radiance, opacity);
  }
