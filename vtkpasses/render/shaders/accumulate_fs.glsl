//VTK::System::Dec
//VTK::Output::Dec
// Folds one rendered frame into the running mean (the blend stage weighs it 1/(k+1)), with the
// background put behind the surfaces in the same pass: where the frame's depth is still the far
// plane (no surface drew there), the environment seen along the pixel's view ray of this
// frame's (jittered) camera, with ANISO_BACKGROUND_ENVIRONMENT, or a uniform radiance. Alpha 0
// there: background is not coverage.
in vec2 texCoord;
uniform sampler2D frame;
uniform sampler2D frameDepth;
uniform vec3 backgroundRadiance;
#ifdef ANISO_FROZEN_PIXELS
uniform sampler2D frozen; // R8: 1 where the pixel's mean no longer changes (discarded: kept)
#endif
#ifdef ANISO_BACKGROUND_ENVIRONMENT
uniform mat4 clipToWorld;
uniform mat3 worldToEnvironment;
uniform samplerCube environment;
#endif
void main()
{
  ivec2 texel = ivec2(texCoord * vec2(textureSize(frame, 0)));
#ifdef ANISO_FROZEN_PIXELS
  if (texelFetch(frozen, texel, 0).r > 0.5)
  {
    discard;
  }
#endif
  if (texelFetch(frameDepth, texel, 0).r < 1.0)
  {
    gl_FragData[0] = texelFetch(frame, texel, 0);
    return;
  }
#ifdef ANISO_BACKGROUND_ENVIRONMENT
  vec2 ndc = 2.0 * texCoord - 1.0;
  vec4 nearH = clipToWorld * vec4(ndc, -1.0, 1.0);
  vec4 farH = clipToWorld * vec4(ndc, 1.0, 1.0);
  vec3 direction = normalize(farH.xyz / farH.w - nearH.xyz / nearH.w);
  gl_FragData[0] = vec4(textureLod(environment, worldToEnvironment * direction, 0.0).rgb, 0.0);
#else
  gl_FragData[0] = vec4(backgroundRadiance, 0.0);
#endif
}
