#include "bench/bench_models.h"

#include "bench/bench_scenes.h"
#include "core/reference/reference_image.h"
#include "bench/render_session.h"
#include "core/env/cubemap.h"
#include "core/env/parallel.h"
#include "core/error.h"
#include "core/leadr/leadr.h"
#include "core/microstructure/microstructure.h"
#include "core/models/models.h"
#include "core/models/samples.h"
#include "vtkpasses/mesh/BuiltinMeshes.h"
#include "vtkpasses/render/LeadrMaterial.h"
#include "vtkpasses/render/LitModelMaterial.h"
#include "vtkpasses/render/MicrostructureMaterial.h"
#include "vtkpasses/render/SurfaceModelSettings.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <glm/geometric.hpp>
#include <memory>
#include <sstream>
#include <vtkPolyData.h>

namespace aniso::bench
{
namespace
{
constexpr double kPi = 3.14159265358979323846;
constexpr int kCubeSize = 256; // the cube-size parameter's default, as the environment set
// Microstructure depth in tile widths: faces of pyramids and grooves rise at atan(2 depth).
constexpr double kMicroDepth = 0.4;
// The baseline frame: the interactive setting of the environment model on a mid-sharp lobe.
const AsLobe kBaselineLobe{1000.0, 100.0};
const glm::dvec3 kF0{0.913, 0.922, 0.924};

const LitModel kLitModels[] = {LitModel::AshikhminShirley, LitModel::Banks, LitModel::BlinnPhong,
                               LitModel::Ward, LitModel::HeidrichSeidel};

// Key, fill, rim and top: directional and point lights in front of the objects (the views look
// from -Y), the first n of them for n lights.
std::vector<Light> benchLights(int count)
{
  const std::vector<Light> all{parseLight("dir:-1,-2,1.5:1,0.95,0.9"),
                               parseLight("point:1.5,-2,1.5:4"), parseLight("dir:1.5,-1,0.4:0.6"),
                               parseLight("point:-1.5,-1,2.5:3,3,3.3")};
  return std::vector<Light>(all.begin(), all.begin() + std::min<std::ptrdiff_t>(count, 4));
}

std::string lightsText(const std::vector<Light>& lights)
{
  int points = 0;
  for (const Light& l : lights)
  {
    points += l.type == LightType::Point ? 1 : 0;
  }
  const int directional = int(lights.size()) - points;
  return std::to_string(directional) + " dir + " + std::to_string(points) + " point";
}

// The pixels of SELECTED (from selectPixels: their 3x3 neighbourhoods are covered) whose
// neighbours' normals lie within 10 degrees of their own. At a crease, as at a silhouette, the
// rasteriser and the ray caster may put a pixel centre on different sides of the edge, and a
// sharp highlight turns that into an error of the whole pixel that says nothing of the model.
std::vector<int> awayFromCreases(const std::vector<PixelSample>& geometry, int width,
                                 const std::vector<int>& selected)
{
  const double minCosine = std::cos(10.0 * kPi / 180.0);
  std::vector<int> kept;
  for (int i : selected)
  {
    const glm::dvec3 n = geometry[std::size_t(i)].normal;
    bool smooth = true;
    for (int dy = -1; dy <= 1 && smooth; ++dy)
    {
      for (int dx = -1; dx <= 1 && smooth; ++dx)
      {
        smooth = glm::dot(geometry[std::size_t(i + dy * width + dx)].normal, n) >= minCosine;
      }
    }
    if (smooth)
    {
      kept.push_back(i);
    }
  }
  return kept;
}

// The plate seen from the -Y side at `elevation` degrees by a parallel camera whose view holds
// only plate: every pixel covered, every footprint the same size in texture space.
CameraPlacement plateCamera(double elevationDegrees)
{
  const double e = elevationDegrees * kPi / 180.0;
  CameraPlacement c;
  c.position = glm::dvec3(0.0, -4.0 * std::cos(e), 4.0 * std::sin(e));
  c.viewUp = glm::dvec3(0.0, 0.0, 1.0);
  c.parallel = true;
  c.parallelScale = 0.8 * std::sin(e);
  return c;
}

// The built-in plate maps (x, y) in [-1, 1]^2 to u = (x + 1) / 2, v = (y + 1) / 2.
glm::dvec2 plateUv(const glm::dvec3& p)
{
  return {(p.x + 1.0) / 2.0, (p.y + 1.0) / 2.0};
}

struct Measured
{
  Image image;
  std::vector<FrameTime> first;
  std::vector<FrameTime> timed;
};

// One frame to read (the first after the material change: compiles and uploads), then RUNS
// timed frames.
Measured renderAndTime(RenderSession& session, int runs)
{
  Measured m;
  m.first = session.render(1);
  m.image = session.read();
  m.timed = session.renderMore(runs);
  return m;
}

// A reference image from per-pixel values computed on all hardware threads: value(pixel,
// false). With WITHBOUND, value(pixel, true) is a coarser evaluation of the same quantity (half
// the resolution of its quadrature), and the relative L2 between the two, the coarser one's
// error estimated as if the finer one were exact, stands as the reference's own error bound.
ReferenceImage referenceOf(const RenderSession& session, const std::vector<int>& pixels,
                           const std::function<glm::dvec3(int pixel, bool coarse)>& value,
                           bool withBound)
{
  const auto start = std::chrono::steady_clock::now();
  ReferenceImage reference;
  reference.width = session.width();
  reference.height = session.height();
  reference.pixels.resize(pixels.size());
  std::vector<glm::dvec3> coarse(withBound ? pixels.size() : 0);
  parallelFor(int(pixels.size()),
              [&](int i)
              {
                ReferencePixel& p = reference.pixels[std::size_t(i)];
                p.x = pixels[std::size_t(i)] % session.width();
                p.y = pixels[std::size_t(i)] / session.width();
                p.value = value(pixels[std::size_t(i)], false);
                if (withBound)
                {
                  coarse[std::size_t(i)] = value(pixels[std::size_t(i)], true);
                }
              });
  if (withBound)
  {
    double difference = 0.0;
    double norm = 0.0;
    for (std::size_t i = 0; i < coarse.size(); ++i)
    {
      const glm::dvec3 d = coarse[i] - reference.pixels[i].value;
      difference += glm::dot(d, d);
      norm += glm::dot(reference.pixels[i].value, reference.pixels[i].value);
    }
    reference.relativeErrorBound = norm > 0.0 ? std::sqrt(difference / norm) : 0.0;
  }
  reference.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return reference;
}

// The built-in relief of the LEADR model (SurfaceModelSettings.h): close to the Gaussian slopes
// LEADR assumes, with detail at every scale down to a sixth of a tile.
LeadrMips bumpyMoments()
{
  return bakeLeadrFromHeight(builtinLeadrRelief(), 1.0);
}

struct MicroVariant
{
  std::string name;
  MicroMasking masking;
  bool shadowing;
};

std::string patternName(MicroPattern p)
{
  switch (p)
  {
  case MicroPattern::Pyramids:
    return "pyramids";
  case MicroPattern::InvertedPyramids:
    return "inverted pyramids";
  case MicroPattern::Grooves:
    return "grooves";
  case MicroPattern::Silk:
    return "silk";
  }
  return "structure";
}

class ModelRunner
{
public:
  ModelRunner(const ModelBenchOptions& options, std::ostream& log, std::vector<BenchRow>& rows)
      : options_(options), log_(log), rows_(rows), studio_(openEnvironment("builtin:studio"))
  {
  }

  void runLit(const std::string& meshName)
  {
    const int size = options_.size;
    RenderSession session(size, size);
    const BenchMesh mesh = makeBenchMesh(meshName);
    session.setSurface(mesh.surface, mesh.view);
    session.setEnvironment(studio_, kCubeSize);
    const std::vector<PixelSample> geometry =
        castPixels(mesh.triangles, session.clipToWorld(), size, size);
    const BenchRow base = baseline(session, geometry, meshName);
    renderer_ = session.rendererName();
    // Every pixel away from the silhouette and the creases: the CPU model costs microseconds
    // per pixel.
    const std::vector<int> pixels =
        awayFromCreases(geometry, size, selectPixels(geometry, size, size, size * size));
    const SvTexel texel = brushedMetal(BrushDirection::Latitudinal);
    const auto maps = std::make_shared<const SvMaps>(uniformSvMaps(texel));
    const std::vector<int> lightCounts =
        options_.quick ? std::vector<int>{2} : std::vector<int>{1, 2, 4};
    for (int count : lightCounts)
    {
      const std::vector<Light> lights = benchLights(count);
      for (LitModel model : kLitModels)
      {
        const ReferenceImage reference = referenceOf(
            session, pixels,
            [&](int i, bool)
            {
              const PixelSample& g = geometry[std::size_t(i)];
              const Frame frame = svShadingFrame(g.normal, g.tangent, texel);
              return shadeLitModel(model, texel, frame, g.position, g.view, lights);
            },
            false);
        LitModelSettings lit;
        lit.model = model;
        lit.lights = lights;
        lit.maps = maps;
        BenchRow row = base;
        row.kind = "lit";
        row.model = std::string(litModelName(model));
        row.method = row.model;
        row.environment = "none";
        row.variant = lightsText(lights);
        row.lights = count;
        row.samples = count;
        measure(row, session, reference, litModelInstaller(lit), runsFor(5));
      }
    }
  }

  // LEADR and the microstructure share the plate, its session and its baseline.
  void runPlate()
  {
    const int size = std::max(16, options_.size / 2);
    RenderSession session(size, size);
    vtkSmartPointer<vtkPolyData> plate = makePlate(1);
    const CameraPlacement camera = plateCamera(50.0);
    session.setSurface(plate, camera);
    session.setEnvironment(studio_, kCubeSize);
    const std::vector<PixelSample> geometry =
        castPixels(triangleMesh(plate), session.clipToWorld(), size, size);
    const BenchRow base = baseline(session, geometry, "plate");
    renderer_ = session.rendererName();
    // Texture space per pixel: the parallel view makes it the same everywhere.
    const glm::dvec2 pixelUv =
        plateUv(geometry[std::size_t(size / 2) * size + size / 2 + 1].position) -
        plateUv(geometry[std::size_t(size / 2) * size + size / 2].position);
    const double pixelWidth = glm::length(pixelUv);
    if (options_.leadr)
    {
      runLeadr(session, geometry, base, pixelWidth);
    }
    if (options_.microstructure)
    {
      runMicrostructure(session, geometry, base, pixelWidth);
    }
  }

private:
  // Pixel (x, y) + (a, b) of the plate, a, b in [-1/2, 1/2]: positions are affine in the pixel
  // coordinates under a parallel projection onto a plane.
  struct PlatePixel
  {
    glm::dvec3 position;
    glm::dvec3 view;
    glm::dvec3 stepX; // to the next pixel right
    glm::dvec3 stepY; // to the next pixel up (the row above)
  };

  static PlatePixel platePixel(const std::vector<PixelSample>& geometry, int width, int index)
  {
    const PixelSample& g = geometry[std::size_t(index)];
    PlatePixel p;
    p.position = g.position;
    p.view = g.view;
    p.stepX = geometry[std::size_t(index) + 1].position - g.position;
    p.stepY = geometry[std::size_t(index) - std::size_t(width)].position - g.position;
    return p;
  }

  void runLeadr(RenderSession& session, const std::vector<PixelSample>& geometry,
                const BenchRow& base, double pixelWidth)
  {
    const int size = session.width();
    const auto mips = std::make_shared<const LeadrMips>(bumpyMoments());
    const int texels = mips->levels.front().width;
    LeadrMaterial surface;
    surface.diffuse = glm::dvec3(0.05);
    surface.f0 = glm::dvec3(0.9);
    surface.baseAlphaX = surface.baseAlphaY = 0.1;
    Light sun;
    // 25 degrees off the mirror direction of the view about the flat plate: outside the base
    // lobe, inside the spread of the bumps' normals.
    sun.vector = glm::normalize(glm::dvec3(0.423, 0.583, 0.694));
    sun.intensity = glm::dvec3(1.0);
    const std::vector<Light> lights{sun};
    const Sh9 sh = projectSh9(*studio_, 128);
    const Frame frame; // the plate: t = +X, b = +Y, n = +Z
    const std::vector<int> pixels = selectPixels(geometry, size, size, options_.quick ? 64 : 256);
    const std::vector<double> distances =
        options_.quick ? std::vector<double>{16.0} : std::vector<double>{1.0, 4.0, 16.0, 64.0};
    const std::vector<int> grids =
        options_.quick ? std::vector<int>{1, 4} : std::vector<int>{1, 2, 4, 8};
    for (double texelsPerPixel : distances)
    {
      const double tiles = texelsPerPixel / (texels * pixelWidth);
      // The reference: each pixel's fine-level shading (the base lobe around each fine slope)
      // averaged over a sub x sub grid of its footprint, at least 8 points per period of the
      // relief's finest wave (a sixth of a tile) along the longer footprint axis; every
      // point's lobe integrated on an 8 x 8 slope grid reading the environment itself.
      const SlopeGrid fineGrid = makeSlopeGrid(8);
      const SlopeGrid coarseGrid = makeSlopeGrid(4);
      const double longAxis = texelsPerPixel / std::sin(50.0 * kPi / 180.0);
      const int sub = std::clamp(int(std::ceil(longAxis * 8.0 / (texels / 6.0))), 8, 96);
      const ReferenceImage reference = referenceOf(
          session, pixels,
          [&](int i, bool coarse)
          {
            const PlatePixel p = platePixel(geometry, size, i);
            glm::dvec3 sum(0.0);
            const int points = coarse ? std::max(2, sub / 2) : sub;
            const SlopeGrid& lobeGrid = coarse ? coarseGrid : fineGrid;
            for (int j = 0; j < points; ++j)
            {
              for (int k = 0; k < points; ++k)
              {
                const glm::dvec3 at = p.position + ((k + 0.5) / points - 0.5) * p.stepX +
                                      ((j + 0.5) / points - 0.5) * p.stepY;
                const SlopeStatistics fine =
                    slopeStatistics(sampleLeadr(*mips, plateUv(at) * tiles, 0.0),
                                    surface.baseAlphaX, surface.baseAlphaY);
                sum +=
                    shadeLeadr(surface, fine, frame, at, p.view, lights, lobeGrid) +
                    leadrEnvironmentSpecular(fine, surface.f0, frame, p.view, *studio_, lobeGrid) +
                    leadrEnvironmentDiffuse(fine, surface.diffuse, frame, sh, lobeGrid);
              }
            }
            return sum / double(points * points);
          },
          true);
      double level = 0.0;
      for (int i : pixels)
      {
        const PlatePixel p = platePixel(geometry, size, i);
        level += leadrLevelOfFootprint(*mips, tiles, glm::dvec2(p.stepX) / 2.0,
                                       glm::dvec2(p.stepY) / 2.0);
      }
      level /= double(pixels.size());
      log_ << "  reference plate LEADR " << texelsPerPixel << " texels per pixel (level " << level
           << "): " << pixels.size() << " pixels, " << sub << "^2 points each, bound "
           << reference.relativeErrorBound << ", " << reference.seconds << " s" << std::endl;
      for (int n : grids)
      {
        for (bool plain : {false, true})
        {
          if (plain && options_.quick && n != 4)
          {
            continue;
          }
          LeadrSettings leadr;
          leadr.moments = mips;
          leadr.surface = surface;
          leadr.tiles = tiles;
          leadr.gridN = n;
          leadr.environment = true;
          leadr.plainNormals = plain;
          leadr.lights = lights;
          BenchRow row = base;
          row.kind = "leadr";
          row.model = plain ? "normal-map" : "leadr";
          row.method = row.model;
          row.variant = std::to_string(int(texelsPerPixel)) +
                        (texelsPerPixel == 1.0 ? " texel per pixel" : " texels per pixel");
          row.lights = 1;
          row.grid = n;
          row.samples = n * n;
          row.mipLevel = level;
          measure(row, session, reference, LeadrShadingMaterial::installer(leadr), runsFor(3));
        }
      }
    }
  }

  void runMicrostructure(RenderSession& session, const std::vector<PixelSample>& geometry,
                         const BenchRow& base, double pixelWidth)
  {
    const int size = session.width();
    // A low sun (27 degrees above the plate) from the side, below the structures' 39-degree
    // faces, and across the grooves (which run along y), so the self-shadowing has something to
    // do.
    Light sun;
    sun.vector = glm::normalize(glm::dvec3(-0.8, 0.35, 0.45));
    sun.intensity = glm::dvec3(2.0);
    Light lamp;
    lamp.type = LightType::Point;
    lamp.vector = glm::dvec3(0.6, -0.8, 1.0);
    lamp.intensity = glm::dvec3(0.8, 1.0, 1.2);
    const std::vector<Light> lights{sun, lamp};
    // About three tiles of structure across a pixel, so the grid decides what the pixel
    // averages; not a simple fraction, so no grid samples the same phases of every tile.
    const double tiles = 2.77 / pixelWidth;
    const Frame frame;
    const std::vector<int> pixels = selectPixels(geometry, size, size, options_.quick ? 64 : 400);
    const int referenceK = options_.quick ? 32 : 64;
    const std::vector<MicroPattern> patterns =
        options_.quick
            ? std::vector<MicroPattern>{MicroPattern::Pyramids}
            : std::vector<MicroPattern>{MicroPattern::Pyramids, MicroPattern::InvertedPyramids,
                                        MicroPattern::Grooves, MicroPattern::Silk};
    std::vector<MicroVariant> variants{{"POM, shadows", MicroMasking::ParallaxOcclusion, true}};
    if (!options_.quick)
    {
      variants = {{"normal", MicroMasking::Normal, false},
                  {"parallax", MicroMasking::Parallax, false},
                  {"POM", MicroMasking::ParallaxOcclusion, false},
                  {"POM, shadows", MicroMasking::ParallaxOcclusion, true}};
    }
    for (MicroPattern pattern : patterns)
    {
      const auto structure =
          std::make_shared<const Microstructure>(makeMicrostructure(pattern, 64, kMicroDepth));
      for (const MicroVariant& variant : variants)
      {
        MicroShadingOptions shading;
        shading.masking = variant.masking;
        shading.selfShadowing = variant.shadowing;
        shading.roughness = 0.2;
        shading.f0 = glm::dvec3(0.5);
        MicroShadingOptions converged = shading;
        converged.samplesPerAxis = referenceK;
        MicroShadingOptions halfGrid = shading;
        halfGrid.samplesPerAxis = referenceK / 2;
        const ReferenceImage reference = referenceOf(
            session, pixels,
            [&](int i, bool coarse)
            {
              const PlatePixel p = platePixel(geometry, size, i);
              PixelFootprint footprint;
              footprint.centre = plateUv(p.position) * tiles;
              footprint.axisU = glm::dvec2(p.stepX) / 2.0 * tiles;
              footprint.axisV = glm::dvec2(p.stepY) / 2.0 * tiles;
              return shadeMicroPixel(*structure, coarse ? halfGrid : converged, footprint, frame,
                                     p.position, p.view, lights);
            },
            true);
        const std::string name = patternName(pattern) + ", " + variant.name;
        log_ << "  reference plate microstructure " << name << ": " << pixels.size()
             << " pixels, K = " << referenceK << ", bound " << reference.relativeErrorBound << ", "
             << reference.seconds << " s" << std::endl;
        for (bool jittered : {false, true})
        {
          for (int k : {1, 2, 4, 8})
          {
            if (jittered && options_.quick && k != 4)
            {
              continue;
            }
            MicrostructureSettings settings;
            settings.structure = structure;
            settings.options = shading;
            settings.options.samplesPerAxis = k;
            settings.options.jittered = jittered;
            settings.tiles = tiles;
            settings.lights = lights;
            BenchRow row = base;
            row.kind = "micro";
            row.model = "microstructure";
            row.method = jittered ? "jittered" : "full-grid";
            row.environment = "none";
            row.variant = name;
            row.lights = int(lights.size());
            row.grid = k;
            row.samples = k * k;
            measure(row, session, reference, MicrostructureShadingMaterial::installer(settings),
                    runsFor(k >= 4 ? 2 : 3));
          }
        }
      }
    }
  }

  // The environment frame (exact, filtered, LUT, 16 samples) on the session's scene, against
  // the reference integrator (few pixels, cached): the time the models' rows are divided by.
  BenchRow baseline(RenderSession& session, const std::vector<PixelSample>& geometry,
                    const std::string& mesh)
  {
    BenchRow row;
    row.kind = "baseline";
    row.mesh = mesh;
    row.environment = "builtin:studio";
    row.lobe = kBaselineLobe;
    row.width = session.width();
    row.height = session.height();
    row.method = "exact";
    row.filtered = "on";
    row.halfVectors = "lut";
    row.samples = 16;
    ReferenceModel model;
    model.asLobe = kBaselineLobe;
    model.f0 = kF0;
    ReferenceOptions referenceOptions;
    referenceOptions.relativeTolerance = 2e-3;
    const ReferenceImage reference = computeReference(
        geometry, session.width(), session.height(),
        selectPixels(geometry, session.width(), session.height(), options_.quick ? 64 : 256), model,
        *studio_, referenceOptions, options_.cacheDirectory);
    session.useMaterial(baselineMaterial());
    record(row, session, reference, 9);
    rows_.back().baselineFrameSeconds = rows_.back().medianFrameSeconds;
    rows_.back().baselineFrameCpuSeconds = rows_.back().medianFrameCpuSeconds;
    return rows_.back();
  }

  static MaterialSettings baselineMaterial()
  {
    MaterialSettings material; // exact, filtered, LUT, 16 samples: the interactive setting
    material.lobe = kBaselineLobe;
    material.f0 = kF0;
    material.albedo = glm::dvec3(0.0);
    return material;
  }

  // Times the environment frame, then renders with INSTALLER's material and records the row
  // with that frame as its baseline: neighbours in time, so a load that changes during the run
  // moves both.
  void measure(BenchRow row, RenderSession& session, const ReferenceImage& reference,
               const MaterialInstaller& installer, int runs)
  {
    session.useMaterial(baselineMaterial());
    session.render(1);
    const FrameTime baseline = medianFrameTime(session.renderMore(3));
    row.baselineFrameSeconds = baseline.wall;
    row.baselineFrameCpuSeconds = baseline.cpu;
    session.useInstalled(installer);
    record(row, session, reference, runs);
  }

  // Timed frames of a configuration: fewer in the quick set.
  int runsFor(int runs) const { return options_.quick ? 2 : runs; }

  // Renders with the session's current material, timing RUNS frames, compares with REFERENCE
  // and appends the row.
  void record(BenchRow row, RenderSession& session, const ReferenceImage& reference, int runs)
  {
    const Measured m = renderAndTime(session, runs);
    const ImageError error = compareToReference(m.image, reference);
    if (error.nonFinite > 0)
    {
      log_ << "  warning: " << error.nonFinite << " compared pixels are not finite" << std::endl;
    }
    row.relativeL2 = error.relativeL2;
    row.percentile99 = error.percentile99;
    row.referenceBound = reference.relativeErrorBound;
    row.comparedPixels = int(reference.pixels.size());
    row.coveredPixels = coveredPixels(m.image);
    row.runs = int(m.timed.size());
    row.firstFrameSeconds = m.first.front().wall;
    const FrameTime median = medianFrameTime(m.timed);
    row.medianFrameSeconds = median.wall;
    row.totalSeconds = median.wall;
    row.medianFrameCpuSeconds = median.cpu;
    row.totalCpuSeconds = median.cpu;
    row.samplesPerSecond = double(row.coveredPixels) * row.samples / median.wall;
    log_ << "  " << row.mesh << " " << row.model << (row.variant.empty() ? "" : " " + row.variant)
         << (row.grid > 0 ? " grid " + std::to_string(row.grid) : std::string()) << " "
         << row.method << ": " << median.wall * 1e3 << " ms";
    if (row.baselineFrameSeconds > 0.0)
    {
      log_ << " (" << median.wall / row.baselineFrameSeconds << "x the environment frame)";
    }
    log_ << ", L2 " << row.relativeL2 << ", p99 " << row.percentile99 << std::endl;
    rows_.push_back(row);
  }

public:
  const std::string& renderer() const { return renderer_; }

private:
  const ModelBenchOptions& options_;
  std::ostream& log_;
  std::vector<BenchRow>& rows_;
  std::shared_ptr<const Environment> studio_;
  std::string renderer_;
};
} // namespace

std::string runModelBenches(const ModelBenchOptions& options, std::ostream& log,
                            std::vector<BenchRow>& rows)
{
  ModelRunner runner(options, log, rows);
  if (options.lit)
  {
    for (const char* mesh : {"sphere", "flange"})
    {
      log << "scene " << mesh << ": the lit models" << std::endl;
      runner.runLit(mesh);
      if (options.quick)
      {
        break; // the sphere alone in the quick set
      }
    }
  }
  if (options.leadr || options.microstructure)
  {
    log << "scene plate: " << (options.leadr ? "LEADR" : "")
        << (options.leadr && options.microstructure ? " and " : "")
        << (options.microstructure ? "microstructure" : "") << std::endl;
    runner.runPlate();
  }
  return runner.renderer();
}
} // namespace aniso::bench
