// The image module's entry point (image_module.h); the module is this file and image.cxx.
#include "core/image/image_module.h"

extern "C" __attribute__((visibility("default"))) const aniso::ImageModule* aniso_image_module()
{
  static const aniso::ImageModule module{aniso::kImageModuleVersion, &aniso::readImage,
                                         &aniso::writeImage};
  return &module;
}
