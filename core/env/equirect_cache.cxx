#include "core/env/equirect_cache.h"

#include "core/cache_directory.h"
#include "core/env/env_sampling.h"
#include "core/env/environment.h"
#include "core/hash.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>
#include <vector>

namespace aniso
{
namespace
{
namespace fs = std::filesystem;

constexpr const char* kMagic = "aniso-equirect 1";

// The radiance at 64 fixed directions (a spiral over the sphere), hashed: changes when the
// environment's function does.
uint64_t fingerprint(const Environment& env)
{
  uint64_t hash = kFnvOffsetBasis;
  constexpr int kDirections = 64;
  for (int i = 0; i < kDirections; ++i)
  {
    const double z = 1.0 - (2.0 * i + 1.0) / kDirections;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = 2.399963229728653 * i; // the golden angle
    const glm::dvec3 l = env.radiance(glm::dvec3(r * std::cos(phi), r * std::sin(phi), z));
    const double values[3] = {l.x, l.y, l.z};
    hash = fnv1a(values, sizeof values, hash);
  }
  return hash;
}

// The header line that names exactly one image.
std::string identityOf(const Environment& env, int width, int height, int supersample)
{
  std::ostringstream out;
  out << env.key() << " " << width << "x" << height << " supersample " << supersample
      << " radiance " << hex16(fingerprint(env));
  return out.str();
}

bool readCached(const fs::path& path, const std::string& identity, int width, int height,
                Image& image)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    return false;
  }
  std::string magic, storedIdentity, checksum;
  if (!std::getline(in, magic) || magic != kMagic || !std::getline(in, storedIdentity) ||
      storedIdentity != identity || !std::getline(in, checksum))
  {
    return false;
  }
  Image read(width, height, 3);
  const std::size_t bytes = read.data.size() * sizeof(float);
  in.read(reinterpret_cast<char*>(read.data.data()), std::streamsize(bytes));
  if (std::size_t(in.gcount()) != bytes || in.peek() != std::ifstream::traits_type::eof() ||
      checksum != hex16(fnv1a(read.data.data(), bytes)))
  {
    return false;
  }
  for (float x : read.data)
  {
    if (!std::isfinite(x))
    {
      return false;
    }
  }
  image = std::move(read);
  return true;
}

void writeCached(const fs::path& directory, const fs::path& path, const std::string& identity,
                 const Image& image)
{
  std::error_code ec;
  fs::create_directories(directory, ec);
  static std::atomic<uint64_t> counter{0};
  const fs::path temp =
      directory / ("." + path.filename().string() + "." + std::to_string(::getpid()) + "." +
                   std::to_string(counter++) + ".tmp");
  {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    const std::size_t bytes = image.data.size() * sizeof(float);
    out << kMagic << "\n" << identity << "\n" << hex16(fnv1a(image.data.data(), bytes)) << "\n";
    out.write(reinterpret_cast<const char*>(image.data.data()), std::streamsize(bytes));
    out.close();
    if (!out)
    {
      fs::remove(temp, ec);
      return;
    }
  }
  fs::rename(temp, path, ec);
  if (ec)
  {
    fs::remove(temp, ec);
  }
}
} // namespace

Image cachedEquirectRefined(const Environment& env, int width, int height, int supersample,
                            const std::string& cacheDirectory)
{
  if (cacheDirectory.empty() || env.key().rfind("builtin:", 0) != 0 || width < 1 || height < 1)
  {
    return renderEquirectRefined(env, width, height, supersample);
  }
  const std::string identity = identityOf(env, width, height, supersample);
  const fs::path directory = fs::path(cacheDirectory) / "env";
  const fs::path path =
      directory / ("equirect-" + hex16(fnv1a(identity.data(), identity.size())) + ".bin");
  Image image;
  try
  {
    if (readCached(path, identity, width, height, image))
    {
      return image;
    }
  }
  catch (const std::exception&)
  {
    // Disk trouble only costs the sampling.
  }
  image = renderEquirectRefined(env, width, height, supersample);
  if (image.channels == 3 && image.width == width && image.height == height)
  {
    try
    {
      writeCached(directory, path, identity, image);
    }
    catch (const std::exception&)
    {
    }
  }
  return image;
}

Image cachedEquirectRefined(const Environment& env, int width, int height, int supersample)
{
  return cachedEquirectRefined(env, width, height, supersample, defaultCacheDirectory());
}
} // namespace aniso
