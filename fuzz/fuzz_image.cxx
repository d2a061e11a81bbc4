// libFuzzer harness of the image layer every map and environment goes through (readImage,
// OpenImageIO underneath): the first byte picks the file's extension (EXR, Radiance HDR, PNG,
// TIFF, JPEG), the rest is the file. Accepted outcomes: an image of the size and channels it
// states, or an aniso::Error naming the file.
#include "core/error.h"
#include "core/image/image.h"
#include "fuzz/fuzz_input.h"

#include <cstdint>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  if (size == 0)
  {
    return 0;
  }
  static const char* const kSuffixes[] = {".exr", ".hdr", ".png", ".tif", ".jpg"};
  const char* suffix = kSuffixes[data[0] % 5];
  const std::string path = aniso::fuzz::writeInput(data + 1, size - 1, suffix);
  try
  {
    const aniso::Image image = aniso::readImage(path);
    if (image.width < 1 || image.height < 1 || image.channels < 1 || image.channels > 4 ||
        image.data.size() != std::size_t(image.width) * image.height * image.channels)
    {
      std::abort(); // readImage promises a non-empty image of the size it states
    }
  }
  catch (const aniso::Error&)
  {
  }
  return 0;
}
