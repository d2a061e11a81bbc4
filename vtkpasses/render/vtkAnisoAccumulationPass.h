#pragma once
// Progressive refinement and display for the anisotropic materials.
//
// Each Render() draws the delegate (usually a vtkRenderStepsPass) into a float RGBA frame and
// folds the frame into a float running mean, putting the background (environment along the view
// rays, a colour, or nothing) behind the surfaces in the same pass: where the frame's depth is
// still the far plane. Frame k asks the materials for the
// sample-set shift frameShift(k) (through FRAME_SHIFT() on the renderer's information) and,
// with jitter on, moves the camera by a sub-pixel offset so edges converge anti-aliased.
// The mean is then drawn into whatever framebuffer was bound, through the display transform
// (exposure, tone mapping, sRGB). The bound framebuffer is saved and restored; 0 is never
// bound. Any change of camera, props, size or lighting starts the mean over; once the target
// frame count is reached the scene is not drawn again until something changes.
//
// The mean is linear radiance: RGB everything seen (surfaces and background), alpha the
// coverage of the surfaces.
//
// With an error target (SetErrorTarget), the mean is read back at the frame counts of
// core/quality/error_estimate.h (2, 3, 4, 6, 8, 12, ...) and kept on the CPU (the last two), and
// from 4 frames on its relative L2 error is estimated against the mean of its first half: the
// view stops when the estimate is at or below 3/4 of the target (errorTargetReached), or at the
// target frame count, whichever comes first. Without one, nothing is read back.
// With an error target, pixels also stop one by one (SetPixelFreezing, on by default): from
// kFreezeFromFrames on, each checkpoint freezes the fully covered pixels whose neighbourhood's
// estimate is a small share of the target, in tiles (core/quality/error_estimate.h
// freezeConvergedPixels). A frozen pixel's mean is kept as it is (the accumulation discards
// it), and AnisoMaterial, which reads FROZEN_PIXELS, discards its fragments before shading them,
// so later frames cost what the pixels still refining cost; the estimate counts a frozen pixel
// by its error when it froze.
//
// A frame may be drawn in horizontal bands (SetFrameBands), one band per Render(): the surfaces
// and the background are drawn and folded into the mean only within the band's rows (scissor),
// so a costly frame keeps the caller busy for a fraction of its cost at a time. The frame counts
// as accumulated once its last band is drawn; every band of it uses the frame's own shift and
// jitter, so the mean is the same as with whole frames. Bands take equal shares of the rows'
// cost, not of the rows: each band's render is timed (waiting for the GL to finish it), its time
// spread over its rows, and the bands of the next frame (of this view or the next at the same
// height) cut so each costs as much as the others: where the surface is, bands are narrower.
// While the first frame of a new size is in bands, the rows it has not drawn yet show the mean
// of the size before, scaled (a view returning from a reduced resolution shows the reduced
// picture there, not empty rows).
#include "core/image/image.h"
#include "core/quality/error_estimate.h"
#include "vtkpasses/render/DisplaySettings.h"

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <memory>
#include <string>
#include <vector>
#include <vtkRenderPass.h>
#include <vtkSmartPointer.h>
#include <vtkWeakPointer.h>

class vtkInformationDoubleVectorKey;
class vtkInformationIntegerKey;
class vtkInformationObjectBaseKey;
class vtkOpenGLFramebufferObject;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkRenderer;
class vtkTextureObject;

namespace aniso
{
class EnvironmentLighting;
}

class vtkAnisoAccumulationPass : public vtkRenderPass
{
public:
  static vtkAnisoAccumulationPass* New();
  vtkTypeMacro(vtkAnisoAccumulationPass, vtkRenderPass)
  void PrintSelf(ostream& os, vtkIndent indent) override;

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

  // The pass that draws the scene.
  vtkGetObjectMacro(DelegatePass, vtkRenderPass);
  virtual void SetDelegatePass(vtkRenderPass* delegatePass);

  // Shift of the sample set for the frame being drawn (2 doubles), set on the renderer's
  // information during the delegate's render; absent = (0, 0).
  static vtkInformationDoubleVectorKey* FRAME_SHIFT();
  // Index k of that frame (0 for the first after a reset), set alongside FRAME_SHIFT: filtered
  // importance sampling blurs less as the mean gathers more samples.
  static vtkInformationIntegerKey* FRAME_INDEX();
  // FRAME_INDEX on RENDERER's information, 0 where it is not set (no renderer, no pass).
  static int GetFrameIndex(vtkRenderer* renderer);
  // The pixels of this mean that no longer change (an R8 texture of the frame's size, GL rows, 1
  // where frozen), set alongside FRAME_SHIFT while any pixel is frozen: a material may discard
  // their fragments (ivec2(gl_FragCoord.xy) is the texel), and only then does freezing save time.
  static vtkInformationObjectBaseKey* FROZEN_PIXELS();

  void SetDisplaySettings(const aniso::DisplaySettings& settings);
  const aniso::DisplaySettings& GetDisplaySettings() const { return this->Display; }

  // Lighting whose environment is the background (BackgroundMode::Environment).
  void SetLighting(std::shared_ptr<aniso::EnvironmentLighting> lighting);

  // Frames to accumulate before stopping (0: never stop).
  void SetTargetFrames(int frames);
  int GetTargetFrames() const { return this->TargetFrames; }
  // Relative L2 error of the mean at which to stop before the target frame count, by the
  // estimate from the frames themselves (core/quality/error_estimate.h), from FROM_FRAMES frames
  // on (earlier estimates are taken and shown, not trusted to stop); 0: none (the default), the
  // frame count alone. A change keeps the mean; a mean begun without an error target has no
  // halves kept, so setting one then starts it over.
  void SetErrorTarget(double relativeError, int fromFrames = 4);
  double GetErrorTarget() const { return this->ErrorTarget; }
  int GetErrorStopFrames() const { return this->ErrorStopFrames; }
  // The estimate at the latest checkpoint of this mean, and the frames it was taken after;
  // negative (and 0 frames) before the first checkpoint or without an error target.
  double GetEstimatedError() const { return this->EstimatedError; }
  int GetEstimatedErrorFrames() const { return this->EstimatedErrorFrames; }
  // Per-pixel stopping with an error target (the default: on); off, every pixel refines until
  // the view stops. A change starts the mean over.
  void SetPixelFreezing(bool freezing);
  bool GetPixelFreezing() const { return this->PixelFreezing; }
  // The pixels frozen in this mean (none without an error target or freezing).
  const aniso::FrozenPixels& GetFrozenPixels() const { return this->Frozen; }
  // Sub-pixel camera jitter per frame (anti-aliasing, fractional coverage). Off: every frame
  // samples pixel centres, as a per-pixel reference does.
  void SetJitter(bool jitter);
  bool GetJitter() const { return this->Jitter; }

  // Bands per frame (at least 1, at most the rows), top to bottom. A change takes effect when
  // the next frame starts; the frame in progress keeps its bands.
  void SetFrameBands(int bands);
  int GetFrameBands() const { return this->PendingBands; }
  // The band of the current frame the next Render() draws; 0 when it starts a new frame (the
  // last frame is complete).
  int GetNextBand() const { return this->Band; }
  // Bands of the frame in progress (or of the last one drawn).
  int GetCurrentFrameBands() const { return this->Bands; }
  // The props the last band drew: a band of several leaves out the props whose bounding boxes
  // project wholly above or below its rows (they would process their vertices for nothing).
  int GetBandRenderedProps() const { return this->BandRenderedProps; }
  // Their rows: band b spans GL rows [edges[b + 1], edges[b]) (GL counts rows from the bottom).
  const std::vector<int>& GetBandEdges() const { return this->BandEdges; }
  // The cost of each GL row (any unit) by which the next frame's bands are cut, as the bands'
  // times set it; given here, it holds for any view until frames in bands measure it anew (the
  // pass's tests). Measured costs belong to the view they were measured in: a frame of another
  // view (the camera moved), or of a height not measured, is cut by the rows' share of the
  // visible geometry (its points projected) over a floor of a quarter of the mean, as the
  // surface may have moved to rows that cost nothing before. The first frame of a run replaces
  // what earlier runs measured; later frames of the run average with it.
  void SetRowCosts(const std::vector<double>& costs);
  const std::vector<double>& GetRowCosts() const { return this->RowCosts; }

  int GetAccumulatedFrames() const { return this->AccumulatedFrames; }
  bool IsConverged() const;
  // Forget the mean: the next Render() starts over.
  void Reset();

  // The running mean (RGBA, linear, row 0 at the top), read back from the GPU in the window of
  // the last Render(). Empty if nothing was rendered yet.
  aniso::Image ReadAccumulation();

  // Where the last Render() spent its time, stage by stage (seconds of wall time), measured
  // only while SetStageTiming(true): the GL is waited for (glFinish) before and after each
  // stage, so a stage's time is its own work; a driver that overlaps stages loses that overlap
  // while timed, so the timed frame may cost more than an untimed one. Stages the Render() did
  // not run are 0 (a converged view only presents).
  struct StageSeconds
  {
    double prepare = 0.0;    // what changed (the signature), the band's rows, the float targets
    double clear = 0.0;      // clearing the frame's colour and depth
    double scene = 0.0;      // the delegate: VTK's passes drawing the props (geometry, shading)
    double accumulate = 0.0; // folding the frame into the running mean, with the background
    double present = 0.0;    // the display transform into the bound framebuffer
    double total() const
    {
      return prepare + clear + scene + accumulate + present;
    }
  };
  void SetStageTiming(bool timing) { this->StageTiming = timing; }
  bool GetStageTiming() const { return this->StageTiming; }
  const StageSeconds& GetStageSeconds() const { return this->Stages; }

protected:
  vtkAnisoAccumulationPass();
  ~vtkAnisoAccumulationPass() override;

private:
  vtkAnisoAccumulationPass(const vtkAnisoAccumulationPass&) = delete;
  void operator=(const vtkAnisoAccumulationPass&) = delete;

  // What a frame depends on; a difference from the last frame restarts the mean.
  struct Signature
  {
    std::vector<double> values;
    bool operator==(const Signature& o) const { return values == o.values; }
  };
  Signature ComputeSignature(const vtkRenderState* s, int width, int height) const;
  void PrepareTargets(vtkOpenGLRenderWindow* window, int width, int height);
  // BandEdges for this->Bands bands of HEIGHT rows, seen by the camera CLIP (world to clip; its
  // values as a vector, as RowCostsView holds them).
  void PlanBandRows(const vtkRenderState* state, int height, const glm::dmat4& clipMatrix,
                    const std::vector<double>& clip);
  // RowCosts from the bands' times of the frame just completed, seen by the camera CLIP.
  void UpdateRowCosts(int height, const std::vector<double>& clip);
  // Rows [y0, y1) (GL order, 0 at the bottom) of the frame are drawn.
  void RenderFrame(const vtkRenderState* s, vtkOpenGLRenderWindow* window, int width, int height,
                   int y0, int y1);
  // Whether the delegate clears the frame's depth itself (a VTK camera pass of an erasing
  // renderer and window).
  bool DelegateClearsDepth(vtkRenderer* renderer) const;
  // Folds the frame into the mean, with the background where no surface drew.
  void Accumulate(vtkOpenGLRenderWindow* window, int width, int height, int y0, int y1);
  // After a frame: keeps the mean at the error estimate's snapshots and estimates the error at
  // its checkpoints (EstimatedError).
  void EstimateError();
  // The frozen pixels' mask in WINDOW's context, uploaded when it changed; null while none is
  // frozen.
  vtkTextureObject* FrozenMaskTexture(vtkOpenGLRenderWindow* window);
  // Shows rows [y0, height) of the mean (all of it with y0 = 0).
  void Present(vtkOpenGLRenderWindow* window, int x, int y, int width, int height, int y0);
  vtkOpenGLQuadHelper* Quad(vtkOpenGLRenderWindow* window,
                            std::unique_ptr<vtkOpenGLQuadHelper>& quad, const char* fragmentSource,
                            const std::string& defines, std::string& builtDefines);

  vtkRenderPass* DelegatePass = nullptr;
  aniso::DisplaySettings Display;
  std::shared_ptr<aniso::EnvironmentLighting> Lighting;
  int TargetFrames = 0;
  double ErrorTarget = 0.0;
  int ErrorStopFrames = 4;
  double EstimatedError = -1.0;
  int EstimatedErrorFrames = 0;
  aniso::Image Snapshots[2]; // the mean at earlier snapshots, with their frame counts
  int SnapshotFrames[2] = {0, 0};
  bool PixelFreezing = true;
  aniso::FrozenPixels Frozen;                   // of this mean
  vtkSmartPointer<vtkTextureObject> FrozenMask; // Frozen's mask, as FROZEN_PIXELS gives it
  bool FrozenMaskCurrent = true;                // the texture holds Frozen's mask
  bool Jitter = true;
  int AccumulatedFrames = 0;
  int PendingBands = 1;
  int Bands = 1;                    // of the frame in progress
  int Band = 0;                     // drawn next
  std::vector<int> BandEdges;       // GL rows: band b spans [BandEdges[b + 1], BandEdges[b])
  std::vector<double> RowCosts;     // per GL row, measured at the last height banded
  std::vector<double> RowCostsView; // the camera they were measured with (empty: any)
  std::vector<double> BandSeconds;  // of the frame in progress
  Signature LastSignature;
  int LastRenderedProps = 0;
  int BandRenderedProps = 0;
  bool StageTiming = false;
  StageSeconds Stages;
  glm::dmat4 FrameClipToWorld{1.0}; // the camera of the frame in progress (jitter included)
  // With StageTiming, waits for the GL and adds the time since the last mark to STAGE.
  void MarkStage(double* stage);
  double StageMark = 0.0;

  vtkWeakPointer<vtkOpenGLRenderWindow> LastWindow; // where the targets live
  int Width = 0;
  int Height = 0;
  vtkTextureObject* FrameColor = nullptr;
  vtkTextureObject* FrameDepth = nullptr;
  vtkTextureObject* AccumulationColor = nullptr;
  // The targets of the size before the last change of size, kept: a view that switches between
  // its own resolution and a reduced one while things move finds the other size's targets made
  // (making them anew costs some 20-40 ms a switch on a software rasteriser, which clears every
  // new texture). PreviousColor is that size's mean, shown under the rows the new size's first
  // frame has not drawn yet (while PreviousShown).
  vtkTextureObject* SpareFrameColor = nullptr;
  vtkTextureObject* SpareFrameDepth = nullptr;
  vtkTextureObject* PreviousColor = nullptr;
  bool PreviousShown = false;
  vtkOpenGLFramebufferObject* FrameBuffer = nullptr;
  vtkOpenGLFramebufferObject* AccumulationBuffer = nullptr;
  std::unique_ptr<vtkOpenGLQuadHelper> AccumulateQuad;
  std::unique_ptr<vtkOpenGLQuadHelper> DisplayQuad;
  std::string AccumulateDefines;
  std::string DisplayDefines;
};
