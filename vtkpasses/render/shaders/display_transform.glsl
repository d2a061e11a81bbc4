// The display transform of linear radiance, shared by the display pass (display_fs.glsl) and by
// a material drawn straight to the screen without it (displayInFragmentCode, DisplaySettings.h):
// tone mapping by the ANISO_TONE_MAP_* define, then sRGB encoding.
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
