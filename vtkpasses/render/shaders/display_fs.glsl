//VTK::System::Dec
//VTK::Output::Dec
// Display transform of the accumulated linear radiance: exposure, tone mapping, sRGB encoding.
// RGB holds everything seen (surfaces and background), alpha the coverage of the surfaces.
in vec2 texCoord;
uniform sampler2D accumulation;
uniform float exposureScale;

vec3 toneMap(vec3 x)
{
#if defined(ANISO_TONE_MAP_ACES)
  // Narkowicz's fit of the ACES filmic curve.
  return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
#elif defined(ANISO_TONE_MAP_REINHARD)
  return x / (1.0 + x);
#else
  return clamp(x, 0.0, 1.0);
#endif
}

// The sRGB transfer function (IEC 61966-2-1), exact piecewise form.
vec3 encodeSrgb(vec3 c)
{
  vec3 low = 12.92 * c;
  vec3 high = 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055;
  return mix(low, high, step(vec3(0.0031308), c));
}

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
