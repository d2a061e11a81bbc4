// LEADR and microstructure materials, vertex shader declarations: the shading frame, texture
// coordinates and clip position reach the fragment shader (normals and tangents in world space).
in vec3 leadrNormalMC;
in vec3 leadrTangentMC;
in vec2 leadrTCoordMC;
uniform mat3 leadrNormalToWorld;    // inverse transpose of the actor matrix (3x3)
uniform mat3 leadrDirectionToWorld; // the actor matrix (3x3)
out vec3 leadrNormalWC;
out vec3 leadrTangentWC;
out vec2 leadrTCoord;
out vec4 leadrClipPosition;
