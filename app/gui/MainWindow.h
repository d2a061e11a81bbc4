#pragma once
// The application window: the VTK view in the centre, the material, maps, environment and
// lookup-table docks around it, menus (File, Edit, View), a status bar with the progressive
// sample count, recent files, drag and drop, sessions and screenshot export. Every failure is
// reported once, in words, and leaves the scene as it was.
#include "app/gui/PreferencesDialog.h"
#include "app/gui/SceneAssets.h"
#include "app/gui/StandardViews.h"
#include "app/gui/TurntableExport.h"
#include "scene/SceneEditor.h"
#include "scene/SceneModel.h"
#include "scene/Session.h"

#include <QMainWindow>
#include <QString>
#include <QStringList>
#include <functional>
#include <memory>
#include <string>
#include <vtkNew.h>

class QAction;
class QLabel;
class QMenu;
class QVTKOpenGLNativeWidget;
class vtkGenericOpenGLRenderWindow;

namespace aniso
{
class Autosave;
class BackgroundLoader;
class CompareWindow;
class EnvironmentDock;
class LightsDock;
class LitModelView;
class SurfaceModelView;
class LutScheduler;
class MapsDock;
class ProgressReporter;
class MaterialDock;
class ReferenceDock;
class ReferenceView;
class SceneDock;
class SceneView;

// What enableAutosave does with the autosave of an earlier run that did not exit normally.
enum class AutosaveRestore
{
  Ask,    // asks whether to restore it (interactive starts without a mesh or session to open)
  Always, // restores it without asking
  Keep,   // leaves it for a later start (one that opens a file of its own)
};

struct ScreenshotOptions
{
  int scale = 1;            // 1 to 4 times the view's size
  bool transparent = false; // no background: PNG/TIFF alpha is the coverage
};

class MainWindow : public QMainWindow
{
  Q_OBJECT

public:
  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;

  SceneModel* model() { return &model_; }
  SceneEditor* editor() { return &editor_; }
  SceneView* view() const { return view_; }
  SurfaceModelView* surfaceView() const { return surfaceView_; }
  LitModelView* litView() const { return litView_; }
  LightsDock* lightsDock() const { return lightsDock_; }
  SceneDock* sceneDock() const { return sceneDock_; }
  // View > Reference (Ctrl+Shift+R): the view's CPU reference computed on a worker
  // (ReferenceView), shown in the Reference dock beside the view (a wipe or the error map), the
  // view's error against it in the status bar. The action is disabled, its tip saying why, where
  // the reference does not cover the view (another model, maps, a data field, line parts).
  ReferenceView* referenceView() const { return reference_; }
  ReferenceDock* referenceDock() const { return referenceDock_; }
  QAction* referenceAction() const { return referenceAction_; }
  void showReference(bool on);
  // The comparison view (View > Compare models), made when first opened.
  CompareWindow* compareWindow() const { return compareWindow_; }
  void showCompareWindow();
  LutScheduler* lutScheduler() const { return luts_; }
  // The background loads (File menu, drops, docks) and the progress of every long task.
  BackgroundLoader* loader() const { return loader_; }
  ProgressReporter* progress() const { return progress_; }
  QVTKOpenGLNativeWidget* vtkWidget() const { return vtkWidget_; }

  // Errors go to the status bar and errorReported; with dialogs on (the default) file
  // operations also show a message box.
  void setErrorDialogs(bool on) { errorDialogs_ = on; }
  // Autosaves the scene from now on (scene/Autosave.h) into DIRECTORY (empty: the state
  // directory), and deals with the newest autosave an earlier run left there by dying as
  // RESTORE says: restored as one undoable step (the older ones are dropped with it).
  void enableAutosave(const QString& directory, AutosaveRestore restore);
  Autosave* autosave() const { return autosave_; }

  // Each returns false after reporting a failure (the scene is unchanged then).
  // A mesh file replaces the scene: one part per block of the file (OBJ groups, .vtm blocks,
  // glTF nodes), one undoable step.
  bool openMesh(const QString& path);
  // Adds the blocks of each mesh file as parts (grouped under the file's name, named by the
  // block, made unique in the scene), one undoable step. A file that fails as a whole is
  // reported with its name and adds nothing; the others are added; a block that fails is
  // skipped with a warning naming the file and the part.
  bool addMeshes(const QStringList& paths);
  // The same after reading and preparing the files on a worker (File > Add Mesh).
  void addMeshesInBackground(const QStringList& paths);
  // Opens the first of PATHS and adds the others, after reading them all on a worker (the
  // command line's MESH...).
  void openMeshesInBackground(const QStringList& paths);
  bool openEnvironment(const QString& path);
  bool openSession(const QString& path);
  bool saveSession(const QString& path);
  // Writes the scene's visible parts as glTF 2.0 (vtkpasses/mesh/GltfWriter: .glb, else .gltf
  // text): each part's loaded, prepared surface in its own frame, its placement and its library
  // material (KHR_materials_anisotropy; maps and fields are not written, the status bar says how
  // many parts had a field). File > Export Scene as glTF.
  bool exportGltf(const QString& path);
  // By the file's kind: a session (.json), a mesh, an environment (.hdr, or an .exr twice as
  // wide as high), else an image taken as the normal map. With BACKGROUND a mesh opens through
  // openMeshInBackground (true then means the load started).
  bool openAny(const QString& path, bool background = false);
  // Opens a mesh as openMesh does, after reading and preparing it on a worker thread: the window
  // answers input meanwhile ("Loading NAME" in the status bar, meshLoading() true). The latest
  // request wins (an earlier one that finishes later is dropped); a failure is reported as
  // openMesh reports it, once, and leaves the scene as it was. The File menu, dropped files and
  // the recent files open meshes so.
  void openMeshInBackground(const QString& path);
  bool meshLoading() const;
  // The same for an environment (a file, or a spec the environment dock lists); with RECENT it
  // joins the recent files as openEnvironment does. The dock opens its choices so.
  void openEnvironmentInBackground(const QString& spec, bool recent);
  bool environmentLoading() const;
  // The same for a map file or pattern (normal-map, tpr, ...) or a tangent model (the mesh
  // prepared anew), then set as KEY's value. The Maps dock edits them so.
  void editInBackground(const std::string& key, const QString& text);
  bool assetLoading(const std::string& key) const;
  // A session: what it names (mesh, environment, maps) is read on a worker, then openSession
  // applies it, finding them read; anything wrong is reported by openSession, in its words.
  void openSessionInBackground(const QString& path);
  bool sessionLoading() const;
  // Renders the current view at scale x its size with the full quality and writes PATH by its
  // extension: .png (display-transformed 8-bit sRGB), .tif/.tiff (the same in 16 bits), .exr
  // (linear radiance, float, alpha = coverage). Throws aniso::Error "PATH: reason".
  void exportScreenshot(const QString& path, const ScreenshotOptions& options);
  // A file name for a screenshot: the mesh's name and the time, in the last used folder.
  QString defaultScreenshotName(const QString& extension) const;
  // What renderOffscreen needs to redraw the view at WIDTH x HEIGHT as screenshots draw it (the
  // model shown: the anisotropic material, a lit model or a surface model, each part's own).
  RenderSettings exportSettings(int width, int height);
  // Writes a turntable (app/gui/TurntableExport.h) of the view's scene, its camera turned from
  // the view's, with a progress dialog whose Cancel stops it. Throws aniso::Error as
  // exportTurntable does.
  TurntableResult exportTurntableFrames(const TurntableOptions& options);

  // The camera framing the visible parts from one side (View > Front, ...), Frame All (the
  // direction kept) and Reset View (the default view).
  void frameAll();

  // The preferences (app/gui/PreferencesDialog.h): saved to QSettings and applied (the recent
  // files' count, the lookup tables' budgets; the screenshot folder is read when used).
  void applyPreferences(const Preferences& preferences);
  void showPreferences();

  QStringList recentFiles() const;

signals:
  void errorReported(const QString& message);

protected:
  // Times the window's repaints (QEvent::UpdateRequest: the widgets painted and the window
  // composed with the view's picture) for the view's frame planning
  // (SceneView::beginWindowRepaint, endWindowRepaint).
  bool event(QEvent* event) override;
  void closeEvent(QCloseEvent* event) override;
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dropEvent(QDropEvent* event) override;

private:
  void createMenus();
  // Runs ACTION; an aniso::Error it throws is reported (with a dialog) and gives false.
  bool attempt(const std::function<void()>& action);
  void reportError(const QString& message, bool dialog);
  void addRecent(const QString& path);
  void rebuildRecentMenu();
  void showSamples(int samples, int target);
  // The Reference action's state and tips, the status bar's words, as the reference changes.
  void showReferenceState();
  void setInteractiveResolution(bool interacting);
  void chooseAndExportScreenshot();
  void chooseAndExportTurntable();
  // Long tasks to the progress: the background loads (Cancel drops them), the environment and
  // lookup-table bakes (Cancel undoes the edit that started them, when it is the last one).
  void connectProgress();
  // Bake KIND (TEXT) to the progress, its Cancel undoing the edit that started it while that is
  // the last one (none at the start, with no edit to undo).
  void beginBake(const QString& kind, const QString& text);
  // The parts of the blocks of PATH (loaded into assets_ already), named uniquely beside TAKEN,
  // placed where the file puts them, with the material the file gives them (adopted into
  // LIBRARY: MaterialLibrary::adopt), else MATERIAL; the blocks skipped go to WARNINGS.
  std::vector<ScenePart> partsOfFile(const QString& path, const std::string& material,
                                     MaterialLibrary& library, std::vector<ScenePart>& taken,
                                     QStringList& warnings);
  // Reads the parts of STEP and IGES files again on a worker with the model's read options
  // (cad-deflection, cad-angle; the view shows the previous surfaces meanwhile), then shows them
  // and their triangle count.
  void rereadPartsInBackground();
  // "STEP: N triangles at deflection D, angle A°" in the status bar, for the scene's CAD parts.
  void showTessellation();
  // PATH as the normal map (and bump quaternion when bump was none).
  bool openNormalMap(const QString& path);
  // An image dropped or reopened: read on a worker, then an environment (an .exr twice as wide
  // as high) or the normal map.
  void openImageInBackground(const QString& path);

  SceneModel model_;
  SceneEditor editor_;
  SceneAssets assets_;
  SessionFile session_;
  QString sessionPath_;
  LutScheduler* luts_;
  QVTKOpenGLNativeWidget* vtkWidget_;
  vtkNew<vtkGenericOpenGLRenderWindow> renderWindow_;
  SceneView* view_ = nullptr;
  MaterialDock* materialDock_;
  MapsDock* mapsDock_;
  EnvironmentDock* environmentDock_;
  QDockWidget* lutDock_;
  LightsDock* lightsDock_ = nullptr;
  int lightsDockHeight_ = 0; // before a model's parameters showed in it (0: none shows)
  SceneDock* sceneDock_;
  LitModelView* litView_ = nullptr;
  SurfaceModelView* surfaceView_ = nullptr;
  CompareWindow* compareWindow_ = nullptr;
  QMenu* recentMenu_ = nullptr;
  QLabel* samplesLabel_;
  QLabel* lutLabel_;
  ReferenceView* reference_ = nullptr;
  ReferenceDock* referenceDock_ = nullptr;
  QAction* referenceAction_ = nullptr;
  QLabel* referenceLabel_;
  bool errorDialogs_ = true;
  Autosave* autosave_ = nullptr;
  // The background loads (the status bar says what loads), each kind's latest request winning.
  BackgroundLoader* loader_;
  ProgressReporter* progress_;
  std::string rereading_; // the read options the latest rereadPartsInBackground reads with
};
} // namespace aniso
