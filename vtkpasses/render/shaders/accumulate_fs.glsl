//VTK::System::Dec
//VTK::Output::Dec
// Copies one rendered frame; the blend stage forms the running mean with weight 1/(k+1).
in vec2 texCoord;
uniform sampler2D frame;
void main()
{
  gl_FragData[0] = texelFetch(frame, ivec2(texCoord * vec2(textureSize(frame, 0))), 0);
}
