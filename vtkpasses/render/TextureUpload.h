#pragma once
// Float textures for the anisotropic material and its passes, made from the core's images,
// lookup tables and cubemaps. Needs the window's context (made current here).
#include "core/env/cubemap.h"
#include "core/image/image.h"

#include <cstdint>
#include <vtkSmartPointer.h>

class vtkOpenGLRenderWindow;
class vtkTextureObject;

namespace aniso
{
enum class TextureFiltering
{
  Nearest,   // exact texels (texelFetch lookups such as the half-vector LUT)
  Linear,    // bilinear, no mip chain (lookup tables)
  Mipmapped, // trilinear over a generated mip chain (maps seen minified on a surface)
};

enum class TextureWrap
{
  Clamp,
  Repeat,
  RepeatSClampT, // an equirectangular image: around in u, clamped at the poles
};

// A 2D float texture of `channels` (1 to 4) from interleaved rows; row 0 of `data` becomes
// texture row t = 0. Throws aniso::Error "SUBJECT: reason" if GL refuses it.
vtkSmartPointer<vtkTextureObject> uploadFloatTexture(vtkOpenGLRenderWindow* window, int width,
                                                     int height, int channels, const float* data,
                                                     TextureFiltering filtering, TextureWrap wrap,
                                                     const char* subject);

// An image texture for a surface map: image row 0 (the top row of the file) goes to v = 1,
// so texture(map, uv) follows the usual UV convention (v = 0 at the bottom). `channels` of
// the image are uploaded (missing ones read 0, 1 for alpha).
vtkSmartPointer<vtkTextureObject> uploadMapTexture(vtkOpenGLRenderWindow* window,
                                                   const Image& image, int channels,
                                                   const char* subject);

// A float RGB cube texture with every level of cube.mips, trilinear, clamped at the edges
// (seamless filtering across faces is enabled where it is sampled).
vtkSmartPointer<vtkTextureObject> uploadCubemap(vtkOpenGLRenderWindow* window, const Cubemap& cube,
                                                const char* subject);

// Textures created by the functions above since the process started (every upload makes one),
// so callers can check that nothing is uploaded again while its inputs stay the same.
uint64_t textureUploadCount();
} // namespace aniso
