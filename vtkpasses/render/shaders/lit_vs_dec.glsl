// Lit models, vertex shader declarations: the shading frame and texture coordinates reach the
// fragment shader in world space, from the actor's own arrays.
#ifdef LIT_LINE
// A line set: varyings with VTK's VSOut suffix, passed on by its wide-line geometry shader
// (ShaderHook.h, lineGeometryCode).
#define litTangentWC litTangentWCVSOut
#define litClipPosition litClipPositionVSOut
#endif
#ifdef LIT_HAVE_NORMALS
in vec3 litNormalMC;
uniform mat3 litNormalToWorld; // inverse transpose of the actor matrix (3x3)
out vec3 litNormalWC;
#endif
#ifdef LIT_HAVE_TANGENTS
in vec3 litTangentMC;
uniform mat3 litDirectionToWorld; // the actor matrix (3x3)
out vec3 litTangentWC;
#endif
#ifdef LIT_HAVE_TCOORDS
in vec2 litTCoordMC;
out vec2 litTCoord;
#endif
out vec4 litClipPosition;
