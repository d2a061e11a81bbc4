#include "app/gui/MainWindow.h"

#include "app/gui/BackgroundLoader.h"
#include "app/gui/CompareWindow.h"
#include "app/gui/LitModelView.h"
#include "app/gui/ProgressReporter.h"
#include "app/gui/ReferenceDock.h"
#include "app/gui/ReferenceView.h"
#include "app/gui/SceneView.h"
#include "app/gui/SurfaceModelView.h"
#include "core/error.h"
#include "core/image/image.h"
#include "core/lut/lut_cache.h"
#include "scene/Autosave.h"
#include "scene/LutScheduler.h"
#include "scene/SceneShading.h"
#include "vtkpasses/mesh/GltfWriter.h"
#include "vtkpasses/mesh/MeshLoader.h"
#include "vtkpasses/render/LitModelMaterial.h"
#include "vtkpasses/render/OffscreenRenderer.h"
#include "vtkpasses/render/ViewSettings.h"
#include "widgets/EnvironmentDock.h"
#include "widgets/LightsDock.h"
#include "widgets/LutView.h"
#include "widgets/MapsDock.h"
#include "widgets/MaterialDock.h"
#include "widgets/SceneDock.h"

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QCloseEvent>
#include <QDateTime>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGuiApplication>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QProgressDialog>
#include <QScreen>
#include <QSettings>
#include <QSpinBox>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTimer>
#include <QToolButton>
#include <QUndoStack>
#include <QUrl>
#include <QVTKOpenGLNativeWidget.h>
#include <algorithm>
#include <cmath>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkPolyData.h>
#include <vtkRenderWindowInteractor.h>

namespace aniso
{
namespace
{
// The kinds of background loads besides the edits of a key (named by the key): no key's names.
const char* const kMeshLoad = "open mesh";
const char* const kAddLoad = "add mesh";
const char* const kEnvironmentLoad = "open environment";
const char* const kSessionLoad = "open session";
const char* const kRereadLoad = "read parts again";

// Equirectangular environments are twice as wide as high; maps usually are not.
bool looksEquirectangular(int width, int height)
{
  return std::abs(width - 2 * height) <= height / 50 + 1;
}

QString lowerSuffix(const QString& path)
{
  return QFileInfo(path).suffix().toLower();
}

bool isMeshFile(const QString& path)
{
  const QString patterns = QString::fromStdString(meshFilePatterns());
  return patterns.split(' ', Qt::SkipEmptyParts).contains("*." + lowerSuffix(path));
}

Image rgbOf(const Image& rgba)
{
  Image rgb(rgba.width, rgba.height, 3);
  for (std::size_t i = 0, n = std::size_t(rgb.width) * rgb.height; i < n; ++i)
  {
    std::copy_n(&rgba.data[i * 4], 3, &rgb.data[i * 3]);
  }
  return rgb;
}
} // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent), editor_(&model_), assets_(&model_),
      luts_(new LutScheduler(&model_, nullptr, this)), vtkWidget_(new QVTKOpenGLNativeWidget(this)),
      samplesLabel_(new QLabel(this)), lutLabel_(new QLabel(this)),
      referenceLabel_(new QLabel(this)), loader_(new BackgroundLoader(&assets_, this)),
      progress_(new ProgressReporter(statusBar(), this))
{
  setWindowTitle(tr("aniso"));
  setObjectName("MainWindow");
  setAcceptDrops(true);
  setDockOptions(AnimatedDocks | AllowTabbedDocks);

  vtkWidget_->setRenderWindow(renderWindow_);
  vtkWidget_->setMinimumSize(320, 240);
  vtkNew<vtkInteractorStyleTrackballCamera> style;
  renderWindow_->GetInteractor()->SetInteractorStyle(style);
  setCentralWidget(vtkWidget_);
  view_ = new SceneView(&model_, &assets_, luts_, renderWindow_, this);
  installShadingValidators(model_);
  litView_ = new LitModelView(&model_, view_, this);
  surfaceView_ = new SurfaceModelView(&model_, &assets_, view_, this);

  materialDock_ = new MaterialDock(&editor_, this);
  mapsDock_ = new MapsDock(&editor_, this);
  environmentDock_ = new EnvironmentDock(&editor_, blenderHdriDirectory(), this);
  lutDock_ = new QDockWidget(tr("Lookup tables"), this);
  lutDock_->setObjectName("LutDock");
  lutDock_->setWidget(new LutView(luts_, lutDock_));
  addDockWidget(Qt::LeftDockWidgetArea, materialDock_);
  addDockWidget(Qt::LeftDockWidgetArea, mapsDock_);
  addDockWidget(Qt::RightDockWidgetArea, environmentDock_);
  addDockWidget(Qt::RightDockWidgetArea, lutDock_);
  // While LEADR or the microstructure is the model, the Lights dock shows its parameters, whose
  // minimum height pushes the bottom strip taller; Qt's dock layout keeps that height when the
  // panel hides again, and the view would stay that much shorter. Back to a model without them,
  // the strip gets the height it had before (once the layout has hidden the panel). Connected
  // before the dock exists, so that its height is read before the dock shows the panel.
  connect(&model_, &SceneModel::valueChanged, this,
          [this](const QString& key)
          {
            if (key != "model" || !lightsDock_)
            {
              return;
            }
            const bool panel = !surfaceModelKeys(model_.text("model")).empty();
            if (panel && lightsDockHeight_ == 0)
            {
              lightsDockHeight_ = lightsDock_->height();
            }
            else if (!panel && lightsDockHeight_ > 0)
            {
              const int height = lightsDockHeight_;
              lightsDockHeight_ = 0;
              QTimer::singleShot(
                  0, this, [this, height] { resizeDocks({lightsDock_}, {height}, Qt::Vertical); });
            }
          });
  lightsDock_ = new LightsDock(&editor_, this);
  sceneDock_ = new SceneDock(&editor_, this);
  addDockWidget(Qt::RightDockWidgetArea, sceneDock_);
  // The view may hear of new parts before the dock does: a part it does not have yet is not
  // loaded yet.
  sceneDock_->setTriangleCounts(
      [this](int part) { return part < view_->partCount() ? view_->partTriangles(part) : -1; });
  connect(view_, &SceneView::partsDrawn, sceneDock_, &SceneDock::refreshCounts);
  // Lights sit in a short strip under the view (not in a tab), so every dock is visible at once;
  // the side columns keep the bottom corners.
  setCorner(Qt::BottomLeftCorner, Qt::LeftDockWidgetArea);
  setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea);
  addDockWidget(Qt::BottomDockWidgetArea, lightsDock_);

  connect(loader_, &BackgroundLoader::started, this,
          [this](const QString& name) { statusBar()->showMessage(tr("Loading %1").arg(name)); });
  connect(loader_, &BackgroundLoader::finished, statusBar(), &QStatusBar::clearMessage);
  connect(loader_, &BackgroundLoader::failed, this,
          [this](const QString& message) { reportError(message, true); });
  const auto toStatus = [this](const QString& message) { reportError(message, false); };
  connect(materialDock_, &MaterialDock::errorOccurred, this, toStatus);
  connect(mapsDock_, &MapsDock::errorOccurred, this, toStatus);
  connect(environmentDock_, &EnvironmentDock::errorOccurred, this, toStatus);
  // Maps and tangent models edited in the dock are read or prepared on a worker first.
  mapsDock_->setOpener([this](const std::string& key, const QString& text)
                       { editInBackground(key, text); });
  // Environment files chosen in the dock are read on a worker before they reach the scene.
  environmentDock_->setOpener([this](const QString& spec)
                              { openEnvironmentInBackground(spec, false); });
  connect(lightsDock_, &LightsDock::errorOccurred, this, toStatus);
  connect(sceneDock_, &SceneDock::errorOccurred, this, toStatus);
  connect(litView_, &LitModelView::errorOccurred, this, toStatus);
  connect(surfaceView_, &SurfaceModelView::errorOccurred, this, toStatus);
  connect(&editor_, &SceneEditor::errorOccurred, this, toStatus);
  connect(view_, &SceneView::errorOccurred, this, toStatus);
  connect(luts_, &LutScheduler::bakeFailed, this, toStatus);
  connect(view_, &SceneView::noteAdded, this,
          [this](const QString& note) { statusBar()->showMessage(note, 8000); });
  // New read options (cad-deflection, cad-angle): the parts of STEP and IGES files are read
  // again on a worker, the previous surfaces shown meanwhile.
  connect(view_, &SceneView::surfacesOutdated, this, &MainWindow::rereadPartsInBackground);
  connect(view_, &SceneView::frameRendered, this, &MainWindow::showSamples);
  connect(view_, &SceneView::interactionChanged, this, &MainWindow::setInteractiveResolution);
  connect(view_, &SceneView::lightingBusyChanged, this,
          [this](bool busy)
          {
            const QString baking = tr("Baking the environment…");
            if (busy)
            {
              statusBar()->showMessage(baking);
            }
            else if (statusBar()->currentMessage() == baking)
            {
              statusBar()->clearMessage();
            }
          });
  connect(luts_, &LutScheduler::busyChanged, this,
          [this](bool busy)
          { lutLabel_->setText(busy ? tr("Baking lookup tables…") : tr("Lookup tables ready")); });

  samplesLabel_->setObjectName("samples");
  statusBar()->addPermanentWidget(lutLabel_);
  statusBar()->addPermanentWidget(samplesLabel_);
  // The reference's words beside the predicted error: the error measured against it.
  reference_ = new ReferenceView(&model_, view_, luts_, this);
  referenceDock_ = new ReferenceDock(reference_, this);
  // Under the view, as wide as it, in a tab beside the lights: the pictures about the view's size.
  addDockWidget(Qt::BottomDockWidgetArea, referenceDock_);
  tabifyDockWidget(lightsDock_, referenceDock_);
  referenceDock_->hide();
  referenceLabel_->setObjectName("reference");
  // Its words change as the reference progresses: they never widen the window (a wider window
  // is a new view size, and the view and its reference would start over).
  referenceLabel_->setMinimumWidth(1);
  referenceLabel_->hide();
  statusBar()->addPermanentWidget(referenceLabel_);
  connect(reference_, &ReferenceView::errorOccurred, this, toStatus);
  connect(reference_, &ReferenceView::changed, this, &MainWindow::showReferenceState);
  connect(reference_, &ReferenceView::unsupportedChanged, this, &MainWindow::showReferenceState);
  connect(referenceDock_, &ReferenceDock::closed, this, [this] { showReference(false); });
  createMenus();

  // Most of the screen, without growing past a comfortable size on large screens.
  if (const QScreen* screen = QGuiApplication::primaryScreen())
  {
    const QRect area = screen->availableGeometry();
    resize(std::min(1500, area.width() * 9 / 10), std::min(960, area.height() * 9 / 10));
  }
  resizeDocks({materialDock_, environmentDock_}, {350, 370}, Qt::Horizontal);
  resizeDocks({materialDock_, mapsDock_}, {520, 380}, Qt::Vertical);
  resizeDocks({lightsDock_}, {190}, Qt::Vertical);
  const Preferences preferences = loadPreferences();
  luts_->cache().setMemoryBudget(std::size_t(preferences.lutMemoryMiB) << 20);
  luts_->cache().setDiskBudget(std::uintmax_t(preferences.lutDiskMiB) << 20);
  if (preferences.restoreLayout)
  {
    QSettings settings;
    restoreGeometry(settings.value("window/geometry").toByteArray());
    restoreState(settings.value("window/state").toByteArray());
    // The reference starts off whatever the last run left.
    referenceDock_->hide();
  }
  connectProgress();
}

MainWindow::~MainWindow()
{
  // A load in flight delivers to this window: it ends first (its result is dropped).
  delete loader_;
  // The reference's run ends (cancelled) before the view it follows goes.
  delete referenceDock_;
  delete reference_;
  // The comparison and the lit actor draw the view's mesh: they go before the view, which goes
  // before the widget whose window it draws into.
  delete compareWindow_;
  delete surfaceView_;
  delete litView_;
  delete view_;
  view_ = nullptr;
}

void MainWindow::createMenus()
{
  QMenu* file = menuBar()->addMenu(tr("&File"));
  file->addAction(
      tr("Open &Mesh…"), this,
      [this]
      {
        const QString path = QFileDialog::getOpenFileName(
            this, tr("Open a mesh"), QString(),
            tr("Meshes (%1);;All files (*)").arg(QString::fromStdString(meshFilePatterns())));
        if (!path.isEmpty())
        {
          openMeshInBackground(path);
        }
      },
      QKeySequence::Open);
  file->addAction(
      tr("&Add Mesh…"), this,
      [this]
      {
        const QStringList paths = QFileDialog::getOpenFileNames(
            this, tr("Add meshes to the scene"), QString(),
            tr("Meshes (%1);;All files (*)").arg(QString::fromStdString(meshFilePatterns())));
        if (!paths.isEmpty())
        {
          addMeshesInBackground(paths);
        }
      },
      QKeySequence(tr("Ctrl+Shift+O")));
  file->addAction(tr("Open &Environment…"), environmentDock_, &EnvironmentDock::openFile);
  file->addAction(tr("Open &Session…"), this,
                  [this]
                  {
                    const QString path =
                        QFileDialog::getOpenFileName(this, tr("Open a session"), QString(),
                                                     tr("Sessions (*.json);;All files (*)"));
                    if (!path.isEmpty())
                    {
                      openSessionInBackground(path);
                    }
                  });
  recentMenu_ = file->addMenu(tr("Open &Recent"));
  rebuildRecentMenu();
  file->addSeparator();
  file->addAction(
      tr("Save Session"), this,
      [this]
      {
        QString path = sessionPath_;
        if (path.isEmpty())
        {
          path = QFileDialog::getSaveFileName(this, tr("Save the session"), "session.json",
                                              tr("Sessions (*.json)"));
        }
        if (!path.isEmpty())
        {
          saveSession(path);
        }
      },
      QKeySequence::Save);
  file->addAction(
      tr("Save Session &As…"), this,
      [this]
      {
        const QString path = QFileDialog::getSaveFileName(this, tr("Save the session"),
                                                          "session.json", tr("Sessions (*.json)"));
        if (!path.isEmpty())
        {
          saveSession(path);
        }
      },
      QKeySequence::SaveAs);
  file->addAction(tr("E&xport Screenshot…"), this, &MainWindow::chooseAndExportScreenshot,
                  QKeySequence(tr("Ctrl+E")));
  file->addAction(tr("Export &Turntable…"), this, &MainWindow::chooseAndExportTurntable,
                  QKeySequence(tr("Ctrl+Shift+E")));
  file->addAction(tr("Export Scene as &glTF…"), this,
                  [this]
                  {
                    QString path =
                        QFileDialog::getSaveFileName(this, tr("Export the scene as glTF"),
                                                     "scene.glb", tr("glTF 2.0 (*.glb *.gltf)"));
                    if (path.isEmpty())
                    {
                      return;
                    }
                    const QString suffix = lowerSuffix(path);
                    if (suffix != "glb" && suffix != "gltf")
                    {
                      path += ".glb";
                    }
                    exportGltf(path);
                  });
  file->addSeparator();
  file->addAction(tr("&Quit"), this, &QWidget::close, QKeySequence::Quit);

  QMenu* edit = menuBar()->addMenu(tr("&Edit"));
  QAction* undo = editor_.undoStack()->createUndoAction(this, tr("&Undo"));
  undo->setShortcut(QKeySequence::Undo);
  QAction* redo = editor_.undoStack()->createRedoAction(this, tr("&Redo"));
  redo->setShortcut(QKeySequence::Redo);
  edit->addAction(undo);
  edit->addAction(redo);
  edit->addSeparator();
  // Ctrl+, where the platform names no key for preferences (X11 desktops other than KDE).
  QAction* preferences = edit->addAction(tr("&Preferences…"), this, &MainWindow::showPreferences);
  preferences->setShortcuts(QKeySequence::keyBindings(QKeySequence::Preferences).isEmpty()
                                ? QList<QKeySequence>{QKeySequence(tr("Ctrl+,"))}
                                : QKeySequence::keyBindings(QKeySequence::Preferences));
  preferences->setMenuRole(QAction::PreferencesRole);

  QMenu* viewMenu = menuBar()->addMenu(tr("&View"));
  for (QDockWidget* dock :
       {static_cast<QDockWidget*>(materialDock_), static_cast<QDockWidget*>(mapsDock_),
        static_cast<QDockWidget*>(environmentDock_), lutDock_,
        static_cast<QDockWidget*>(lightsDock_)})
  {
    viewMenu->addAction(dock->toggleViewAction());
  }
  viewMenu->addSeparator();
  viewMenu->addAction(
      tr("Reset &View"), this, [this] { view_->resetCamera(); }, QKeySequence(tr("Ctrl+R")));
  viewMenu->addAction(tr("&Frame All"), this, &MainWindow::frameAll, QKeySequence(Qt::Key_Home));
  // The named views, as `aniso render --view` names them: Ctrl+0 the three-quarter view, Ctrl+1
  // to Ctrl+6 the sides (front, back, left, right, top, bottom).
  QMenu* views = viewMenu->addMenu(tr("&Standard Views"));
  int number = 0;
  for (const ViewPreset& preset : viewPresets())
  {
    QAction* action = views->addAction(
        QString::fromStdString(preset.label), this,
        [this, name = preset.name] { view_->showView(name); },
        QKeySequence(tr("Ctrl+%1").arg(number++)));
    action->setData(QString::fromStdString(preset.name));
  }
  viewMenu->addAction(tr("Compare &Models"), this, &MainWindow::showCompareWindow);
  referenceAction_ = viewMenu->addAction(tr("R&eference"));
  referenceAction_->setObjectName("referenceAction");
  referenceAction_->setCheckable(true);
  referenceAction_->setShortcut(QKeySequence(tr("Ctrl+Shift+R")));
  connect(referenceAction_, &QAction::toggled, this, &MainWindow::showReference);
  // Where the reference does not cover the view, the entry's tip says why.
  viewMenu->setToolTipsVisible(true);
  showReferenceState();
}

void MainWindow::showReference(bool on)
{
  if (referenceAction_->isChecked() != on)
  {
    referenceAction_->setChecked(on); // toggled comes back here
    return;
  }
  reference_->setEnabled(on);
  referenceDock_->setVisible(on);
  if (on)
  {
    referenceDock_->raise();
  }
  referenceLabel_->setVisible(on);
  showReferenceState();
}

void MainWindow::showReferenceState()
{
  const QString why = reference_->unsupported();
  const QString tip =
      why.isEmpty()
          ? tr("The CPU reference of the view, beside it, and the view's error against it")
          : tr("No reference: %1").arg(why);
  referenceAction_->setEnabled(why.isEmpty());
  referenceAction_->setToolTip(tip);
  referenceAction_->setStatusTip(tip);
  referenceLabel_->setText(reference_->summary());
  referenceLabel_->setToolTip(referenceLabel_->text());
}

void MainWindow::showCompareWindow()
{
  if (!compareWindow_)
  {
    compareWindow_ = new CompareWindow(&model_, view_, this);
    connect(compareWindow_, &CompareWindow::errorOccurred, this,
            [this](const QString& message) { reportError(message, false); });
  }
  compareWindow_->show();
  compareWindow_->raise();
}

void MainWindow::reportError(const QString& message, bool dialog)
{
  statusBar()->showMessage(message, 15000);
  emit errorReported(message);
  if (dialog && errorDialogs_)
  {
    QMessageBox::warning(this, tr("aniso"), message);
  }
}

bool MainWindow::attempt(const std::function<void()>& action)
{
  try
  {
    action();
    return true;
  }
  catch (const Error& e)
  {
    reportError(QString::fromStdString(e.what()), true);
    return false;
  }
}

namespace
{
// The block a part of block B of LOADED draws: empty (the file as loadMesh reads it) for a file
// of one surface that sits where its coordinates are, else the block's name (always for a line
// set, which loadMesh does not read).
std::string partBlock(const LoadedBlocks& loaded, std::size_t b)
{
  const MeshBlock& block = loaded.blocks[b];
  return loaded.blocks.size() > 1 || block.placement != kIdentityPlacement || block.lines
             ? block.name
             : std::string();
}

// The tangent model a part of BLOCK starts with: its file material's, else TANGENTS.
std::string blockTangents(const MeshBlock& block, const std::string& tangents)
{
  return block.material ? block.material->value("tangents").text : tangents;
}

// What opening MESH reads first, whose failure is the load's: the file as one surface, or the
// parts of a file that has line parts (which the one surface leaves out; a file of lines only
// has no surface at all).
void readOpened(SceneAssets& staged, const std::string& mesh, const std::string& tangents)
{
  const bool builtin = mesh.rfind("builtin:", 0) == 0;
  const std::shared_ptr<const LoadedBlocks> loaded = builtin ? nullptr : staged.blocks(mesh);
  if (!loaded || std::none_of(loaded->blocks.begin(), loaded->blocks.end(),
                              [](const MeshBlock& b) { return b.lines; }))
  {
    staged.surface(mesh, tangents);
    return;
  }
  for (std::size_t b = 0; b < loaded->blocks.size(); ++b)
  {
    staged.surface(mesh, partBlock(*loaded, b), blockTangents(loaded->blocks[b], tangents));
  }
}
} // namespace

std::vector<ScenePart> MainWindow::partsOfFile(const QString& path, const std::string& material,
                                               MaterialLibrary& library,
                                               std::vector<ScenePart>& taken,
                                               QStringList& warnings)
{
  const std::string mesh = path.toStdString();
  const std::shared_ptr<const LoadedBlocks> loaded = assets_.blocks(mesh);
  for (const std::string& w : loaded->warnings)
  {
    warnings << QString::fromStdString(w);
  }
  const std::vector<MeshBlock>& blocks = loaded->blocks;
  // The file's materials first, all of them, so a failure leaves LIBRARY as it was.
  MaterialLibrary adopted = library;
  std::vector<std::string> materials(blocks.size(), material);
  for (std::size_t b = 0; b < blocks.size(); ++b)
  {
    if (blocks[b].material)
    {
      materials[b] = adopted.adopt(*blocks[b].material);
    }
  }
  std::vector<ScenePart> parts;
  for (std::size_t b = 0; b < blocks.size(); ++b)
  {
    const MeshBlock& block = blocks[b];
    ScenePart part = partOfMesh(mesh, materials[b]);
    part.block = partBlock(*loaded, b);
    part.group = blocks.size() > 1 ? QFileInfo(path).fileName().toStdString() : std::string();
    part.placement = block.placement;
    std::string name = blocks.size() > 1 ? block.name : part.name;
    // Unique in the scene: "shaft", "shaft 2", ...
    const auto used = [&](const std::string& n)
    {
      return std::any_of(taken.begin(), taken.end(),
                         [&](const ScenePart& p) { return p.name == n; });
    };
    std::string unique = name;
    for (int i = 2; used(unique); ++i)
    {
      unique = name + " " + std::to_string(i);
    }
    part.name = unique;
    taken.push_back(part);
    parts.push_back(part);
  }
  library = std::move(adopted);
  return parts;
}

bool MainWindow::openMesh(const QString& path)
{
  return attempt(
      [&]
      {
        // Everything that can fail first (the file loads, its blocks), so a failure leaves no
        // step on the undo stack.
        const ParameterValue mesh = textValue(path.toStdString());
        if (!(mesh == model_.value("mesh")))
        {
          model_.check("mesh", mesh);
        }
        QStringList warnings;
        std::vector<ScenePart> taken;
        // The new part keeps the material edits go to (as setting the mesh key does), unless
        // the file gives its parts materials of their own.
        const std::string material = model_.editedMaterials().front();
        MaterialLibrary library = model_.materials();
        const std::vector<ScenePart> parts = partsOfFile(path, material, library, taken, warnings);
        // What setting the mesh key alone makes of the scene: one part of the edited material.
        const bool plain = parts.size() == 1 && parts[0].material == material &&
                           parts[0].placement == kIdentityPlacement && parts[0].block.empty();
        const bool same = mesh == model_.value("mesh") &&
                          (plain ? model_.parts().size() == 1 : parts == model_.parts());
        if (!same)
        {
          // One step: the mesh key (the scene one part of it), then the file's blocks as parts.
          editor_.undoStack()->beginMacro(tr("Open %1").arg(QFileInfo(path).fileName()));
          editor_.edit("mesh", mesh);
          if (!plain)
          {
            editor_.editParts(parts, library, tr("Parts of %1").arg(path));
          }
          editor_.undoStack()->endMacro();
        }
        showTessellation();
        for (const QString& w : warnings)
        {
          reportError(w, false);
        }
        view_->resetCamera();
        addRecent(path);
      });
}

bool MainWindow::addMeshes(const QStringList& paths)
{
  std::vector<ScenePart> parts = model_.parts();
  MaterialLibrary library = model_.materials();
  std::string material(kDefaultMaterialName);
  if (!library.contains(material))
  {
    library.put(*builtinMaterials().find(material));
  }
  QStringList warnings;
  bool added = false;
  for (const QString& path : paths)
  {
    try
    {
      std::vector<ScenePart> taken = parts;
      const std::vector<ScenePart> more = partsOfFile(path, material, library, taken, warnings);
      parts.insert(parts.end(), more.begin(), more.end());
      added = true;
    }
    catch (const Error& e)
    {
      reportError(QString::fromStdString(e.what()), true);
    }
  }
  for (const QString& w : warnings)
  {
    reportError(w, false);
  }
  if (!added)
  {
    return false;
  }
  return attempt(
      [&]
      {
        editor_.editParts(parts, library,
                          paths.size() == 1 ? tr("Add %1").arg(QFileInfo(paths.front()).fileName())
                                            : tr("Add %1 meshes").arg(paths.size()));
        for (const QString& path : paths)
        {
          addRecent(path);
        }
      });
}

namespace
{
// Reads the blocks of each file and prepares them with TANGENTS, each file on its own: one that
// fails does not keep the others from being read (the failures are reported as they are added).
void prefetchMeshes(SceneAssets& staged, const std::vector<std::string>& files,
                    const std::string& tangents)
{
  for (const std::string& file : files)
  {
    try
    {
      const std::shared_ptr<const LoadedBlocks> loaded = staged.blocks(file);
      for (std::size_t b = 0; b < loaded->blocks.size(); ++b)
      {
        staged.surface(file, partBlock(*loaded, b), blockTangents(loaded->blocks[b], tangents));
      }
    }
    catch (const Error&)
    {
    }
  }
}
} // namespace

void MainWindow::openMeshesInBackground(const QStringList& paths)
{
  if (paths.isEmpty())
  {
    return;
  }
  std::vector<std::string> files;
  for (const QString& p : paths)
  {
    files.push_back(p.toStdString());
  }
  const std::string tangents = model_.text("tangents");
  loader_->load(
      kMeshLoad, paths.front(),
      [files, tangents](SceneAssets& staged)
      {
        readOpened(staged, files.front(), tangents); // the first opens: its failure is the load's
        prefetchMeshes(staged, files, tangents);
      },
      [this, paths]
      {
        if (openMesh(paths.front()) && paths.size() > 1)
        {
          addMeshes(paths.mid(1));
        }
      });
}

void MainWindow::addMeshesInBackground(const QStringList& paths)
{
  std::vector<std::string> files;
  for (const QString& p : paths)
  {
    files.push_back(p.toStdString());
  }
  const std::string tangents = builtinMaterials().at(kDefaultMaterialName).value("tangents").text;
  loader_->load(
      kAddLoad, paths.size() == 1 ? paths.front() : tr("%1 meshes").arg(paths.size()),
      [files, tangents](SceneAssets& staged) { prefetchMeshes(staged, files, tangents); },
      [this, paths] { addMeshes(paths); }, true);
}

bool MainWindow::meshLoading() const
{
  return loader_->loading(kMeshLoad);
}

bool MainWindow::environmentLoading() const
{
  return loader_->loading(kEnvironmentLoad);
}

bool MainWindow::assetLoading(const std::string& key) const
{
  return loader_->loading(key);
}

bool MainWindow::sessionLoading() const
{
  return loader_->loading(kSessionLoad);
}

void MainWindow::openMeshInBackground(const QString& path)
{
  const std::string mesh = path.toStdString();
  const std::string tangents = model_.text("tangents");
  loader_->load(
      kMeshLoad, path,
      [mesh, tangents](SceneAssets& staged)
      {
        readOpened(staged, mesh, tangents);
        // Its blocks too, as they become its parts.
        const std::shared_ptr<const LoadedBlocks> loaded = staged.blocks(mesh);
        for (std::size_t b = 0; b < loaded->blocks.size(); ++b)
        {
          staged.surface(mesh, partBlock(*loaded, b), blockTangents(loaded->blocks[b], tangents));
        }
      },
      // In the assets now: opening it (the model's validation, the view) reads nothing again,
      // unless the tangents changed meanwhile.
      [this, path] { openMesh(path); });
}

void MainWindow::rereadPartsInBackground()
{
  struct Wanted
  {
    std::string mesh, block, tangents;
  };
  std::vector<Wanted> wanted;
  QStringList files;
  for (std::size_t i = 0; i < model_.parts().size(); ++i)
  {
    const ScenePart& part = model_.parts()[i];
    const std::string tangents = model_.partMaterial(int(i)).value("tangents").text;
    if (!assets_.readOptionsKey(part.mesh).empty() &&
        !assets_.hasSurface(part.mesh, part.block, tangents))
    {
      wanted.push_back({part.mesh, part.block, tangents});
      const QString file = QFileInfo(QString::fromStdString(part.mesh)).fileName();
      if (!files.contains(file))
      {
        files << file;
      }
    }
  }
  if (wanted.empty())
  {
    view_->refreshSurfaces();
    return;
  }
  const MeshReadOptions options = assets_.meshReadOptions();
  // Another edit while these options are being read (a part shown, a material) waits for that
  // reading instead of starting it again.
  const std::string reading =
      toString(options.cadDeflection) + " " + formatNumber(options.cadAngleDegrees);
  if (loader_->loading(kRereadLoad) && rereading_ == reading)
  {
    return;
  }
  rereading_ = reading;
  loader_->load(
      kRereadLoad,
      tr("%1 at deflection %2, %3°")
          .arg(files.size() == 1 ? files.front() : tr("%1 files").arg(files.size()),
               QString::fromStdString(toString(options.cadDeflection)))
          .arg(options.cadAngleDegrees),
      [wanted](SceneAssets& staged)
      {
        // Each part on its own: one that fails is reported when the view takes it (skipped).
        for (const Wanted& w : wanted)
        {
          try
          {
            staged.surface(w.mesh, w.block, w.tangents);
          }
          catch (const Error&)
          {
          }
        }
      },
      [this]
      {
        view_->refreshSurfaces();
        showTessellation();
      },
      true);
}

void MainWindow::showTessellation()
{
  long long triangles = 0;
  QStringList formats;
  for (int i = 0; i < view_->partCount() && i < int(model_.parts().size()); ++i)
  {
    const std::string& mesh = model_.parts()[std::size_t(i)].mesh;
    if (assets_.readOptionsKey(mesh).empty())
    {
      continue;
    }
    const QString ext = lowerSuffix(QString::fromStdString(mesh));
    const QString format = ext == "step" || ext == "stp" ? tr("STEP") : tr("IGES");
    if (!formats.contains(format))
    {
      formats << format;
    }
    triangles += std::max(0LL, view_->partTriangles(i));
  }
  if (formats.isEmpty())
  {
    return;
  }
  const MeshReadOptions options = assets_.meshReadOptions();
  statusBar()->showMessage(tr("%1: %2 triangles at deflection %3, angle %4°")
                               .arg(formats.join(tr(" and ")), QLocale().toString(triangles),
                                    QString::fromStdString(toString(options.cadDeflection)))
                               .arg(options.cadAngleDegrees),
                           15000);
}

void MainWindow::openEnvironmentInBackground(const QString& spec, bool recent)
{
  const std::string text = spec.toStdString();
  loader_->load(
      kEnvironmentLoad, spec, [text](SceneAssets& staged) { staged.environment(text); },
      [this, spec, text, recent]
      {
        if (recent)
        {
          openEnvironment(spec);
        }
        else
        {
          attempt([&] { editor_.edit("env", textValue(text)); });
        }
      });
}

void MainWindow::editInBackground(const std::string& key, const QString& text)
{
  const std::string value = text.toStdString();
  const std::string mesh = model_.text("mesh");
  loader_->load(
      key, text.isEmpty() ? QString::fromStdString(key) : text,
      [key, value, mesh](SceneAssets& staged)
      {
        if (key == "tangents")
        {
          staged.surface(mesh, value); // the mesh prepared anew with these tangents
        }
        else
        {
          staged.map(key, value);
        }
      },
      [this, key, value] { attempt([&] { editor_.edit(key, textValue(value)); }); });
}

void MainWindow::openSessionInBackground(const QString& path)
{
  loader_->load(
      kSessionLoad, path,
      [path](SceneAssets& staged)
      {
        // What the session names, read ahead; anything wrong with it is left to openSession.
        const SessionContent content = readSessionFile(path);
        // Its parts read as the scene will read them once the session's values are set.
        MeshReadOptions options = staged.meshReadOptions();
        const auto deflection = content.values.find("cad-deflection");
        if (deflection != content.values.end())
        {
          options.cadDeflection.value = deflection->second.number[0];
        }
        const auto angle = content.values.find("cad-angle");
        if (angle != content.values.end())
        {
          options.cadAngleDegrees = angle->second.number[0];
        }
        staged.setMeshReadOptions(options);
        const auto text = [&](const char* key)
        {
          const auto it = content.values.find(key);
          return it == content.values.end() ? std::string() : it->second.text;
        };
        // Each on its own: one that fails does not keep the others from being read.
        const auto ahead = [](const std::function<void()>& read)
        {
          try
          {
            read();
          }
          catch (const Error&)
          {
          }
        };
        ahead([&] { staged.surface(text("mesh"), text("tangents")); });
        ahead([&] { staged.environment(text("env")); });
        // Every part's surface with its material's tangents, and its material's maps.
        for (const ScenePart& part : content.parts)
        {
          const Material* material = content.library.find(part.material);
          if (!material)
          {
            continue;
          }
          ahead([&]
                { staged.surface(part.mesh, part.block, material->value("tangents").text); });
          for (const char* key : SceneAssets::kMapKeys)
          {
            ahead([&] { staged.map(key, material->value(key).text); });
          }
        }
      },
      [this, path] { openSession(path); }, true);
}

bool MainWindow::openEnvironment(const QString& path)
{
  return attempt(
      [&]
      {
        editor_.edit("env", textValue(path.toStdString()));
        addRecent(path);
      });
}

bool MainWindow::openSession(const QString& path)
{
  return attempt(
      [&]
      {
        const QStringList unknown = session_.open(editor_, path);
        sessionPath_ = path;
        addRecent(path);
        if (!unknown.isEmpty())
        {
          // Reported once, here; the keys are kept and written back on save.
          statusBar()->showMessage(
              tr("%1: kept keys this version does not know: %2").arg(path, unknown.join(", ")),
              15000);
        }
      });
}

void MainWindow::enableAutosave(const QString& directory, AutosaveRestore restore)
{
  const QString dir = directory.isEmpty() ? Autosave::stateDirectory() : directory;
  const std::vector<CrashedSession> crashed = Autosave::crashedSessions(dir);
  delete autosave_;
  autosave_ = new Autosave(&model_, &session_, dir, Autosave::kDefaultDelayMs, this);
  connect(autosave_, &Autosave::failed, this, [this](const QString& m) { reportError(m, false); });
  if (crashed.empty() || restore == AutosaveRestore::Keep)
  {
    return;
  }
  const CrashedSession& latest = crashed.front();
  bool restoreIt = restore == AutosaveRestore::Always;
  if (restore == AutosaveRestore::Ask)
  {
    restoreIt = QMessageBox::question(
                    this, tr("Restore the last scene"),
                    tr("aniso did not close normally last time. Restore the scene it autosaved "
                       "at %1?")
                        .arg(QLocale().toString(latest.savedAt, QLocale::ShortFormat))) ==
                QMessageBox::Yes;
  }
  if (restoreIt)
  {
    // Not through openSession: the autosave is no file of the user's (no recent entry, no
    // session path to save back to).
    attempt([&] { session_.open(editor_, latest.path); });
    statusBar()->showMessage(tr("Restored the scene autosaved at %1")
                                 .arg(QLocale().toString(latest.savedAt, QLocale::ShortFormat)),
                             10000);
  }
  for (const CrashedSession& c : crashed)
  {
    Autosave::forget(c);
  }
}

bool MainWindow::saveSession(const QString& path)
{
  return attempt(
      [&]
      {
        session_.save(model_, path);
        sessionPath_ = path;
        addRecent(path);
        statusBar()->showMessage(tr("Saved %1").arg(path), 5000);
      });
}

bool MainWindow::exportGltf(const QString& path)
{
  return attempt(
      [&]
      {
        const std::string file = path.toStdString();
        std::vector<std::shared_ptr<const PreparedSurface>> surfaces; // alive while writing
        std::vector<GltfPart> parts;
        const std::vector<ScenePart>& scene = model_.parts();
        for (std::size_t i = 0; i < scene.size(); ++i)
        {
          if (!scene[i].visible)
          {
            continue;
          }
          GltfPart part;
          part.name = scene[i].name;
          part.material = model_.partMaterial(int(i));
          part.placement = scene[i].placement;
          try
          {
            surfaces.push_back(assets_.surface(scene[i].mesh, scene[i].block,
                                               part.material.value("tangents").text));
          }
          catch (const Error& e)
          {
            throw errorAbout(file, "part " + part.name + ": " + e.what());
          }
          part.polyData = surfaces.back()->polyData;
          parts.push_back(std::move(part));
        }
        if (parts.empty())
        {
          throw errorAbout(file, "no visible part to export");
        }
        writeGltfScene(file, parts);
        // glTF has the material, not a data field that varies it: said, not silently dropped.
        const std::size_t withFields = partsWithFields(parts).size();
        statusBar()->showMessage(
            tr("Exported %n part(s) to %1", nullptr, int(parts.size())).arg(path) +
                (withFields > 0 ? tr("; %n part(s) without their field (glTF has none)", nullptr,
                                     int(withFields))
                                : QString()),
            5000);
      });
}

bool MainWindow::openAny(const QString& path, bool background)
{
  const QString suffix = lowerSuffix(path);
  if (suffix == "json")
  {
    if (background)
    {
      openSessionInBackground(path);
      return true;
    }
    return openSession(path);
  }
  if (isMeshFile(path))
  {
    if (background)
    {
      openMeshInBackground(path);
      return true;
    }
    return openMesh(path);
  }
  if (background && suffix != "hdr")
  {
    // An image: its kind (an .exr may be an environment) is told on the worker, which reads it.
    openImageInBackground(path);
    return true;
  }
  bool environment = suffix == "hdr";
  if (suffix == "exr" && !attempt(
                             [&]
                             {
                               const Image image = readImage(path.toStdString());
                               environment = looksEquirectangular(image.width, image.height);
                             }))
  {
    return false;
  }
  if (environment)
  {
    if (background)
    {
      openEnvironmentInBackground(path, true);
      return true;
    }
    return openEnvironment(path);
  }
  return openNormalMap(path);
}

bool MainWindow::openNormalMap(const QString& path)
{
  return attempt(
      [&]
      {
        editor_.edit("normal-map", textValue(path.toStdString()));
        if (parseBumpMapping(model_.text("bump")) == BumpMapping::None)
        {
          editor_.edit("bump", textValue(std::string(spelling(BumpMapping::Quaternion))));
        }
      });
}

void MainWindow::openImageInBackground(const QString& path)
{
  const std::string text = path.toStdString();
  const bool exr = lowerSuffix(path) == "exr";
  auto environment = std::make_shared<bool>(false);
  loader_->load(
      "normal-map", path,
      [text, exr, environment](SceneAssets& staged)
      {
        const std::shared_ptr<const Image> image = staged.map("normal-map", text);
        *environment = exr && image && looksEquirectangular(image->width, image->height);
        if (*environment)
        {
          staged.environment(text);
        }
      },
      [this, path, environment]
      {
        if (*environment)
        {
          openEnvironment(path);
        }
        else
        {
          openNormalMap(path);
        }
      });
}

QString MainWindow::defaultScreenshotName(const QString& extension) const
{
  QString folder = loadPreferences().screenshotFolder;
  if (folder.isEmpty())
  {
    folder = QStandardPaths::writableLocation(QStandardPaths::PicturesLocation);
  }
  QString mesh = QString::fromStdString(model_.text("mesh"));
  mesh = mesh.startsWith("builtin:") ? mesh.mid(8) : QFileInfo(mesh).completeBaseName();
  const QString stamp = QDateTime::currentDateTime().toString("yyyyMMdd-HHmmss");
  return QDir(folder).filePath(QString("%1-%2.%3").arg(mesh, stamp, extension));
}

void MainWindow::exportScreenshot(const QString& path, const ScreenshotOptions& options)
{
  const std::string subject = path.toStdString();
  const QString suffix = lowerSuffix(path);
  if (suffix != "png" && suffix != "exr" && suffix != "tif" && suffix != "tiff")
  {
    throw errorAbout(subject, "a screenshot is .png, .exr, .tif or .tiff");
  }
  if (options.scale < 1 || options.scale > 4)
  {
    throw errorAbout(subject, "the scale must be 1 to 4");
  }
  const qreal ratio = vtkWidget_->devicePixelRatioF();
  const int width = std::max(1, static_cast<int>(vtkWidget_->width() * ratio)) * options.scale;
  const int height = std::max(1, static_cast<int>(vtkWidget_->height() * ratio)) * options.scale;
  RenderSettings settings = exportSettings(width, height);
  if (options.transparent)
  {
    settings.display.background = BackgroundMode::Transparent;
  }
  const bool alpha = settings.display.background == BackgroundMode::Transparent;
  QApplication::setOverrideCursor(Qt::WaitCursor);
  try
  {
    const RenderResult result = renderOffscreen(settings);
    if (suffix == "exr")
    {
      writeImage(subject, result.linear);
    }
    else
    {
      writeImage(subject, alpha ? result.display : rgbOf(result.display));
    }
  }
  catch (...)
  {
    QApplication::restoreOverrideCursor();
    throw;
  }
  QApplication::restoreOverrideCursor();
  QSettings().setValue(preference_keys::kScreenshotFolder, QFileInfo(path).absolutePath());
}

RenderSettings MainWindow::exportSettings(int width, int height)
{
  RenderSettings settings = view_->renderSettings(width, height);
  // A lit model is exported as the view draws it, each part with its own material.
  LitModelSettings lit;
  if (litSettingsOf(model_, lit))
  {
    settings.installMaterial = litModelInstaller(lit);
    for (std::size_t i = 0; i < settings.parts.size(); ++i)
    {
      LitModelSettings part = lit;
      litSceneOf(model_, model_.partParameters(int(i)), part);
      settings.parts[i].installMaterial = litModelInstaller(part);
    }
  }
  // So are LEADR and the microstructure.
  if (MaterialInstaller surface = surfaceModelInstallerOf(model_, assets_))
  {
    settings.installMaterial = std::move(surface);
    for (std::size_t i = 0; i < settings.parts.size(); ++i)
    {
      settings.parts[i].installMaterial = surfaceModelInstallerOf(model_, int(i), assets_);
    }
  }
  return settings;
}

void MainWindow::chooseAndExportScreenshot()
{
  QDialog dialog(this);
  dialog.setWindowTitle(tr("Export screenshot"));
  auto* pathEdit = new QLineEdit(defaultScreenshotName("png"), &dialog);
  auto* browse = new QToolButton(&dialog);
  browse->setText(tr("…"));
  auto* pathRow = new QWidget(&dialog);
  auto* pathLayout = new QHBoxLayout(pathRow);
  pathLayout->setContentsMargins(0, 0, 0, 0);
  pathLayout->addWidget(pathEdit, 1);
  pathLayout->addWidget(browse);
  auto* scale = new QSpinBox(&dialog);
  scale->setRange(1, 4);
  scale->setSuffix(tr(" ×"));
  auto* size = new QLabel(&dialog);
  const auto updateSize = [this, scale, size]
  {
    const qreal ratio = vtkWidget_->devicePixelRatioF();
    size->setText(tr("%1 × %2 pixels")
                      .arg(static_cast<int>(vtkWidget_->width() * ratio) * scale->value())
                      .arg(static_cast<int>(vtkWidget_->height() * ratio) * scale->value()));
  };
  updateSize();
  connect(scale, qOverload<int>(&QSpinBox::valueChanged), &dialog, updateSize);
  auto* transparent = new QCheckBox(tr("Transparent background (PNG, TIFF alpha)"), &dialog);
  connect(browse, &QToolButton::clicked, &dialog,
          [&dialog, pathEdit]
          {
            const QString chosen = QFileDialog::getSaveFileName(
                &dialog, tr("Export screenshot"), pathEdit->text(),
                tr("PNG, as displayed (*.png);;EXR, linear radiance (*.exr);;TIFF, 16-bit (*.tif "
                   "*.tiff)"));
            if (!chosen.isEmpty())
            {
              pathEdit->setText(chosen);
            }
          });
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &dialog);
  connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
  auto* form = new QFormLayout(&dialog);
  form->addRow(tr("File"), pathRow);
  form->addRow(tr("Scale"), scale);
  form->addRow(tr("Size"), size);
  form->addRow(QString(), transparent);
  form->addRow(buttons);
  if (dialog.exec() != QDialog::Accepted)
  {
    return;
  }
  ScreenshotOptions options;
  options.scale = scale->value();
  options.transparent = transparent->isChecked();
  if (attempt([&] { exportScreenshot(pathEdit->text(), options); }))
  {
    statusBar()->showMessage(tr("Wrote %1").arg(pathEdit->text()), 8000);
  }
}

TurntableResult MainWindow::exportTurntableFrames(const TurntableOptions& options)
{
  checkTurntableOptions(options, options.prefix.toStdString());
  const std::vector<CameraState> cameras = turntableCameras(
      view_->currentCamera(), view_->drawingFrame(), options.frames, options.elevationDegrees);
  const RenderSettings settings = exportSettings(options.width, options.height);
  QProgressDialog progress(tr("Rendering the turntable…"), tr("Cancel"), 0, options.frames, this);
  progress.setWindowModality(Qt::WindowModal);
  progress.setMinimumDuration(ProgressReporter::kShowAfterMs);
  const TurntableResult result = exportTurntable(settings, cameras, options,
                                                 [&progress](int done)
                                                 {
                                                   progress.setValue(done);
                                                   QApplication::processEvents();
                                                   return !progress.wasCanceled();
                                                 });
  QSettings().setValue(preference_keys::kScreenshotFolder,
                       QFileInfo(options.prefix).absolutePath());
  return result;
}

void MainWindow::chooseAndExportTurntable()
{
  TurntableOptions options;
  options.prefix = defaultScreenshotName("png");
  options.prefix.chop(4);
  const qreal ratio = vtkWidget_->devicePixelRatioF();
  options.width = static_cast<int>(vtkWidget_->width() * ratio);
  options.height = static_cast<int>(vtkWidget_->height() * ratio);
  double azimuth = 0.0;
  azimuthElevationOf(view_->currentCamera(), view_->drawingFrame(), azimuth,
                     options.elevationDegrees);
  options.video = !ffmpegExecutable().isEmpty();
  if (!askTurntableOptions(this, options))
  {
    return;
  }
  TurntableResult result;
  if (!attempt([&] { result = exportTurntableFrames(options); }))
  {
    return;
  }
  if (result.cancelled)
  {
    statusBar()->showMessage(
        tr("Turntable cancelled after %n frames", nullptr, static_cast<int>(result.frames.size())),
        8000);
  }
  else if (!result.videoError.isEmpty())
  {
    reportError(tr("Wrote %n frames; %1", nullptr, static_cast<int>(result.frames.size()))
                    .arg(result.videoError),
                false);
  }
  else
  {
    statusBar()->showMessage(
        result.video.isEmpty()
            ? tr("Wrote %n frames", nullptr, static_cast<int>(result.frames.size()))
            : tr("Wrote %n frames and %1", nullptr, static_cast<int>(result.frames.size()))
                  .arg(result.video),
        8000);
  }
}

void MainWindow::frameAll()
{
  const int* size = renderWindow_->GetSize();
  attempt(
      [&]
      {
        model_.setCamera(
            aniso::frameAll(view_->currentCamera(), view_->drawingFrame(), size[0], size[1]));
      });
}

void MainWindow::applyPreferences(const Preferences& preferences)
{
  savePreferences(preferences);
  luts_->cache().setMemoryBudget(std::size_t(preferences.lutMemoryMiB) << 20);
  luts_->cache().setDiskBudget(std::uintmax_t(preferences.lutDiskMiB) << 20);
  rebuildRecentMenu();
}

void MainWindow::showPreferences()
{
  PreferencesDialog dialog(loadPreferences(), QString::fromStdString(luts_->cache().directory()),
                           this);
  connect(&dialog, &PreferencesDialog::applied, this, &MainWindow::applyPreferences);
  dialog.exec();
}

void MainWindow::beginBake(const QString& kind, const QString& text)
{
  QUndoStack* stack = editor_.undoStack();
  auto index = std::make_shared<int>(0);
  auto command = std::make_shared<const QUndoCommand*>(nullptr);
  progress_->begin(kind, text,
                   [stack, index, command]
                   {
                     // Other edits came since: Cancel leaves them be.
                     if (*index > 0 && stack->index() == *index &&
                         stack->command(*index - 1) == *command)
                     {
                       stack->undo();
                     }
                   });
  // A bake starts inside the push (or undo) of its edit, before the stack counts it: the edit
  // is read once that is done.
  QTimer::singleShot(0, this,
                     [this, stack, index, command, kind, text]
                     {
                       *index = stack->index();
                       *command = *index > 0 ? stack->command(*index - 1) : nullptr;
                       if (*index == 0 && progress_->running(kind))
                       {
                         // The scene as it started: nothing to go back to, no Cancel.
                         progress_->begin(kind, text, {});
                       }
                     });
}

void MainWindow::connectProgress()
{
  connect(loader_, &BackgroundLoader::began, this,
          [this](const QString& kind, const QString& name)
          {
            progress_->begin(kind, tr("Loading %1").arg(QFileInfo(name).fileName()),
                             [this, kind] { loader_->cancel(kind.toStdString()); });
          });
  connect(loader_, &BackgroundLoader::ended, progress_, &ProgressReporter::end);
  // A bake follows an edit (an environment, its cube size or sampling; a lobe's exponents):
  // Cancel takes that edit back, and with it what the bake would have shown (the lighting
  // loader drops its bake's result, the scheduler cancels its bake).
  connect(view_, &SceneView::lightingBusyChanged, this,
          [this](bool busy)
          {
            if (busy)
            {
              beginBake("environment bake", tr("Baking the environment"));
            }
            else
            {
              progress_->end("environment bake");
            }
          });
  connect(luts_, &LutScheduler::busyChanged, this,
          [this](bool busy)
          {
            if (busy)
            {
              beginBake("lookup-table bake", tr("Baking lookup tables"));
            }
            else
            {
              progress_->end("lookup-table bake");
            }
          });
}

QStringList MainWindow::recentFiles() const
{
  return QSettings().value(preference_keys::kRecentFiles).toStringList();
}

void MainWindow::addRecent(const QString& path)
{
  QStringList files = recentFiles();
  const QString absolute = QFileInfo(path).absoluteFilePath();
  files.removeAll(absolute);
  files.prepend(absolute);
  const int count = loadPreferences().recentCount;
  while (files.size() > count)
  {
    files.removeLast();
  }
  QSettings().setValue(preference_keys::kRecentFiles, files);
  rebuildRecentMenu();
}

void MainWindow::rebuildRecentMenu()
{
  if (!recentMenu_)
  {
    return;
  }
  recentMenu_->clear();
  const QStringList files = recentFiles();
  for (const QString& path : files)
  {
    recentMenu_->addAction(QFileInfo(path).fileName(), this, [this, path] { openAny(path, true); })
        ->setToolTip(path);
  }
  recentMenu_->setEnabled(!files.isEmpty());
}

void MainWindow::setInteractiveResolution(bool interacting)
{
  // While things move, frames at half the resolution (a quarter of the pixels, scaled up by the
  // widget): on a CPU rasteriser most of a frame's cost is per pixel.
  const double before = vtkWidget_->effectiveDevicePixelRatio();
  vtkWidget_->setCustomDevicePixelRatio(interacting ? 0.5 * vtkWidget_->devicePixelRatioF() : 0.0);
  // The widget sizes its render window by the ratio when its size changes (its protected slot
  // updateSize). Called directly rather than through a resize event: that would also re-create
  // the widget's framebuffer and paint, drawing a frame in this very pass of the event loop
  // (40-80 ms); this way the view's next frame, in a pass of its own, is drawn at the new size.
  QMetaObject::invokeMethod(vtkWidget_, "updateSize", Qt::DirectConnection);
  const double ratio = vtkWidget_->effectiveDevicePixelRatio() / before;
  // A drag in progress continues from where the pointer is in the new pixel units, so the
  // camera does not jump.
  vtkRenderWindowInteractor* interactor = renderWindow_->GetInteractor();
  const int* p = interactor->GetEventPosition();
  interactor->SetEventPosition(static_cast<int>(std::lround(p[0] * ratio)),
                               static_cast<int>(std::lround(p[1] * ratio)));
}

void MainWindow::showSamples(int samples, int target)
{
  if (view_->interacting())
  {
    samplesLabel_->setText(tr("Preview"));
    return;
  }
  // By error: the error the view's own frames show (the mean against its first half), once
  // they show one. By samples: the error the target's sample count is predicted to reach (the
  // error model).
  const double estimated = view_->estimatedError();
  if (view_->byError() && estimated >= 0.0)
  {
    samplesLabel_->setText(tr("Samples %1 / %2, estimated error %3%")
                               .arg(std::min(samples, target))
                               .arg(target)
                               .arg(100.0 * estimated, 0, 'g', 2));
    return;
  }
  samplesLabel_->setText(tr("Samples %1 / %2, predicted error %3%")
                             .arg(std::min(samples, target))
                             .arg(target)
                             .arg(100.0 * view_->quality().predictedError, 0, 'g', 2));
}

bool MainWindow::event(QEvent* event)
{
  if (event->type() != QEvent::UpdateRequest || !view_)
  {
    return QMainWindow::event(event);
  }
  view_->beginWindowRepaint();
  const bool handled = QMainWindow::event(event);
  view_->endWindowRepaint();
  return handled;
}

void MainWindow::closeEvent(QCloseEvent* event)
{
  QSettings settings;
  settings.setValue("window/geometry", saveGeometry());
  settings.setValue("window/state", saveState());
  event->accept();
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event)
{
  if (event->mimeData()->hasUrls())
  {
    for (const QUrl& url : event->mimeData()->urls())
    {
      if (url.isLocalFile())
      {
        event->acceptProposedAction();
        return;
      }
    }
  }
}

void MainWindow::dropEvent(QDropEvent* event)
{
  for (const QUrl& url : event->mimeData()->urls())
  {
    if (url.isLocalFile())
    {
      openAny(url.toLocalFile(), true);
    }
  }
  event->acceptProposedAction();
}
} // namespace aniso
