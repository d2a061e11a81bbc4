#pragma once
// The environment dock: the built-in studio, the CC0 HDRIs that Blender installs (when present)
// and any file, each with a thumbnail made off the UI thread; rotation, exposure, background
// and tone mapping.
#include "scene/SceneEditor.h"

#include <QDockWidget>
#include <QString>
#include <functional>

class QListWidget;
class QListWidgetItem;

namespace aniso
{
class ParameterPanel;

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

private:
  QListWidgetItem* addItem(const QString& label, const QString& spec);
  void select(const QString& spec);
  void sync();

  SceneEditor* editor_;
  ParameterPanel* panel_;
  QListWidget* list_;
  int pending_ = 0;
  std::function<void(const QString&)> opener_;
};
} // namespace aniso
