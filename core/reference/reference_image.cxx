#include "core/reference/reference_image.h"

#include "core/env/parallel.h"
#include "core/env/sun_sky.h"
#include "core/error.h"
#include "core/frame.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>
#include <limits>
#include <sstream>
#include <unistd.h>

namespace aniso
{
namespace
{
namespace fs = std::filesystem;

// Bumped whenever what a cached reference holds changes meaning.
constexpr int kCacheFormat = 2; // 2: each pixel's converged flag
constexpr const char* kCacheMagic = "aniso-bench-reference";

double luminance(const glm::dvec3& c)
{
  return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
}

// FNV-1a over raw bytes: a fingerprint of the inputs for file names, not a security measure
// (the file repeats the full key, which is compared on reading).
struct Fnv
{
  uint64_t state = 1469598103934665603ull;
  void add(const void* data, std::size_t size)
  {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i)
    {
      state = (state ^ bytes[i]) * 1099511628211ull;
    }
  }
  void add(double value) { add(&value, sizeof value); }
  void add(const glm::dvec3& v)
  {
    add(v.x);
    add(v.y);
    add(v.z);
  }
};

std::string hex(double value)
{
  uint64_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(bits));
  return text;
}

// Everything a reference depends on, spelled out: the model, the environment, the integrator's
// options, and a fingerprint of the compared pixels' geometry (which stands for the mesh, the
// camera and the image size).
std::string cacheKey(const std::vector<PixelSample>& geometry, int width, int height,
                     const std::vector<int>& selected, const ReferenceModel& model,
                     const Environment& environment, const ReferenceOptions& options)
{
  Fnv pixels;
  for (int index : selected)
  {
    const PixelSample& s = geometry[std::size_t(index)];
    pixels.add(&index, sizeof index);
    pixels.add(s.position);
    pixels.add(s.normal);
    pixels.add(s.tangent);
    pixels.add(s.view);
  }
  std::ostringstream key;
  key << kCacheMagic << " v" << kCacheFormat << " " << width << "x" << height << " pixels "
      << selected.size() << " geometry " << std::hex << pixels.state << std::dec;
  if (model.ggx)
  {
    key << " ggx " << hex(model.ggxLobe.alphaX) << " " << hex(model.ggxLobe.alphaY) << " rot "
        << hex(model.tangentRotation);
  }
  else
  {
    key << " as " << hex(model.asLobe.nu) << " " << hex(model.asLobe.nv);
  }
  key << " f0 " << hex(model.f0.x) << " " << hex(model.f0.y) << " " << hex(model.f0.z) << " env "
      << environment.key() << " tol " << hex(options.relativeTolerance) << " "
      << hex(options.absoluteTolerance) << " max " << options.maxEvaluations;
  if (dynamic_cast<const SunSkyEnvironment*>(&environment))
  {
    key << " sun-cone"; // the sun integrated over its own cone (integrateSpecularSunSky)
  }
  if (!model.ggx && sharedSourceQuadrature(environment))
  {
    key << " sources-split"; // the sources over their texels (integrateSpecularSources)
  }
  return key.str();
}

std::string cachePath(const std::string& directory, const std::string& key)
{
  Fnv name;
  name.add(key.data(), key.size());
  char file[64];
  std::snprintf(file, sizeof file, "reference_%016llx.bin",
                static_cast<unsigned long long>(name.state));
  return (fs::path(directory) / file).string();
}

struct Record
{
  int32_t x;
  int32_t y;
  double value[3];
  double errorEstimate;
  int64_t converged; // 0 or 1 (64 bits: the record keeps no padding)
};

bool readCache(const std::string& path, const std::string& key, std::size_t count,
               ReferenceImage& image)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    return false;
  }
  std::string storedKey;
  std::getline(in, storedKey);
  uint64_t storedCount = 0;
  uint64_t evaluations = 0;
  in.read(reinterpret_cast<char*>(&storedCount), sizeof storedCount);
  in.read(reinterpret_cast<char*>(&evaluations), sizeof evaluations);
  if (!in || storedKey != key || storedCount != count)
  {
    return false;
  }
  std::vector<Record> records(count);
  in.read(reinterpret_cast<char*>(records.data()),
          static_cast<std::streamsize>(count * sizeof(Record)));
  if (!in || in.peek() != std::char_traits<char>::eof())
  {
    return false;
  }
  image.pixels.clear();
  for (const Record& r : records)
  {
    const glm::dvec3 value(r.value[0], r.value[1], r.value[2]);
    if (!std::isfinite(luminance(value)) || !std::isfinite(r.errorEstimate))
    {
      return false;
    }
    image.pixels.push_back({r.x, r.y, value, r.errorEstimate, r.converged != 0});
    image.unconverged += r.converged != 0 ? 0 : 1;
  }
  image.evaluations = evaluations;
  return true;
}

// Written to a temporary file and renamed, so a reader never sees half a file. A failure only
// costs the next run a recomputation.
void writeCache(const std::string& path, const std::string& key, const ReferenceImage& image)
{
  std::error_code ec;
  fs::create_directories(fs::path(path).parent_path(), ec);
  const std::string temporary = path + ".tmp" + std::to_string(::getpid());
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out)
    {
      return;
    }
    out << key << "\n";
    const uint64_t count = image.pixels.size();
    out.write(reinterpret_cast<const char*>(&count), sizeof count);
    out.write(reinterpret_cast<const char*>(&image.evaluations), sizeof image.evaluations);
    for (const ReferencePixel& p : image.pixels)
    {
      const Record r{
          p.x, p.y, {p.value.x, p.value.y, p.value.z}, p.errorEstimate, p.converged ? 1 : 0};
      out.write(reinterpret_cast<const char*>(&r), sizeof r);
    }
    if (!out)
    {
      out.close();
      fs::remove(temporary, ec);
      return;
    }
  }
  fs::rename(temporary, path, ec);
  if (ec)
  {
    fs::remove(temporary, ec);
  }
}

double errorBound(const std::vector<ReferencePixel>& pixels)
{
  double error = 0.0;
  double norm = 0.0;
  for (const ReferencePixel& p : pixels)
  {
    const double squared = glm::dot(p.value, p.value);
    const double y = luminance(p.value);
    const double relative = y > 0.0 ? p.errorEstimate / y : 0.0;
    error += relative * relative * squared;
    norm += squared;
  }
  return norm > 0.0 ? std::sqrt(error / norm) : 0.0;
}

// Hit pixels facing the viewer whose 3x3 neighbourhood is hit too (selectPixels).
std::vector<char> eligiblePixels(const std::vector<PixelSample>& geometry, int width, int height)
{
  auto hitAt = [&](int x, int y) {
    return x >= 0 && y >= 0 && x < width && y < height && geometry[std::size_t(y) * width + x].hit;
  };
  std::vector<char> eligible(geometry.size(), 0);
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      const PixelSample& s = geometry[std::size_t(y) * width + x];
      bool inside = s.hit && glm::dot(s.normal, s.view) > 0.0;
      for (int dy = -1; dy <= 1 && inside; ++dy)
      {
        for (int dx = -1; dx <= 1 && inside; ++dx)
        {
          inside = hitAt(x + dx, y + dy);
        }
      }
      eligible[std::size_t(y) * width + x] = inside ? 1 : 0;
    }
  }
  return eligible;
}

std::vector<int> onGrid(const std::vector<char>& eligible, int width, int height, int stride)
{
  std::vector<int> selected;
  for (int y = stride / 2; y < height; y += stride)
  {
    for (int x = stride / 2; x < width; x += stride)
    {
      if (eligible[std::size_t(y) * width + x])
      {
        selected.push_back(y * width + x);
      }
    }
  }
  return selected;
}
} // namespace

std::vector<int> selectPixels(const std::vector<PixelSample>& geometry, int width, int height,
                              int count)
{
  const std::vector<char> eligible = eligiblePixels(geometry, width, height);
  const auto total = std::count(eligible.begin(), eligible.end(), char(1));
  const int stride =
      std::max(1, static_cast<int>(std::floor(std::sqrt(double(total) / std::max(count, 1)))));
  return onGrid(eligible, width, height, stride);
}

std::vector<int> selectPixelGrid(const std::vector<PixelSample>& geometry, int width, int height,
                                 int stride)
{
  if (stride < 1)
  {
    throw errorAbout("reference", "the pixel stride must be at least 1");
  }
  return onGrid(eligiblePixels(geometry, width, height), width, height, stride);
}

namespace
{
// The Ashikhmin-Shirley specular by the rule the environment needs: the sun-sky's sun over its
// own cone, an image's concentrated sources over their texels, anything else by the rules.
ReferenceResult specularReference(const AsLobe& lobe, const glm::dvec3& f0, const Frame& frame,
                                  const glm::dvec3& view, const Environment& environment,
                                  const ReferenceOptions& options)
{
  if (const auto* sunSky = dynamic_cast<const SunSkyEnvironment*>(&environment))
    return integrateSpecularSunSky(lobe, f0, frame, view, *sunSky, options);
  if (const std::shared_ptr<const SourceQuadrature> sources = sharedSourceQuadrature(environment))
    return integrateSpecularSources(lobe, f0, frame, view, environment, *sources, options);
  return integrateSpecular(lobe, f0, frame, view, environment, options);
}
} // namespace

ReferenceImage computeReference(const std::vector<PixelSample>& geometry, int width, int height,
                                const std::vector<int>& selected, const ReferenceModel& model,
                                const Environment& environment, const ReferenceOptions& options,
                                const std::string& directory)
{
  ReferenceImage image;
  image.width = width;
  image.height = height;
  const std::string key = cacheKey(geometry, width, height, selected, model, environment, options);
  const std::string path = directory.empty() ? std::string() : cachePath(directory, key);
  if (!path.empty() && readCache(path, key, selected.size(), image))
  {
    image.fromCache = true;
    image.relativeErrorBound = errorBound(image.pixels);
    return image;
  }

  const auto start = std::chrono::steady_clock::now();
  // The sun-sky's disc is far smaller than the general rules resolve: its own cone.
  const auto* sunSky = dynamic_cast<const SunSkyEnvironment*>(&environment);
  image.pixels.resize(selected.size());
  std::vector<uint64_t> evaluations(selected.size(), 0);
  parallelFor(
      static_cast<int>(selected.size()),
      [&](int i)
      {
        const int index = selected[std::size_t(i)];
        const PixelSample& s = geometry[std::size_t(index)];
        Frame frame = Frame::fromNormalTangent(s.normal, s.tangent);
        ReferenceResult r;
        if (model.ggx)
        {
          const double c = std::cos(model.tangentRotation);
          const double sn = std::sin(model.tangentRotation);
          frame = Frame::fromNormalTangent(frame.n, c * frame.t + sn * frame.b);
          r = sunSky ? integrateSpecularGgxSunSky(model.ggxLobe, model.f0, frame, s.view, *sunSky,
                                                  options)
                     : integrateSpecularGgx(model.ggxLobe, model.f0, frame, s.view, environment,
                                            options);
        }
        else
        {
          r = specularReference(model.asLobe, model.f0, frame, s.view, environment, options);
        }
        image.pixels[std::size_t(i)] = {index % width, index / width, r.value, r.errorEstimate,
                                        r.converged};
        evaluations[std::size_t(i)] = r.evaluations;
      });
  for (uint64_t e : evaluations)
  {
    image.evaluations += e;
  }
  for (const ReferencePixel& p : image.pixels)
  {
    image.unconverged += p.converged ? 0 : 1;
  }
  image.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  image.relativeErrorBound = errorBound(image.pixels);
  if (!path.empty())
  {
    writeCache(path, key, image);
  }
  return image;
}

ReferencePixel referencePixel(const PixelSample& s, int x, int y, const ReferenceMaterial& material,
                              const Environment& environment, const glm::dmat3& worldToEnvironment,
                              const ReferenceOptions& options, uint64_t* evaluations)
{
  const Frame world = Frame::fromNormalTangent(s.normal, s.tangent);
  const Frame frame = Frame::fromNormalTangent(worldToEnvironment * world.n,
                                               worldToEnvironment * world.t);
  const glm::dvec3 view = worldToEnvironment * s.view;
  const ReferenceResult specular =
      specularReference(material.lobe, material.f0, frame, view, environment, options);
  ReferencePixel p{x, y, specular.value, specular.errorEstimate, specular.converged};
  uint64_t count = specular.evaluations;
  if (material.albedo != glm::dvec3(0.0))
  {
    // The shader's k_d = 1 - F(n.v), Schlick at the view angle.
    const double m = std::clamp(1.0 - glm::dot(frame.n, view), 0.0, 1.0);
    const glm::dvec3 fresnel = material.f0 + (1.0 - material.f0) * std::pow(m, 5.0);
    const ReferenceResult irradiance = integrateIrradiance(frame.n, environment, options);
    const glm::dvec3 factor = (1.0 - fresnel) * material.albedo / M_PI;
    p.value += factor * irradiance.value;
    p.errorEstimate += luminance(factor) * irradiance.errorEstimate;
    p.converged = p.converged && irradiance.converged;
    count += irradiance.evaluations;
  }
  if (evaluations)
  {
    *evaluations = count;
  }
  return p;
}

SceneReference computeSceneReference(const std::vector<PixelSample>& geometry, int width,
                                     int height, const std::vector<int>& selected,
                                     const std::vector<ReferenceMaterial>& materials,
                                     const Environment& environment,
                                     const glm::dmat3& worldToEnvironment,
                                     const ReferenceOptions& options,
                                     const std::atomic<bool>* cancel)
{
  SceneReference image;
  image.width = width;
  image.height = height;
  const auto start = std::chrono::steady_clock::now();
  std::vector<ReferencePixel> pixels(selected.size());
  std::vector<char> done(selected.size(), 0);
  std::vector<uint64_t> evaluations(selected.size(), 0);
  parallelFor(
      static_cast<int>(selected.size()),
      [&](int i)
      {
        if (cancel && cancel->load(std::memory_order_relaxed))
        {
          return;
        }
        const int index = selected[std::size_t(i)];
        const PixelSample& s = geometry.at(std::size_t(index));
        if (!s.hit || s.material < 0 || s.material >= int(materials.size()))
        {
          throw errorAbout("reference", "pixel " + std::to_string(index) +
                                            " is not on a part with a material");
        }
        pixels[std::size_t(i)] =
            referencePixel(s, index % width, index / width, materials[std::size_t(s.material)],
                           environment, worldToEnvironment, options, &evaluations[std::size_t(i)]);
        done[std::size_t(i)] = 1;
      });
  for (std::size_t i = 0; i < pixels.size(); ++i)
  {
    if (done[i])
    {
      image.pixels.push_back(pixels[i]);
      image.evaluations += evaluations[i];
      image.unconverged += pixels[i].converged ? 0 : 1;
    }
  }
  image.cancelled = image.pixels.size() < selected.size();
  image.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  image.relativeErrorBound = errorBound(image.pixels);
  return image;
}

Image errorMap(const Image& render, const ReferenceImage& reference)
{
  if (render.width != reference.width || render.height != reference.height || render.channels < 3)
  {
    throw errorAbout("render", "image size or channels differ from the reference");
  }
  Image map(reference.width, reference.height, 1);
  std::fill(map.data.begin(), map.data.end(), std::numeric_limits<float>::quiet_NaN());
  double norm = 0.0;
  for (const ReferencePixel& p : reference.pixels)
  {
    norm += glm::dot(p.value, p.value);
  }
  const double rms =
      reference.pixels.empty() ? 0.0 : std::sqrt(norm / double(reference.pixels.size()));
  for (const ReferencePixel& p : reference.pixels)
  {
    const glm::dvec3 value(render.at(p.x, p.y, 0), render.at(p.x, p.y, 1), render.at(p.x, p.y, 2));
    const double d = glm::length(value - p.value);
    map.at(p.x, p.y, 0) = static_cast<float>(rms > 0.0 ? d / rms : d);
  }
  return map;
}

ImageError compareToReference(const Image& render, const ReferenceImage& reference)
{
  if (render.width != reference.width || render.height != reference.height || render.channels < 4)
  {
    throw errorAbout("render", "image size or channels differ from the reference");
  }
  ImageError e;
  double error = 0.0;
  double norm = 0.0;
  std::vector<double> pixelErrors;
  pixelErrors.reserve(reference.pixels.size());
  for (const ReferencePixel& p : reference.pixels)
  {
    const glm::dvec3 value(render.at(p.x, p.y, 0), render.at(p.x, p.y, 1), render.at(p.x, p.y, 2));
    if (!std::isfinite(value.x) || !std::isfinite(value.y) || !std::isfinite(value.z))
    {
      ++e.nonFinite;
      continue;
    }
    e.uncovered += render.at(p.x, p.y, 3) < 1.0f ? 1 : 0;
    const glm::dvec3 d = value - p.value;
    error += glm::dot(d, d);
    norm += glm::dot(p.value, p.value);
    pixelErrors.push_back(glm::length(d));
  }
  if (e.nonFinite > 0)
  {
    e.relativeL2 = e.percentile99 = std::numeric_limits<double>::infinity();
    return e;
  }
  if (norm <= 0.0 || pixelErrors.empty())
  {
    e.relativeL2 = e.percentile99 = std::numeric_limits<double>::quiet_NaN();
    return e;
  }
  e.relativeL2 = std::sqrt(error / norm);
  const double rms = std::sqrt(norm / double(pixelErrors.size()));
  const std::size_t rank =
      static_cast<std::size_t>(std::ceil(0.99 * double(pixelErrors.size()))) - 1;
  std::nth_element(pixelErrors.begin(), pixelErrors.begin() + static_cast<std::ptrdiff_t>(rank),
                   pixelErrors.end());
  e.percentile99 = pixelErrors[rank] / rms;
  return e;
}
} // namespace aniso
