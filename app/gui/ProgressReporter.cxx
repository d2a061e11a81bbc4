#include "app/gui/ProgressReporter.h"

#include "widgets/BusyBar.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QStatusBar>
#include <QTimer>
#include <QToolButton>

namespace aniso
{
ProgressReporter::ProgressReporter(QStatusBar* bar, QObject* parent)
    : QObject(parent), box_(new QWidget(bar)), label_(new QLabel(box_)),
      bar_(new BusyBar(box_)), cancel_(new QToolButton(box_)), timer_(new QTimer(this))
{
  box_->setObjectName("progress");
  cancel_->setObjectName("cancelProgress");
  auto* layout = new QHBoxLayout(box_);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(label_);
  // No fraction is known of a read or a bake: the bar says only that it runs.
  bar_->setMaximumWidth(120);
  layout->addWidget(bar_);
  cancel_->setText(tr("Cancel"));
  cancel_->setToolTip(tr("Stop this task; the scene stays as it is"));
  layout->addWidget(cancel_);
  bar->addPermanentWidget(box_);
  box_->hide();
  connect(cancel_, &QToolButton::clicked, this, &ProgressReporter::cancelShown);
  timer_->setSingleShot(true);
  connect(timer_, &QTimer::timeout, this, &ProgressReporter::update);
}

void ProgressReporter::begin(const QString& kind, const QString& text, std::function<void()> cancel)
{
  Task& task = tasks_[kind];
  if (!task.clock.isValid())
  {
    task.clock.start();
  }
  task.text = text;
  task.cancel = std::move(cancel);
  update();
}

void ProgressReporter::end(const QString& kind)
{
  if (tasks_.erase(kind) > 0)
  {
    update();
  }
}

bool ProgressReporter::shown() const
{
  return !box_->isHidden();
}

QString ProgressReporter::shownKind() const
{
  QString oldest;
  qint64 longest = -1;
  for (const auto& [kind, task] : tasks_)
  {
    const qint64 ms = task.clock.elapsed();
    if (ms > longest)
    {
      longest = ms;
      oldest = kind;
    }
  }
  return oldest;
}

void ProgressReporter::update()
{
  const QString kind = shownKind();
  if (kind.isEmpty())
  {
    timer_->stop();
    box_->hide();
    return;
  }
  const Task& task = tasks_.at(kind);
  const qint64 ms = task.clock.elapsed();
  if (ms < kShowAfterMs)
  {
    box_->hide();
    timer_->start(static_cast<int>(kShowAfterMs - ms));
    return;
  }
  const int others = static_cast<int>(tasks_.size()) - 1;
  label_->setText(others > 0 ? tr("%1 (and %n more)", nullptr, others).arg(task.text) : task.text);
  cancel_->setEnabled(static_cast<bool>(task.cancel));
  box_->show();
}

void ProgressReporter::cancelShown()
{
  const QString kind = shownKind();
  const auto it = tasks_.find(kind);
  if (it == tasks_.end() || !it->second.cancel)
  {
    return;
  }
  // The cancel may end the task itself (end(kind)); it runs on a copy.
  const std::function<void()> cancel = it->second.cancel;
  tasks_.erase(it);
  cancel();
  update();
  emit cancelled(kind);
}
} // namespace aniso
