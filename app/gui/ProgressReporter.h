#pragma once
// Progress of the window's long tasks (mesh and session loads, environment bakes, lookup-table
// bakes) in the status bar: a busy bar, what runs and a Cancel button, shown only once a task
// has run for kShowAfterMs (shorter ones never flicker into view). Cancel runs the task's own
// cancel, which stops or discards the work and keeps the scene as it is.
#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <functional>
#include <map>

class QLabel;
class QStatusBar;
class QTimer;
class QToolButton;
class QWidget;

namespace aniso
{
class BusyBar;

class ProgressReporter : public QObject
{
  Q_OBJECT

public:
  static constexpr int kShowAfterMs = 500;

  // The progress widgets go into BAR (permanent widgets, hidden until a task runs long).
  explicit ProgressReporter(QStatusBar* bar, QObject* parent = nullptr);

  // Task KIND (one of each kind at a time; a new begin replaces its text and cancel) started,
  // TEXT saying what it does ("Loading bunny.ply"). CANCEL: what Cancel does for it (none: the
  // task cannot be cancelled, Cancel is disabled while it is the one shown).
  void begin(const QString& kind, const QString& text, std::function<void()> cancel);
  // Task KIND is done (or cancelled, or failed); nothing when it is not running.
  void end(const QString& kind);

  bool running(const QString& kind) const { return tasks_.count(kind) > 0; }
  // The progress is on screen.
  bool shown() const;
  // The task shown: the longest running.
  QString shownKind() const;
  QWidget* widget() const { return box_; }
  QToolButton* cancelButton() const { return cancel_; }

signals:
  // Cancel was pressed for task KIND (after its cancel ran).
  void cancelled(const QString& kind);

private:
  struct Task
  {
    QString text;
    std::function<void()> cancel;
    QElapsedTimer clock;
  };
  void update();
  void cancelShown();

  std::map<QString, Task> tasks_;
  QWidget* box_;
  QLabel* label_;
  BusyBar* bar_;
  QToolButton* cancel_;
  QTimer* timer_;
};
} // namespace aniso
