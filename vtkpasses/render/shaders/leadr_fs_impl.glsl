  // LEADR mapping: replaces VTK's lighting result.
  {
//LEADR_FRAME
    // The mip level of the moments from the footprint of the pixel (the GL rule, explicit so the
    // CPU evaluation can follow it exactly).
    vec2 uv = leadrTCoord * leadrTiles;
    float rho = max(length(leadrUvDx * leadrTiles * leadrMomentsSize),
                    length(leadrUvDy * leadrTiles * leadrMomentsSize));
    float lod = clamp(log2(max(rho, 1e-30)), 0.0, leadrMaxLevel);
    vec4 moments = textureLod(leadrMoments, uv, lod);
    float momentXY = textureLod(leadrMomentsXY, uv, lod).r;
    if (leadrPlainNormals != 0)
    {
      moments.zw = moments.xy * moments.xy;
      momentXY = moments.x * moments.y;
    }
    LeadrStats stats = leadrStatistics(moments, momentXY);
    v = leadrLiftedView(v);
    LeadrStats shifted = leadrMicronormal(stats, v);
    int gridN = clamp(leadrGridN, 1, 16);
    float gridWeight = 1.0 / float(gridN * gridN);

    vec3 radiance = vec3(0.0);
    for (int i = 0; i < leadrLightCount && i < leadrMaxLights; ++i)
    {
      vec3 irradiance;
      vec3 l = transpose(tbn) * leadrLightArrival(i, leadrPositionWC, irradiance);
      if (!(l.z > 0.0))
      {
        continue;
      }
      // The rough diffuse part: the Lambert term averaged over the texel's normals.
      float lambert = 0.0;
      for (int a = 0; a < gridN; ++a)
      {
        for (int c = 0; c < gridN; ++c)
        {
          lambert += max(dot(leadrGridNormal(shifted, leadrQuantiles[a], leadrQuantilesY[c]), l), 0.0);
        }
      }
      lambert *= gridWeight;
      radiance += (leadrSpecular(shifted, v, l) * l.z + leadrDiffuse * (lambert / leadrPi)) *
        irradiance;
    }

    if (leadrUseEnvironment != 0)
    {
      float g1v = leadrMasking(shifted, v);
      vec3 specular = vec3(0.0);
      vec3 irradiance = vec3(0.0);
      for (int a = 0; a < gridN; ++a)
      {
        for (int c = 0; c < gridN; ++c)
        {
          irradiance += max(leadrIrradiance(tbn * leadrGridNormal(stats, leadrQuantiles[a],
                                                                   leadrQuantilesY[c])), 0.0);
          if (!(g1v > 0.0))
          {
            continue;
          }
          vec3 m = leadrGridNormal(shifted, leadrQuantiles[a], leadrQuantilesY[c]);
          float vm = dot(v, m);
          if (!(vm > 0.0))
          {
            continue;
          }
          vec3 l = 2.0 * vm * m - v;
          if (!(l.z > 0.0))
          {
            continue;
          }
          float weight = g1v * leadrMasking(shifted, l) * vm / (v.z * m.z);
          // The cube level whose texels cover the solid angle this sample stands for.
          float density = leadrDistribution(shifted, m) * m.z;
          float sampleLod = 0.0;
          if (density > 0.0)
          {
            float omega = 4.0 * vm / (float(gridN * gridN) * density);
            // Frame k's mean holds the samples of k + 1 frames: the blur fades as it converges.
            sampleLod = clamp(0.5 * (log2(omega) - leadrLog2TexelSolidAngle - leadrLog2FrameCount),
                              0.0, leadrMaxLod);
          }
          vec3 incoming =
            textureLod(leadrEnvironment, leadrWorldToEnvironment * (tbn * l), sampleLod).rgb;
          specular += leadrSchlick(leadrF0, vm) * incoming * weight;
        }
      }
      radiance += specular * gridWeight + leadrDiffuse / leadrPi * irradiance * gridWeight;
    }
    gl_FragData[0] = vec4(radiance, opacity);
  }
