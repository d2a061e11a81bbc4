//VTK::System::Dec
//VTK::Output::Dec
// Display transform of the accumulated linear radiance: exposure, tone mapping, sRGB encoding.
// RGB holds everything seen (surfaces and background), alpha the coverage of the surfaces.
in vec2 texCoord;
uniform sampler2D accumulation;
uniform float exposureScale;

//ANISO::DisplayTransform::Dec

void main()
{
  vec4 pixel = texelFetch(accumulation, ivec2(texCoord * vec2(textureSize(accumulation, 0))), 0);
  vec3 radiance = max(pixel.rgb, 0.0);
#ifdef ANISO_TRANSPARENT_BACKGROUND
  // Nothing behind the surfaces: un-premultiply so the PNG's colour is the surface's own.
  float alpha = clamp(pixel.a, 0.0, 1.0);
  radiance = alpha > 0.0 ? radiance / alpha : vec3(0.0);
#else
  float alpha = 1.0;
#endif
  gl_FragData[0] = vec4(encodeSrgb(toneMap(radiance * exposureScale)), alpha);
}
