#pragma once
// The environment dock: the built-in studio, the CC0 HDRIs that Blender installs (when present)
// and any file, each with a thumbnail made off the UI thread; the selected environment's
// analysis (its sources: sun, lamps, windows) marked on a preview and listed; rotation,
// exposure, background and tone mapping.
#include "scene/SceneEditor.h"

#include <QDockWidget>
#include <QString>
#include <atomic>
#include <functional>
#include <memory>

class QLabel;
class QListWidget;
class QListWidgetItem;
class QTableWidget;

namespace aniso
{
class ParameterPanel;
struct EnvAnalysis;

// Where Debian's blender-data package puts Blender's studio-light HDRIs.
QString blenderHdriDirectory();
// A file filter for environment files: HDR, EXR and the other formats OpenImageIO reads.
QString environmentFileFilter();

class EnvironmentDock : public QDockWidget
{
  Q_OBJECT

public:
  // HDRI_DIRECTORY: where to list ready-made environments (*.exr, *.hdr); may not exist.
  explicit EnvironmentDock(SceneEditor* editor,
                           const QString& hdriDirectory = blenderHdriDirectory(),
                           QWidget* parent = nullptr);
  ~EnvironmentDock() override;

  QListWidget* list() const { return list_; }
  // Thumbnails still being made.
  int pendingThumbnails() const { return pending_; }

  // The selected environment's analysis (sharedEnvironmentAnalysis: whoever asks for the same
  // environment shares it; the last few shown stay held, so a return to one is not analysed
  // again), made on a worker whenever the scene's environment changes; one runs at a time and
  // the latest request wins; the previous one stays shown until then. The preview shows the environment with its sources marked
  // (markedSources, in the image's own coordinates), the table lists them (kind, azimuth and
  // elevation in degrees in the world, env-rotation applied, as `aniso render --azimuth/
  // --elevation` take them; solid angle and the cone of that solid angle; share of the power),
  // the summary says how concentrated the power is.
  QLabel* sourcesPreview() const { return preview_; }
  QTableWidget* sourcesTable() const { return sources_; }
  QLabel* sourcesSummary() const { return summary_; }
  // The environment whose analysis is shown (empty before the first one, and after a failure),
  // and that analysis.
  const QString& analysedSpec() const { return analysedSpec_; }
  const std::shared_ptr<const EnvAnalysis>& analysis() const { return analysis_; }
  // Whether an analysis is running or waiting for the running one.
  bool analysing() const { return analysing_; }

  // Asks for a file and sets it as the environment.
  void openFile();
  // How a chosen environment (a file, a listed HDRI, the studio) reaches the scene: by default
  // it is submitted to the editor at once, its file read by the model's validation on this
  // thread; an opener set here takes the spec instead (the main window reads the file on a
  // worker first, then edits the scene).
  void setOpener(std::function<void(const QString& spec)> opener) { opener_ = std::move(opener); }

signals:
  void errorOccurred(const QString& message);
  void thumbnailsReady();
  // The latest requested analysis is shown (or its failure reported).
  void sourcesShown();

private:
  QListWidgetItem* addItem(const QString& label, const QString& spec);
  void select(const QString& spec);
  void sync();
  void analyse(const QString& spec);
  void startAnalysis(const QString& spec);
  void showSourceRows();

  SceneEditor* editor_;
  ParameterPanel* panel_;
  QListWidget* list_;
  int pending_ = 0;
  std::function<void(const QString&)> opener_;

  QLabel* preview_;
  QTableWidget* sources_;
  QLabel* summary_;
  QString requestedSpec_; // the latest request
  QString analysedSpec_;
  std::shared_ptr<const EnvAnalysis> analysis_;
  bool analysing_ = false; // a worker runs
  // False once the dock is gone: its workers skip what they have not begun.
  std::shared_ptr<std::atomic<bool>> alive_ = std::make_shared<std::atomic<bool>>(true);
};
} // namespace aniso
