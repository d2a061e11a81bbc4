// Point and directional lights (core/lights/light.h) and the fragment's shading frame, shared by
// the LEADR and microstructure materials.
in vec3 leadrNormalWC;
in vec3 leadrTangentWC;
in vec2 leadrTCoord;
in vec4 leadrClipPosition;
const int leadrMaxLights = 8;
uniform mat4 leadrClipToWorld; // inverse of the camera's world-to-clip transform
uniform int leadrLightCount;
uniform vec4 leadrLightVector[leadrMaxLights]; // xyz: direction (w = 0) or position (w = 1)
uniform vec3 leadrLightIntensity[leadrMaxLights];
const float leadrPi = 3.14159265358979;

// Direction towards light i (world space) and the irradiance it delivers at p, facing it.
vec3 leadrLightArrival(int i, vec3 p, out vec3 irradiance)
{
  vec4 light = leadrLightVector[i];
  if (light.w == 0.0)
  {
    irradiance = leadrLightIntensity[i];
    return normalize(light.xyz);
  }
  vec3 toLight = light.xyz - p;
  float distance = length(toLight);
  if (!(distance > 1e-9))
  {
    irradiance = vec3(0.0);
    return vec3(0.0, 0.0, 1.0);
  }
  irradiance = leadrLightIntensity[i] / (distance * distance);
  return toLight / distance;
}

vec3 leadrSchlick(vec3 f0, float c)
{
  float m = clamp(1.0 - c, 0.0, 1.0);
  return f0 + (1.0 - f0) * (m * m * m * m * m);
}

vec3 leadrAnyPerpendicular(vec3 n)
{
  vec3 axis = abs(n.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
  return normalize(axis - dot(axis, n) * n);
}
