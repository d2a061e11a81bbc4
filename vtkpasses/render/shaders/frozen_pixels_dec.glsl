// The pixels whose mean no longer changes (vtkAnisoAccumulationPass::FROZEN_PIXELS: R8, 1 where
// frozen, ivec2(gl_FragCoord.xy) the texel); anisoFrozenSize (0, 0) when none is. Inserted by
// ShaderHook before a material's declarations (ShaderCode::discardFrozenPixels).
uniform sampler2D anisoFrozen;
uniform ivec2 anisoFrozenSize;
