#include "core/maps/map_files.h"

#include "core/error.h"
#include "core/maps/tpr_map.h"

#include <filesystem>
#include <utility>

namespace aniso
{
Image decodeSignedMap(Image image, bool integerFormat)
{
  if (integerFormat)
  {
    for (float& v : image.data)
    {
      v = 2.0f * v - 1.0f;
    }
  }
  return image;
}

Image readSignedMap(const std::string& path)
{
  ImageInfo info;
  Image image = readImage(path, &info);
  return decodeSignedMap(std::move(image), info.integerFormat);
}

Image tprFromFileImage(Image image, bool integerFormat)
{
  if (image.channels == 1)
  {
    return tprFromAngleImage(image);
  }
  return decodeSignedMap(std::move(image), integerFormat);
}

Image readTprMap(const std::string& text, const std::string& subject)
{
  std::error_code ec;
  if (std::filesystem::exists(text, ec))
  {
    ImageInfo info;
    Image image = readImage(text, &info);
    return tprFromFileImage(std::move(image), info.integerFormat);
  }
  TprParams params;
  try
  {
    params = parseTprPattern(text);
  }
  catch (const Error& e)
  {
    throw errorAbout(subject, "'" + text + "' is no file, nor a pattern (" + e.what() + ")");
  }
  return bakeTprMap(params, kTprPatternSide, kTprPatternSide);
}
} // namespace aniso
