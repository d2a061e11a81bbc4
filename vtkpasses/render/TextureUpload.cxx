#include "vtkpasses/render/TextureUpload.h"

#include "core/error.h"

#include <atomic>
#include <string>
#include <vector>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLState.h>
#include <vtkTextureObject.h>
#include <vtk_glew.h>

namespace aniso
{
namespace
{
std::atomic<uint64_t> textureUploads{0};

struct GlFormat
{
  unsigned int internalFormat;
  unsigned int format;
};

GlFormat floatFormat(int channels, const char* subject)
{
  switch (channels)
  {
  case 1:
    return {GL_R32F, GL_RED};
  case 2:
    return {GL_RG32F, GL_RG};
  case 3:
    return {GL_RGB32F, GL_RGB};
  case 4:
    return {GL_RGBA32F, GL_RGBA};
  default:
    throw errorAbout(subject, std::to_string(channels) + " channels (1 to 4 expected)");
  }
}

// GL reports failures through glGetError only; turn the first one into an aniso::Error.
void checkGl(const char* subject, const char* what)
{
  const GLenum code = glGetError();
  if (code != GL_NO_ERROR)
  {
    throw errorAbout(subject,
                     std::string(what) + " failed (GL error " + std::to_string(code) + ")");
  }
}

vtkSmartPointer<vtkTextureObject> newFloatTexture(vtkOpenGLRenderWindow* window, int channels,
                                                  const char* subject)
{
  if (!window)
  {
    throw errorAbout(subject, "no OpenGL render window to create the texture in");
  }
  window->MakeCurrent();
  while (glGetError() != GL_NO_ERROR)
  {
    // Earlier errors belong to someone else; start clean so checkGl reports ours.
  }
  ++textureUploads;
  auto texture = vtkSmartPointer<vtkTextureObject>::New();
  texture->SetContext(window);
  const GlFormat format = floatFormat(channels, subject);
  texture->SetInternalFormat(format.internalFormat);
  texture->SetFormat(format.format);
  texture->SetDataType(GL_FLOAT);
  // Anisotropic filtering would change what the shaders compute; they ask for exact levels.
  texture->SetMaximumAnisotropicFiltering(1.0f);
  return texture;
}
} // namespace

uint64_t textureUploadCount()
{
  return textureUploads.load();
}

vtkSmartPointer<vtkTextureObject> uploadFloatTexture(vtkOpenGLRenderWindow* window, int width,
                                                     int height, int channels, const float* data,
                                                     TextureFiltering filtering, TextureWrap wrap,
                                                     const char* subject)
{
  if (width <= 0 || height <= 0 || !data)
  {
    throw errorAbout(subject, "empty texture");
  }
  auto texture = newFloatTexture(window, channels, subject);
  texture->SetWrapS(wrap == TextureWrap::Clamp ? vtkTextureObject::ClampToEdge
                                               : vtkTextureObject::Repeat);
  texture->SetWrapT(wrap == TextureWrap::Repeat ? vtkTextureObject::Repeat
                                                : vtkTextureObject::ClampToEdge);
  switch (filtering)
  {
  case TextureFiltering::Nearest:
    texture->SetMinificationFilter(vtkTextureObject::Nearest);
    texture->SetMagnificationFilter(vtkTextureObject::Nearest);
    break;
  case TextureFiltering::Linear:
    texture->SetMinificationFilter(vtkTextureObject::Linear);
    texture->SetMagnificationFilter(vtkTextureObject::Linear);
    break;
  case TextureFiltering::Mipmapped:
    texture->SetMinificationFilter(vtkTextureObject::LinearMipmapLinear);
    texture->SetMagnificationFilter(vtkTextureObject::Linear);
    break;
  }
  if (!texture->Create2DFromRaw(static_cast<unsigned int>(width), static_cast<unsigned int>(height),
                                channels, VTK_FLOAT, const_cast<float*>(data)))
  {
    throw errorAbout(subject, "the float texture could not be created");
  }
  checkGl(subject, "uploading the texture");
  if (filtering == TextureFiltering::Mipmapped)
  {
    texture->Activate();
    glGenerateMipmap(GL_TEXTURE_2D);
    texture->Deactivate();
    checkGl(subject, "generating the mip chain");
  }
  return texture;
}

vtkSmartPointer<vtkTextureObject> uploadMapTexture(vtkOpenGLRenderWindow* window,
                                                   const Image& image, int channels,
                                                   const char* subject)
{
  if (image.empty() || image.width <= 0 || image.height <= 0 || image.channels <= 0)
  {
    throw errorAbout(subject, "empty image");
  }
  std::vector<float> texels(std::size_t(image.width) * image.height * channels);
  for (int y = 0; y < image.height; ++y)
  {
    // Image row 0 is the top (v = 1); GL's first row is t = 0.
    const int row = image.height - 1 - y;
    for (int x = 0; x < image.width; ++x)
    {
      float* out = &texels[(std::size_t(y) * image.width + x) * channels];
      for (int c = 0; c < channels; ++c)
      {
        out[c] = c < image.channels ? image.at(x, row, c) : (c == 3 ? 1.0f : 0.0f);
      }
    }
  }
  return uploadFloatTexture(window, image.width, image.height, channels, texels.data(),
                            TextureFiltering::Mipmapped, TextureWrap::Repeat, subject);
}

vtkSmartPointer<vtkTextureObject> uploadCubemap(vtkOpenGLRenderWindow* window, const Cubemap& cube,
                                                const char* subject)
{
  if (cube.size <= 0 || cube.mips.empty())
  {
    throw errorAbout(subject, "empty cubemap");
  }
  auto texture = newFloatTexture(window, 3, subject);
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  texture->SetWrapR(vtkTextureObject::ClampToEdge);
  texture->SetMinificationFilter(vtkTextureObject::LinearMipmapLinear);
  texture->SetMagnificationFilter(vtkTextureObject::Linear);
  texture->SetBaseLevel(0);
  texture->SetMaxLevel(static_cast<int>(cube.mips.size()) - 1);
  texture->SetMinLOD(0.0f);
  texture->SetMaxLOD(static_cast<float>(cube.mips.size() - 1));

  // The face images hold RGB; pick the channels out in case a level carries more.
  auto faceTexels = [&](const Image& face, int size)
  {
    if (face.width != size || face.height != size || face.channels < 3)
    {
      throw errorAbout(subject, "a cubemap face is not " + std::to_string(size) + "x" +
                                    std::to_string(size) + " RGB");
    }
    std::vector<float> texels(std::size_t(size) * size * 3);
    for (int y = 0; y < size; ++y)
    {
      for (int x = 0; x < size; ++x)
      {
        for (int c = 0; c < 3; ++c)
        {
          texels[(std::size_t(y) * size + x) * 3 + c] = face.at(x, y, c);
        }
      }
    }
    return texels;
  };

  std::vector<std::vector<float>> level0(6);
  void* faces[6];
  for (int f = 0; f < 6; ++f)
  {
    level0[f] = faceTexels(cube.mips[0][f], cube.size);
    faces[f] = level0[f].data();
  }
  if (!texture->CreateCubeFromRaw(static_cast<unsigned int>(cube.size),
                                  static_cast<unsigned int>(cube.size), 3, VTK_FLOAT, faces))
  {
    throw errorAbout(subject, "the cube texture could not be created");
  }
  checkGl(subject, "uploading cubemap level 0");

  texture->Activate();
  window->GetState()->vtkglPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (std::size_t level = 1; level < cube.mips.size(); ++level)
  {
    const int size = std::max(cube.size >> level, 1);
    for (int f = 0; f < 6; ++f)
    {
      const std::vector<float> texels = faceTexels(cube.mips[level][f], size);
      glTexImage2D(static_cast<GLenum>(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f),
                   static_cast<GLint>(level), GL_RGB32F, size, size, 0, GL_RGB, GL_FLOAT,
                   texels.data());
    }
  }
  texture->Deactivate();
  checkGl(subject, "uploading the cubemap mip chain");
  return texture;
}
} // namespace aniso
