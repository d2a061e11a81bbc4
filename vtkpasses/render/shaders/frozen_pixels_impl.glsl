  // A frozen pixel keeps its mean: nothing to shade (a discard before the material's work;
  // llvmpipe then skips the rest of the shader for a block of such pixels). Inserted by
  // ShaderHook before a material's shading (ShaderCode::discardFrozenPixels).
  if (all(lessThan(ivec2(gl_FragCoord.xy), anisoFrozenSize)) &&
      texelFetch(anisoFrozen, ivec2(gl_FragCoord.xy), 0).r > 0.5)
  {
    discard;
  }
