#include "vtkpasses/render/vtkAnisoAccumulationPass.h"

#include "aniso_shaders.h"
#include "core/quality/error_estimate.h"
#include "core/sampling/hammersley.h"
#include "vtkpasses/render/EnvironmentLighting.h"
#include "vtkpasses/render/RendererMatrices.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>
#include <limits>
#include <utility>
#include <vector>
#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCameraPass.h>
#include <vtkCommand.h>
#include <vtkDataObject.h>
#include <vtkInformation.h>
#include <vtkInformationDoubleVectorKey.h>
#include <vtkInformationIntegerKey.h>
#include <vtkInformationObjectBaseKey.h>
#include <vtkMapper.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLQuadHelper.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLShaderCache.h>
#include <vtkOpenGLState.h>
#include <vtkPointSet.h>
#include <vtkPoints.h>
#include <vtkProp.h>
#include <vtkProperty.h>
#include <vtkRenderState.h>
#include <vtkRenderStepsPass.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkShaderProgram.h>
#include <vtkShaderProperty.h>
#include <vtkTextureObject.h>
#include <vtk_glew.h>

vtkStandardNewMacro(vtkAnisoAccumulationPass);
vtkCxxSetObjectMacro(vtkAnisoAccumulationPass, DelegatePass, vtkRenderPass);
vtkInformationKeyRestrictedMacro(vtkAnisoAccumulationPass, FRAME_SHIFT, DoubleVector, 2);
vtkInformationKeyMacro(vtkAnisoAccumulationPass, FRAME_INDEX, Integer);

int vtkAnisoAccumulationPass::GetFrameIndex(vtkRenderer* renderer)
{
  vtkInformation* info = renderer ? renderer->GetInformation() : nullptr;
  return info && info->Has(FRAME_INDEX()) ? std::max(info->Get(FRAME_INDEX()), 0) : 0;
}
vtkInformationKeyMacro(vtkAnisoAccumulationPass, FROZEN_PIXELS, ObjectBase);

namespace
{
// How much of the visible surfaces' geometry each GL row holds: the points of the visible
// actors' inputs (at most about kDensityPoints of them, evenly strided) projected by CLIP, counted
// per row. A render of many triangles costs about in proportion to them per row.
constexpr vtkIdType kDensityPoints = 65536;

std::vector<double> rowDensity(const vtkRenderState* s, const glm::dmat4& clip, int height)
{
  std::vector<double> density(std::size_t(height), 0.0);
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    auto* actor = vtkActor::SafeDownCast(s->GetPropArray()[i]);
    vtkMapper* mapper = actor && actor->GetVisibility() ? actor->GetMapper() : nullptr;
    auto* input = mapper ? vtkPointSet::SafeDownCast(mapper->GetInputDataObject(0, 0)) : nullptr;
    vtkPoints* points = input ? input->GetPoints() : nullptr;
    if (!points || points->GetNumberOfPoints() == 0)
    {
      continue;
    }
    glm::dmat4 model(1.0);
    vtkMatrix4x4* matrix = actor->GetMatrix();
    for (int r = 0; r < 4; ++r)
    {
      for (int c = 0; c < 4; ++c)
      {
        model[c][r] = matrix->GetElement(r, c);
      }
    }
    const glm::dmat4 toClip = clip * model;
    const vtkIdType n = points->GetNumberOfPoints();
    const vtkIdType stride = std::max<vtkIdType>(1, n / kDensityPoints);
    for (vtkIdType id = 0; id < n; id += stride)
    {
      double p[3];
      points->GetPoint(id, p);
      const glm::dvec4 q = toClip * glm::dvec4(p[0], p[1], p[2], 1.0);
      if (!(q.w > 0.0) || std::abs(q.x) > q.w || std::abs(q.y) > q.w)
      {
        continue;
      }
      const int row = std::min(height - 1, static_cast<int>((0.5 * q.y / q.w + 0.5) * height));
      density[std::size_t(std::max(row, 0))] += 1.0;
    }
  }
  return density;
}
} // namespace

namespace
{
// Radical inverse in base 2 or 3: the sub-pixel jitter follows the Halton sequence, a
// different low-discrepancy sequence from the sample-set shifts (R2), so the two stay
// uncorrelated across frames.
double radicalInverse(int index, int base)
{
  double result = 0.0;
  double scale = 1.0 / base;
  for (int i = index; i > 0; i /= base)
  {
    result += (i % base) * scale;
    scale /= base;
  }
  return result;
}

// The scissor rectangle of a band, set through the window's state (which caches GL state, so
// the camera pass's restore afterwards reaches the GL).
struct BandRows
{
  vtkOpenGLState* state;
  int rect[4];
};

// The props of S that may cover a GL row of [Y0, Y1) of a HEIGHT-row frame under CLIP (world
// to clip space): a prop whose bounding box projects wholly above or below those rows (two rows
// of margin, for the sub-pixel jitter) is left out of the band. A prop without bounds, or whose
// box reaches behind the camera, is kept.
std::vector<vtkProp*> propsInRows(const vtkRenderState* s, const glm::dmat4& clip, int height,
                                  int y0, int y1)
{
  std::vector<vtkProp*> kept;
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = s->GetPropArray()[i];
    const double* b = prop->GetBounds();
    if (!b || !(b[0] <= b[1]) || !(b[2] <= b[3]) || !(b[4] <= b[5]))
    {
      kept.push_back(prop);
      continue;
    }
    double low = std::numeric_limits<double>::infinity();
    double high = -low;
    bool behind = false;
    for (int corner = 0; corner < 8 && !behind; ++corner)
    {
      const glm::dvec4 p = clip * glm::dvec4(b[corner & 1], b[2 + ((corner >> 1) & 1)],
                                             b[4 + ((corner >> 2) & 1)], 1.0);
      behind = !(p.w > 0.0);
      const double row = (0.5 * p.y / p.w + 0.5) * height;
      if (!std::isfinite(row))
      {
        low = high = row; // unknown: kept
        break;
      }
      low = std::min(low, row);
      high = std::max(high, row);
    }
    constexpr double kMargin = 2.0;
    // Rows that do not come out as numbers (a box of 1e30 overflows the projection) keep the
    // prop: only a box known to lie outside the band leaves it out.
    const bool unknown = !std::isfinite(low) || !std::isfinite(high);
    if (behind || unknown || (high + kMargin >= y0 && low - kMargin <= y1))
    {
      kept.push_back(prop);
    }
  }
  return kept;
}

void allocateColor(vtkTextureObject* texture, vtkOpenGLRenderWindow* window, int width, int height)
{
  texture->SetContext(window);
  if (texture->GetHandle() && int(texture->GetWidth()) == width &&
      int(texture->GetHeight()) == height)
  {
    return; // made at this size already
  }
  if (!texture->GetHandle())
  {
    texture->SetInternalFormat(GL_RGBA32F);
    texture->SetFormat(GL_RGBA);
    texture->SetDataType(GL_FLOAT);
    texture->SetMinificationFilter(vtkTextureObject::Nearest);
    texture->SetMagnificationFilter(vtkTextureObject::Nearest);
    texture->SetWrapS(vtkTextureObject::ClampToEdge);
    texture->SetWrapT(vtkTextureObject::ClampToEdge);
    texture->Allocate2D(static_cast<unsigned int>(width), static_cast<unsigned int>(height), 4,
                        VTK_FLOAT);
  }
  else
  {
    texture->Resize(static_cast<unsigned int>(width), static_cast<unsigned int>(height));
  }
}
} // namespace

vtkAnisoAccumulationPass::vtkAnisoAccumulationPass() = default;

vtkAnisoAccumulationPass::~vtkAnisoAccumulationPass()
{
  this->SetDelegatePass(nullptr);
  if (this->FrameBuffer)
  {
    this->FrameBuffer->Delete();
  }
  if (this->AccumulationBuffer)
  {
    this->AccumulationBuffer->Delete();
  }
  for (vtkTextureObject* texture :
       {this->FrameColor, this->FrameDepth, this->AccumulationColor, this->SpareFrameColor,
        this->SpareFrameDepth, this->PreviousColor})
  {
    if (texture)
    {
      texture->Delete();
    }
  }
}

void vtkAnisoAccumulationPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "AccumulatedFrames: " << this->AccumulatedFrames << "\n";
  os << indent << "TargetFrames: " << this->TargetFrames << "\n";
  os << indent << "Jitter: " << this->Jitter << "\n";
  os << indent << "ExposureEV: " << this->Display.exposureEV << "\n";
}

void vtkAnisoAccumulationPass::SetDisplaySettings(const aniso::DisplaySettings& settings)
{
  if (settings != this->Display)
  {
    this->Display = settings;
    this->Modified();
  }
}

void vtkAnisoAccumulationPass::SetLighting(std::shared_ptr<aniso::EnvironmentLighting> lighting)
{
  if (lighting != this->Lighting)
  {
    this->Lighting = std::move(lighting);
    this->Modified();
  }
}

void vtkAnisoAccumulationPass::SetTargetFrames(int frames)
{
  this->TargetFrames = frames > 0 ? frames : 0;
}

void vtkAnisoAccumulationPass::SetFrameBands(int bands)
{
  this->PendingBands = std::max(bands, 1);
}

void vtkAnisoAccumulationPass::SetJitter(bool jitter)
{
  if (jitter != this->Jitter)
  {
    this->Jitter = jitter;
    this->Reset();
  }
}

void vtkAnisoAccumulationPass::SetErrorTarget(double relativeError, int fromFrames)
{
  this->ErrorStopFrames = std::max(fromFrames, 1);
  const double target = std::isfinite(relativeError) && relativeError > 0.0 ? relativeError : 0.0;
  if (target > 0.0 && !(this->ErrorTarget > 0.0))
  {
    this->Reset(); // the frames so far kept no halves
  }
  this->ErrorTarget = target;
  if (!(target > 0.0))
  {
    this->EstimatedError = -1.0;
    this->EstimatedErrorFrames = 0;
  }
}

bool vtkAnisoAccumulationPass::IsConverged() const
{
  if (this->TargetFrames > 0 && this->AccumulatedFrames >= this->TargetFrames)
  {
    return true;
  }
  return this->ErrorTarget > 0.0 && this->AccumulatedFrames >= this->ErrorStopFrames &&
         this->EstimatedErrorFrames == this->AccumulatedFrames &&
         aniso::errorTargetReached(this->EstimatedError, this->ErrorTarget);
}

void vtkAnisoAccumulationPass::Reset()
{
  this->AccumulatedFrames = 0;
  this->Band = 0;
  this->EstimatedError = -1.0;
  this->EstimatedErrorFrames = 0;
  this->SnapshotFrames[0] = this->SnapshotFrames[1] = 0;
  this->Frozen = aniso::FrozenPixels{};
  this->FrozenMaskCurrent = true;
}

void vtkAnisoAccumulationPass::SetPixelFreezing(bool freezing)
{
  if (freezing != this->PixelFreezing)
  {
    this->PixelFreezing = freezing;
    this->Reset();
  }
}

vtkTextureObject* vtkAnisoAccumulationPass::FrozenMaskTexture(vtkOpenGLRenderWindow* window)
{
  if (this->Frozen.count == 0)
  {
    return nullptr;
  }
  if (!this->FrozenMaskCurrent || !this->FrozenMask || this->FrozenMask->GetHandle() == 0 ||
      this->FrozenMask->GetContext() != window)
  {
    // GL's rows from the bottom; 255 reads 1 in the shaders.
    const int w = this->Frozen.width;
    const int h = this->Frozen.height;
    std::vector<unsigned char> rows(std::size_t(w) * h);
    for (int y = 0; y < h; ++y)
    {
      for (int x = 0; x < w; ++x)
      {
        rows[std::size_t(h - 1 - y) * w + x] = this->Frozen.frozen(x, y) ? 255 : 0;
      }
    }
    if (!this->FrozenMask || this->FrozenMask->GetContext() != window)
    {
      this->FrozenMask = vtkSmartPointer<vtkTextureObject>::New();
      this->FrozenMask->SetContext(window);
    }
    this->FrozenMask->SetMinificationFilter(vtkTextureObject::Nearest);
    this->FrozenMask->SetMagnificationFilter(vtkTextureObject::Nearest);
    this->FrozenMask->Create2DFromRaw(static_cast<unsigned int>(w), static_cast<unsigned int>(h), 1,
                                      VTK_UNSIGNED_CHAR, rows.data());
    this->FrozenMaskCurrent = true;
  }
  return this->FrozenMask;
}

vtkAnisoAccumulationPass::Signature
vtkAnisoAccumulationPass::ComputeSignature(const vtkRenderState* s, int width, int height) const
{
  Signature signature;
  std::vector<double>& v = signature.values;
  vtkRenderer* renderer = s->GetRenderer();
  v.push_back(width);
  v.push_back(height);
  const glm::dmat4 clip = aniso::worldToClip(renderer);
  for (int i = 0; i < 16; ++i)
  {
    v.push_back(glm::value_ptr(clip)[i]);
  }
  // The background is part of the mean; exposure and tone mapping are not.
  v.push_back(static_cast<double>(this->Display.background));
  for (int i = 0; i < 3; ++i)
  {
    v.push_back(this->Display.backgroundColor[i]);
  }
  v.push_back(static_cast<double>(reinterpret_cast<std::uintptr_t>(this->Lighting.get())));
  v.push_back(this->Lighting ? static_cast<double>(this->Lighting->revision()) : 0.0);
  v.push_back(this->Jitter ? 1.0 : 0.0);
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = s->GetPropArray()[i];
    v.push_back(static_cast<double>(prop->GetRedrawMTime()));
    v.push_back(prop->GetVisibility());
    if (auto* actor = vtkActor::SafeDownCast(prop))
    {
      v.push_back(static_cast<double>(actor->GetProperty()->GetMTime()));
      v.push_back(static_cast<double>(actor->GetShaderProperty()->GetMTime()));
      if (vtkMapper* mapper = actor->GetMapper())
      {
        v.push_back(static_cast<double>(mapper->GetMTime()));
        if (vtkDataObject* input = mapper->GetInputDataObject(0, 0))
        {
          v.push_back(static_cast<double>(input->GetMTime()));
        }
      }
    }
  }
  return signature;
}

void vtkAnisoAccumulationPass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  vtkRenderer* renderer = s->GetRenderer();
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  if (!this->DelegatePass || !window)
  {
    vtkWarningMacro("vtkAnisoAccumulationPass needs a delegate pass and an OpenGL window.");
    return;
  }
  int x = 0;
  int y = 0;
  int width = 0;
  int height = 0;
  if (s->GetFrameBuffer())
  {
    int size[2];
    s->GetWindowSize(size);
    width = size[0];
    height = size[1];
  }
  else
  {
    renderer->GetTiledSizeAndOrigin(&width, &height, &x, &y);
  }
  if (width <= 0 || height <= 0)
  {
    return;
  }
  this->Stages = StageSeconds();
  this->MarkStage(nullptr);

  if (window != this->LastWindow)
  {
    if (this->LastWindow)
    {
      this->ReleaseGraphicsResources(this->LastWindow);
    }
    this->LastWindow = window;
    this->Reset();
  }
  const bool resized = width != this->Width || height != this->Height;
  if (resized)
  {
    // The mean of the old size stays as the picture under the rows the new size's first frame
    // has not drawn yet (Present): a window switching from a reduced resolution back to its own
    // shows the reduced picture scaled up there, not an empty framebuffer's rows.
    this->PreviousShown = this->AccumulatedFrames > 0 && this->AccumulationColor &&
                          this->AccumulationColor->GetHandle() != 0;
    // The old size's targets become the spare ones, the spare ones (made at the size before, as
    // often as not the new one) the current ones: PrepareTargets resizes only what differs.
    std::swap(this->AccumulationColor, this->PreviousColor);
    std::swap(this->FrameColor, this->SpareFrameColor);
    std::swap(this->FrameDepth, this->SpareFrameDepth);
  }
  // Taken whether or not the size changed: the first taking reads every prop's state (and may
  // make what a prop makes on demand), which must not count as a change at the next band.
  const Signature signature = this->ComputeSignature(s, width, height);
  if (resized || !(signature == this->LastSignature))
  {
    this->Reset();
  }

  // Rows of the mean that hold a whole frame's worth: all of them, except while the first frame
  // is drawn in bands (the rows below the bands drawn hold nothing of this view yet).
  int shownFrom = 0;
  if (!this->IsConverged() || this->AccumulatedFrames == 0)
  {
    const glm::dmat4 clipMatrix = aniso::worldToClip(renderer);
    const std::vector<double> clip(glm::value_ptr(clipMatrix), glm::value_ptr(clipMatrix) + 16);
    if (this->Band == 0)
    {
      this->Bands = std::min(this->PendingBands, height);
      this->PlanBandRows(s, height, clipMatrix, clip);
      this->BandSeconds.assign(std::size_t(this->Bands), 0.0);
    }
    // Band 0 is the top one; GL's rows count from the bottom.
    const int y0 = this->BandEdges[std::size_t(this->Band) + 1];
    const int y1 = this->BandEdges[std::size_t(this->Band)];
    const auto start = std::chrono::steady_clock::now();
    this->PrepareTargets(window, width, height);
    this->MarkStage(&this->Stages.prepare);
    this->RenderFrame(s, window, width, height, y0, y1);
    this->Accumulate(window, width, height, y0, y1);
    this->MarkStage(&this->Stages.accumulate);
    if (this->Bands > 1)
    {
      // What this band cost (the rasteriser may work on its own threads: waited for).
      glFinish();
      this->BandSeconds[std::size_t(this->Band)] =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    if (++this->Band >= this->Bands)
    {
      this->Band = 0;
      ++this->AccumulatedFrames;
      if (this->Bands > 1)
      {
        this->UpdateRowCosts(height, clip);
      }
      this->EstimateError();
    }
    else if (this->AccumulatedFrames == 0)
    {
      shownFrom = y0;
    }
    // Taken after drawing: what the draw itself modified (first shader build, attribute
    // mappings) is the baseline, not a change.
    this->LastSignature = this->ComputeSignature(s, width, height);
  }
  this->NumberOfRenderedProps = this->LastRenderedProps;
  this->MarkStage(&this->Stages.prepare);
  this->Present(window, x, y, width, height, shownFrom);
  this->MarkStage(&this->Stages.present);
}

void vtkAnisoAccumulationPass::MarkStage(double* stage)
{
  if (!this->StageTiming)
  {
    return;
  }
  glFinish();
  const double now =
      std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
  if (stage)
  {
    *stage += now - this->StageMark;
  }
  this->StageMark = now;
}

void vtkAnisoAccumulationPass::PlanBandRows(const vtkRenderState* state, int height,
                                            const glm::dmat4& clipMatrix,
                                            const std::vector<double>& clip)
{
  // Band b spans GL rows [BandEdges[b + 1], BandEdges[b]), from the top down. Each band takes an
  // equal share of the rows' measured cost when it is known for this height and view, else of
  // the rows' share of the geometry (rowDensity).
  const int bands = this->Bands;
  this->BandEdges.assign(std::size_t(bands) + 1, 0);
  this->BandEdges[0] = height;
  if (bands == 1)
  {
    return; // a whole frame (every frame while things move): nothing to weigh
  }
  std::vector<double> weights(std::size_t(height), 1.0);
  const bool measured = static_cast<int>(this->RowCosts.size()) == height &&
                        (this->RowCostsView.empty() || this->RowCostsView == clip);
  if (measured)
  {
    weights = this->RowCosts;
  }
  else
  {
    // Measured in another view (the camera moved) or at another height: what they measured may
    // lie in other rows now. The rows' share of the geometry in this view, over a floor for what
    // every row costs (a quarter of the mean).
    const std::vector<double> density = rowDensity(state, clipMatrix, height);
    double mean = 0.0;
    for (double d : density)
    {
      mean += d / height;
    }
    for (int row = 0; row < height && mean > 0.0; ++row)
    {
      weights[std::size_t(row)] = 0.25 + 0.75 * density[std::size_t(row)] / mean;
    }
  }
  double total = 0.0;
  for (int row = 0; row < height; ++row)
  {
    total += weights[std::size_t(row)];
  }
  double sum = 0.0;
  int row = height; // rows above this one are taken
  for (int b = 1; b < bands; ++b)
  {
    const double share = total * b / bands;
    // Leave at least one row to each band still to come.
    const int lowest = bands - b;
    while (row - 1 >= lowest && sum < share)
    {
      --row;
      sum += weights[std::size_t(row)];
    }
    // At least one row for this band.
    if (row >= this->BandEdges[std::size_t(b) - 1])
    {
      row = this->BandEdges[std::size_t(b) - 1] - 1;
      sum += weights[std::size_t(row)];
    }
    this->BandEdges[std::size_t(b)] = row;
  }
  this->BandEdges[std::size_t(bands)] = 0;
}

void vtkAnisoAccumulationPass::UpdateRowCosts(int height, const std::vector<double>& clip)
{
  // Each band's time spread over its rows; averaged with what the rows cost before (at this
  // height, in this run), so one disturbed band moves the cut by half its error. A run's first
  // frame replaces them: what earlier runs measured was another view or another shading.
  const bool before = static_cast<int>(this->RowCosts.size()) == height &&
                      this->AccumulatedFrames > 1 &&
                      (this->RowCostsView.empty() || this->RowCostsView == clip);
  this->RowCostsView = clip;
  if (!before)
  {
    this->RowCosts.assign(std::size_t(height), 0.0);
  }
  for (int b = 0; b < this->Bands; ++b)
  {
    const int top = this->BandEdges[std::size_t(b)];
    const int bottom = this->BandEdges[std::size_t(b) + 1];
    const double perRow = this->BandSeconds[std::size_t(b)] / std::max(top - bottom, 1);
    for (int row = bottom; row < top; ++row)
    {
      double& cost = this->RowCosts[std::size_t(row)];
      cost = before ? 0.5 * (cost + perRow) : perRow;
    }
  }
}

void vtkAnisoAccumulationPass::SetRowCosts(const std::vector<double>& costs)
{
  this->RowCosts = costs;
  this->RowCostsView.clear();
}

void vtkAnisoAccumulationPass::PrepareTargets(vtkOpenGLRenderWindow* window, int width, int height)
{
  if (!this->FrameColor)
  {
    this->FrameColor = vtkTextureObject::New();
    this->FrameDepth = vtkTextureObject::New();
  }
  if (!this->AccumulationColor)
  {
    this->AccumulationColor = vtkTextureObject::New();
  }
  allocateColor(this->FrameColor, window, width, height);
  allocateColor(this->AccumulationColor, window, width, height);
  this->FrameDepth->SetContext(window);
  if (!this->FrameDepth->GetHandle())
  {
    this->FrameDepth->AllocateDepth(static_cast<unsigned int>(width),
                                    static_cast<unsigned int>(height), vtkTextureObject::Float32);
  }
  else if (int(this->FrameDepth->GetWidth()) != width ||
           int(this->FrameDepth->GetHeight()) != height)
  {
    this->FrameDepth->Resize(static_cast<unsigned int>(width), static_cast<unsigned int>(height));
  }
  if (!this->FrameBuffer)
  {
    this->FrameBuffer = vtkOpenGLFramebufferObject::New();
    this->FrameBuffer->SetContext(window);
    this->AccumulationBuffer = vtkOpenGLFramebufferObject::New();
    this->AccumulationBuffer->SetContext(window);
  }
  this->Width = width;
  this->Height = height;
}

void vtkAnisoAccumulationPass::RenderFrame(const vtkRenderState* s, vtkOpenGLRenderWindow* window,
                                           int width, int height, int y0, int y1)
{
  vtkRenderer* renderer = s->GetRenderer();
  vtkOpenGLState* ostate = window->GetState();
  const int frame = this->AccumulatedFrames;

  vtkCamera* camera = renderer->GetActiveCamera();
  double center[2];
  camera->GetWindowCenter(center);
  if (this->Jitter && frame > 0)
  {
    // A window-centre offset of 2/width moves the image by one pixel.
    const double jx = radicalInverse(frame, 2) - 0.5;
    const double jy = radicalInverse(frame, 3) - 0.5;
    camera->SetWindowCenter(center[0] + 2.0 * jx / width, center[1] + 2.0 * jy / height);
  }
  const glm::dvec2 shift = aniso::frameShift(static_cast<uint32_t>(frame));
  const double shiftValues[2] = {shift.x, shift.y};
  renderer->GetInformation()->Set(FRAME_SHIFT(), shiftValues, 2);
  renderer->GetInformation()->Set(FRAME_INDEX(), frame);
  vtkTextureObject* frozen = this->FrozenMaskTexture(window);
  if (frozen)
  {
    renderer->GetInformation()->Set(FROZEN_PIXELS(), frozen);
  }

  ostate->PushFramebufferBindings();
  this->FrameBuffer->Bind();
  this->FrameBuffer->AddColorAttachment(0, this->FrameColor);
  this->FrameBuffer->ActivateBuffer(0);
  this->FrameBuffer->AddDepthAttachment(this->FrameDepth);
  this->FrameBuffer->StartNonOrtho(width, height);
  {
    vtkOpenGLState::ScopedglViewport viewport(ostate);
    vtkOpenGLState::ScopedglScissor scissor(ostate);
    vtkOpenGLState::ScopedglEnableDisable scissorTest(ostate, GL_SCISSOR_TEST);
    vtkOpenGLState::ScopedglClearColor clearColor(ostate);
    // The band's rows are kept by the scissor, which the window does not always test.
    ostate->vtkglEnable(GL_SCISSOR_TEST);
    ostate->vtkglViewport(0, 0, width, height);
    ostate->vtkglScissor(0, 0, width, height);
    // Only the depth matters: Accumulate reads the frame's colour where a surface drew (depth
    // below the far plane) and puts the background elsewhere. VTK's camera pass clears the depth
    // itself when the renderer and window erase (and the depth is not preserved); a second
    // clear of the whole target would cost as much again.
    if (!this->DelegateClearsDepth(renderer))
    {
      ostate->vtkglClearColor(0.0f, 0.0f, 0.0f, 0.0f);
      ostate->vtkglDepthMask(GL_TRUE);
      ostate->vtkglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    }
    this->MarkStage(&this->Stages.clear);

    // A band draws the props that may reach its rows: of a scene of parts, those above and
    // below it cost nothing (a prop's vertices are processed whatever the scissor keeps).
    const bool partial = y0 > 0 || y1 < height;
    std::vector<vtkProp*> props(s->GetPropArray(), s->GetPropArray() + s->GetPropArrayCount());
    if (partial)
    {
      props = propsInRows(s, aniso::worldToClip(renderer), height, y0, y1);
    }
    vtkRenderState delegateState(renderer);
    delegateState.SetPropArrayAndCount(props.data(), static_cast<int>(props.size()));
    delegateState.SetFrameBuffer(this->FrameBuffer);
    ostate->vtkglEnable(GL_DEPTH_TEST);
    // Part of a frame: the delegate's camera pass sets the scissor to the whole frame, so the
    // band's rows are set again just before each mapper draws (its UpdateShaderEvent): the
    // rasteriser then shades nothing outside them. Outside the band nothing is accumulated
    // either, so a mapper that does not announce its draws costs more but draws the same mean.
    std::vector<std::pair<vtkMapper*, unsigned long>> observed;
    vtkNew<vtkCallbackCommand> bandScissor;
    BandRows band{ostate, {0, y0, width, y1 - y0}};
    if (partial)
    {
      bandScissor->SetClientData(&band);
      bandScissor->SetCallback(
          [](vtkObject*, unsigned long, void* data, void*)
          {
            const auto* b = static_cast<const BandRows*>(data);
            b->state->vtkglScissor(b->rect[0], b->rect[1], b->rect[2], b->rect[3]);
          });
      for (vtkProp* prop : props)
      {
        auto* actor = vtkActor::SafeDownCast(prop);
        if (vtkMapper* mapper = actor ? actor->GetMapper() : nullptr)
        {
          observed.emplace_back(mapper,
                                mapper->AddObserver(vtkCommand::UpdateShaderEvent, bandScissor));
        }
      }
    }
    this->DelegatePass->Render(&delegateState);
    for (const auto& [mapper, tag] : observed)
    {
      mapper->RemoveObserver(tag);
    }
    this->MarkStage(&this->Stages.scene);
    this->BandRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
    // What the frame draws, whichever band this was.
    this->LastRenderedProps =
        partial ? std::max(this->LastRenderedProps, this->DelegatePass->GetNumberOfRenderedProps())
                : this->DelegatePass->GetNumberOfRenderedProps();

    // The view rays of this frame's camera (jittered), for the background in Accumulate.
    this->FrameClipToWorld = aniso::clipToWorld(renderer);
  }
  ostate->PopFramebufferBindings();

  renderer->GetInformation()->Remove(FRAME_SHIFT());
  renderer->GetInformation()->Remove(FRAME_INDEX());
  renderer->GetInformation()->Remove(FROZEN_PIXELS());
  camera->SetWindowCenter(center[0], center[1]);
}

vtkOpenGLQuadHelper* vtkAnisoAccumulationPass::Quad(vtkOpenGLRenderWindow* window,
                                                    std::unique_ptr<vtkOpenGLQuadHelper>& quad,
                                                    const char* fragmentSource,
                                                    const std::string& defines,
                                                    std::string& builtDefines)
{
  if (quad && builtDefines == defines)
  {
    window->GetShaderCache()->ReadyShaderProgram(quad->Program);
  }
  else
  {
    std::string source = fragmentSource;
    vtkShaderProgram::Substitute(source, "//VTK::System::Dec", "//VTK::System::Dec\n" + defines);
    quad = std::make_unique<vtkOpenGLQuadHelper>(window, aniso::shaders::kFullscreenVs,
                                                 source.c_str(), "");
    builtDefines = defines;
  }
  if (!quad->Program || !quad->Program->GetCompiled())
  {
    vtkErrorMacro("A shader of vtkAnisoAccumulationPass failed to compile.");
    return nullptr;
  }
  return quad.get();
}

bool vtkAnisoAccumulationPass::DelegateClearsDepth(vtkRenderer* renderer) const
{
  // Both draw through a vtkCameraPass, which clears when the renderer and its window erase.
  const bool camera = vtkRenderStepsPass::SafeDownCast(this->DelegatePass) != nullptr ||
                      vtkCameraPass::SafeDownCast(this->DelegatePass) != nullptr;
  vtkRenderWindow* window = renderer->GetRenderWindow();
  return camera && renderer->GetErase() && window && window->GetErase() &&
         !renderer->GetPreserveDepthBuffer();
}

void vtkAnisoAccumulationPass::Accumulate(vtkOpenGLRenderWindow* window, int width, int height,
                                          int y0, int y1)
{
  const bool environment =
      this->Display.background == aniso::BackgroundMode::Environment && this->Lighting;
  vtkTextureObject* cube = environment ? this->Lighting->cubeTexture(window) : nullptr;
  vtkTextureObject* frozen = this->FrozenMaskTexture(window);
  std::string defines = cube ? "#define ANISO_BACKGROUND_ENVIRONMENT\n" : "";
  if (frozen)
  {
    defines += "#define ANISO_FROZEN_PIXELS\n";
  }
  vtkOpenGLQuadHelper* quad =
      this->Quad(window, this->AccumulateQuad, aniso::shaders::kAccumulateFs, defines,
                 this->AccumulateDefines);
  if (!quad)
  {
    return;
  }
  vtkOpenGLState* ostate = window->GetState();
  ostate->PushFramebufferBindings();
  this->AccumulationBuffer->Bind();
  this->AccumulationBuffer->AddColorAttachment(0, this->AccumulationColor);
  this->AccumulationBuffer->ActivateBuffer(0);
  this->AccumulationBuffer->RemoveDepthAttachment();
  this->AccumulationBuffer->StartNonOrtho(width, height);
  {
    vtkOpenGLState::ScopedglViewport viewport(ostate);
    vtkOpenGLState::ScopedglScissor scissor(ostate);
    vtkOpenGLState::ScopedglEnableDisable scissorTest(ostate, GL_SCISSOR_TEST);
    vtkOpenGLState::ScopedglEnableDisable depthTest(ostate, GL_DEPTH_TEST);
    vtkOpenGLState::ScopedglEnableDisable blend(ostate, GL_BLEND);
    vtkOpenGLState::ScopedglBlendFuncSeparate blendFunc(ostate);
    ostate->vtkglEnable(GL_SCISSOR_TEST);
    ostate->vtkglViewport(0, 0, width, height);
    ostate->vtkglScissor(0, y0, width, y1 - y0);
    ostate->vtkglDisable(GL_DEPTH_TEST);
    const int frame = this->AccumulatedFrames;
    if (frame == 0)
    {
      ostate->vtkglDisable(GL_BLEND);
    }
    else
    {
      // Running mean: mean_k = mean_{k-1} + (frame - mean_{k-1}) / (k + 1), as a blend.
      ostate->vtkglEnable(GL_BLEND);
      glBlendColor(0.0f, 0.0f, 0.0f, 1.0f / static_cast<float>(frame + 1));
      ostate->vtkglBlendFuncSeparate(GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA,
                                     GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA);
    }
    vtkShaderProgram* program = quad->Program;
    this->FrameColor->Activate();
    program->SetUniformi("frame", this->FrameColor->GetTextureUnit());
    this->FrameDepth->Activate();
    program->SetUniformi("frameDepth", this->FrameDepth->GetTextureUnit());
    program->SetUniformf("quadDepth", 0.0f);
    const bool color = this->Display.background == aniso::BackgroundMode::Color;
    const glm::vec3 radiance = color ? glm::vec3(this->Display.backgroundColor) : glm::vec3(0.0f);
    program->SetUniform3f("backgroundRadiance", glm::value_ptr(radiance));
    if (cube)
    {
      cube->Activate();
      ostate->vtkglEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
      program->SetUniformi("environment", cube->GetTextureUnit());
      aniso::setUniformMatrix(program, "clipToWorld", this->FrameClipToWorld);
      aniso::setUniformMatrix(program, "worldToEnvironment", this->Lighting->worldToEnvironment());
    }
    if (frozen)
    {
      frozen->Activate();
      program->SetUniformi("frozen", frozen->GetTextureUnit());
    }
    quad->Render();
    if (frozen)
    {
      frozen->Deactivate();
    }
    if (cube)
    {
      cube->Deactivate();
    }
    this->FrameDepth->Deactivate();
    this->FrameColor->Deactivate();
  }
  ostate->PopFramebufferBindings();
}

void vtkAnisoAccumulationPass::Present(vtkOpenGLRenderWindow* window, int x, int y, int width,
                                       int height, int y0)
{
  std::string defines = aniso::toneMappingDefines(this->Display);
  if (this->Display.background == aniso::BackgroundMode::Transparent)
  {
    defines += "#define ANISO_TRANSPARENT_BACKGROUND\n";
  }
  std::string source = aniso::shaders::kDisplayFs;
  vtkShaderProgram::Substitute(source, "//ANISO::DisplayTransform::Dec",
                               aniso::shaders::kDisplayTransform);
  vtkOpenGLQuadHelper* quad =
      this->Quad(window, this->DisplayQuad, source.c_str(), defines, this->DisplayDefines);
  if (!quad)
  {
    return;
  }
  vtkOpenGLState* ostate = window->GetState();
  vtkOpenGLState::ScopedglViewport viewport(ostate);
  vtkOpenGLState::ScopedglScissor scissor(ostate);
  vtkOpenGLState::ScopedglEnableDisable scissorTest(ostate, GL_SCISSOR_TEST);
  vtkOpenGLState::ScopedglEnableDisable depthTest(ostate, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable blend(ostate, GL_BLEND);
  ostate->vtkglEnable(GL_SCISSOR_TEST);
  ostate->vtkglViewport(x, y, width, height);
  ostate->vtkglDisable(GL_DEPTH_TEST);
  ostate->vtkglDisable(GL_BLEND);
  vtkShaderProgram* program = quad->Program;
  program->SetUniformf("exposureScale", static_cast<float>(std::exp2(this->Display.exposureEV)));
  program->SetUniformf("quadDepth", 0.0f);
  // Rows [y0, height) from the mean; below, while a new size's first frame is in bands, the
  // previous size's mean stretched over the viewport (the shader reads texels by position in
  // the viewport, so a texture of another size scales).
  const bool previous = y0 > 0 && this->PreviousShown && this->PreviousColor;
  for (int part = previous ? 0 : 1; part < 2; ++part)
  {
    vtkTextureObject* texture = part == 0 ? this->PreviousColor : this->AccumulationColor;
    if (part == 0)
    {
      ostate->vtkglScissor(x, y, width, y0);
    }
    else
    {
      ostate->vtkglScissor(x, y + y0, width, height - y0);
    }
    texture->Activate();
    program->SetUniformi("accumulation", texture->GetTextureUnit());
    quad->Render();
    texture->Deactivate();
  }
  if (y0 == 0)
  {
    this->PreviousShown = false; // a whole frame of this size is on screen
  }
}

aniso::Image vtkAnisoAccumulationPass::ReadAccumulation()
{
  if (!this->LastWindow || !this->AccumulationBuffer || this->AccumulatedFrames == 0)
  {
    return {};
  }
  vtkOpenGLRenderWindow* window = this->LastWindow;
  window->MakeCurrent();
  vtkOpenGLState* ostate = window->GetState();
  aniso::Image image(this->Width, this->Height, 4);
  std::vector<float> rows(image.data.size());
  ostate->PushReadFramebufferBinding();
  this->AccumulationBuffer->Bind(vtkOpenGLFramebufferObject::GetReadMode());
  this->AccumulationBuffer->ActivateReadBuffer(0);
  ostate->vtkglPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, this->Width, this->Height, GL_RGBA, GL_FLOAT, rows.data());
  ostate->PopReadFramebufferBinding();
  const std::size_t rowValues = std::size_t(this->Width) * 4;
  for (int row = 0; row < this->Height; ++row)
  {
    // GL's first row is the bottom one; images start at the top.
    std::copy_n(&rows[std::size_t(this->Height - 1 - row) * rowValues], rowValues,
                &image.data[std::size_t(row) * rowValues]);
  }
  return image;
}

void vtkAnisoAccumulationPass::EstimateError()
{
  const int frames = this->AccumulatedFrames;
  if (!(this->ErrorTarget > 0.0) || !aniso::isErrorSnapshot(frames))
  {
    return;
  }
  aniso::Image mean = this->ReadAccumulation();
  if (mean.empty())
  {
    return;
  }
  if (aniso::isErrorCheckpoint(frames))
  {
    for (int k = 0; k < 2; ++k)
    {
      if (2 * this->SnapshotFrames[k] == frames && this->Snapshots[k].width == mean.width &&
          this->Snapshots[k].height == mean.height)
      {
        this->EstimatedError =
            aniso::estimatedRelativeError(mean, this->Snapshots[k], this->Frozen);
        this->EstimatedErrorFrames = frames;
        if (this->PixelFreezing && frames >= aniso::kFreezeFromFrames &&
            aniso::freezeConvergedPixels(mean, this->Snapshots[k], this->ErrorTarget,
                                         this->Frozen) > 0)
        {
          this->FrozenMaskCurrent = false;
        }
      }
    }
  }
  // The older of the two is no longer half of any later checkpoint.
  const int older = this->SnapshotFrames[0] <= this->SnapshotFrames[1] ? 0 : 1;
  this->Snapshots[older] = std::move(mean);
  this->SnapshotFrames[older] = frames;
}

void vtkAnisoAccumulationPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Superclass::ReleaseGraphicsResources(w);
  if (this->DelegatePass)
  {
    this->DelegatePass->ReleaseGraphicsResources(w);
  }
  for (auto* quad : {&this->AccumulateQuad, &this->DisplayQuad})
  {
    if (*quad)
    {
      (*quad)->ReleaseGraphicsResources(w);
      quad->reset();
    }
  }
  if (this->FrameBuffer)
  {
    this->FrameBuffer->ReleaseGraphicsResources(w);
    this->FrameBuffer->Delete();
    this->FrameBuffer = nullptr;
    this->AccumulationBuffer->ReleaseGraphicsResources(w);
    this->AccumulationBuffer->Delete();
    this->AccumulationBuffer = nullptr;
  }
  for (vtkTextureObject* texture :
       {this->FrameColor, this->FrameDepth, this->AccumulationColor, this->SpareFrameColor,
        this->SpareFrameDepth, this->PreviousColor})
  {
    if (texture)
    {
      texture->ReleaseGraphicsResources(w);
    }
  }
  this->PreviousShown = false;
  if (this->FrozenMask)
  {
    this->FrozenMask->ReleaseGraphicsResources(w);
    this->FrozenMask = nullptr;
  }
  if (this->Lighting)
  {
    this->Lighting->releaseGraphicsResources(w);
  }
  this->Reset();
}
