//VTK::System::Dec
//VTK::Output::Dec
// Background behind the surfaces (drawn at the far plane, depth-tested): the environment seen
// along each pixel's view ray, or a uniform radiance. Alpha 0: background is not coverage.
in vec2 texCoord;
uniform mat4 clipToWorld;
uniform mat3 worldToEnvironment;
uniform samplerCube environment;
uniform bool showEnvironment; // else backgroundRadiance
uniform vec3 backgroundRadiance;
void main()
{
  vec2 ndc = 2.0 * texCoord - 1.0;
  if (showEnvironment)
  {
    vec4 nearH = clipToWorld * vec4(ndc, -1.0, 1.0);
    vec4 farH = clipToWorld * vec4(ndc, 1.0, 1.0);
    vec3 direction = normalize(farH.xyz / farH.w - nearH.xyz / nearH.w);
    gl_FragData[0] = vec4(textureLod(environment, worldToEnvironment * direction, 0.0).rgb, 0.0);
  }
  else
  {
    gl_FragData[0] = vec4(backgroundRadiance, 0.0);
  }
}
