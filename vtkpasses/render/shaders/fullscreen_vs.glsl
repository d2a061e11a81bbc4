//VTK::System::Dec
// Full-screen triangle pair at a chosen depth (1 = the far plane, behind every surface).
in vec4 ndCoordIn;
in vec2 texCoordIn;
out vec2 texCoord;
uniform float quadDepth;
void main()
{
  gl_Position = vec4(ndCoordIn.xy, quadDepth, 1.0);
  texCoord = texCoordIn;
}
