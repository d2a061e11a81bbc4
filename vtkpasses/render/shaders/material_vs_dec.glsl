// Anisotropic material, vertex shader declarations: the shading frame reaches the fragment
// shader in world space (normals and tangents from the actor's own arrays, so VTK's
// shift-and-scale of positions never bends them).
#ifdef ANISO_LINE
// A line set: the varyings carry VTK's VSOut suffix, so that its wide-line geometry shader
// passes them on (ShaderHook.h, lineGeometryCode).
#define anisoTangentWC anisoTangentWCVSOut
#define anisoClipPosition anisoClipPositionVSOut
#endif
#ifdef ANISO_HAVE_NORMALS
in vec3 anisoNormalMC;
uniform mat3 anisoNormalToWorld; // inverse transpose of the actor matrix (3x3)
out vec3 anisoNormalWC;
#endif
#ifdef ANISO_HAVE_TANGENTS
in vec3 anisoTangentMC;
uniform mat3 anisoDirectionToWorld; // the actor matrix (3x3)
out vec3 anisoTangentWC;
#endif
#ifdef ANISO_HAVE_TCOORDS
in vec2 anisoTCoordMC;
out vec2 anisoTCoord;
#endif
#ifdef ANISO_FIELD
in vec2 anisoFieldMC; // the field's value and 1 where it is NaN (MaterialShaderSource.h)
out vec2 anisoField;
#endif
out vec4 anisoClipPosition;
