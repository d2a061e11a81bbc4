#pragma once
// The image module: readImage and writeImage (image.h) with OpenImageIO in a shared object of
// their own, aniso-image-io.so, for a program that should not pay for OpenImageIO at its start.
// OpenImageIO brings about 260 shared libraries (OpenCV, ffmpeg, GDAL, ...), whose loading costs
// a process about 280 ms here; the mesh reader program, started for every file the application
// opens, needs images only for glTF textures. Such a program compiles image_on_demand.cxx
// instead of linking image.cxx: its readImage and writeImage load the module beside the
// executable on first use. The application and everything else link image.cxx as they did.
#include "core/image/image.h"

#include <string>

namespace aniso
{
struct ImageModule
{
  int version;
  Image (*read)(const std::string& path, ImageInfo* info);
  void (*write)(const std::string& path, const Image& image, const WriteOptions& options);
};

// Raised whenever ImageModule or the functions behind it change their signature or meaning.
constexpr int kImageModuleVersion = 1;
constexpr const char* kImageModuleFile = "aniso-image-io.so";
constexpr const char* kImageModuleEntry = "aniso_image_module";

// Loads the module now, for a program that bounds its address space afterwards (the mesh reader
// program, for glTF files): the module's libraries then count as what the program had at its
// start, not against the file's budget. A failure is kept and reported by the first readImage or
// writeImage, as without this call. Only in the programs that compile image_on_demand.cxx.
void loadImageModule();
} // namespace aniso
