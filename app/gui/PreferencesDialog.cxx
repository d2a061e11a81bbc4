#include "app/gui/PreferencesDialog.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QToolButton>
#include <algorithm>

namespace aniso
{
namespace
{
constexpr int kMaxRecent = 30;
constexpr int kMaxLutMiB = 65536;

int clampedInt(const QSettings& settings, const char* key, int fallback, int low, int high)
{
  bool ok = false;
  const int value = settings.value(key, fallback).toInt(&ok);
  return ok ? std::clamp(value, low, high) : fallback;
}
} // namespace

bool Preferences::operator==(const Preferences& o) const
{
  return screenshotFolder == o.screenshotFolder && recentCount == o.recentCount &&
         clearRecent == o.clearRecent && lutMemoryMiB == o.lutMemoryMiB &&
         lutDiskMiB == o.lutDiskMiB && restoreLayout == o.restoreLayout;
}

Preferences loadPreferences()
{
  using namespace preference_keys;
  const QSettings settings;
  Preferences p;
  p.screenshotFolder = settings.value(kScreenshotFolder).toString();
  p.recentCount = clampedInt(settings, kRecentCount, p.recentCount, 0, kMaxRecent);
  p.lutMemoryMiB = clampedInt(settings, kLutMemory, p.lutMemoryMiB, 16, kMaxLutMiB);
  p.lutDiskMiB = clampedInt(settings, kLutDisk, p.lutDiskMiB, 0, kMaxLutMiB);
  p.restoreLayout = settings.value(kRestoreLayout, true).toBool();
  return p;
}

void savePreferences(const Preferences& p)
{
  using namespace preference_keys;
  QSettings settings;
  settings.setValue(kScreenshotFolder, p.screenshotFolder);
  settings.setValue(kRecentCount, p.recentCount);
  settings.setValue(kLutMemory, p.lutMemoryMiB);
  settings.setValue(kLutDisk, p.lutDiskMiB);
  settings.setValue(kRestoreLayout, p.restoreLayout);
  QStringList recent = settings.value(kRecentFiles).toStringList();
  if (p.clearRecent)
  {
    recent.clear();
  }
  while (recent.size() > p.recentCount)
  {
    recent.removeLast();
  }
  settings.setValue(kRecentFiles, recent);
}

PreferencesDialog::PreferencesDialog(const Preferences& preferences, const QString& lutDirectory,
                                     QWidget* parent)
    : QDialog(parent), screenshotFolder_(new QLineEdit(this)), recentCount_(new QSpinBox(this)),
      clearRecent_(new QPushButton(tr("Clear"), this)), lutMemory_(new QSpinBox(this)),
      lutDisk_(new QSpinBox(this)),
      restoreLayout_(new QCheckBox(tr("Restore the docks and window size at start"), this)),
      buttons_(new QDialogButtonBox(
          QDialogButtonBox::Ok | QDialogButtonBox::Apply | QDialogButtonBox::Cancel, this))
{
  setWindowTitle(tr("Preferences"));
  setObjectName("PreferencesDialog");
  screenshotFolder_->setPlaceholderText(tr("Pictures"));
  auto* browse = new QToolButton(this);
  browse->setText(tr("…"));
  auto* folderRow = new QWidget(this);
  auto* folderLayout = new QHBoxLayout(folderRow);
  folderLayout->setContentsMargins(0, 0, 0, 0);
  folderLayout->addWidget(screenshotFolder_, 1);
  folderLayout->addWidget(browse);
  connect(browse, &QToolButton::clicked, this,
          [this]
          {
            const QString folder = QFileDialog::getExistingDirectory(
                this, tr("Folder for screenshots"), screenshotFolder_->text());
            if (!folder.isEmpty())
            {
              screenshotFolder_->setText(folder);
            }
          });
  recentCount_->setRange(0, kMaxRecent);
  auto* recentRow = new QWidget(this);
  auto* recentLayout = new QHBoxLayout(recentRow);
  recentLayout->setContentsMargins(0, 0, 0, 0);
  recentLayout->addWidget(recentCount_, 1);
  recentLayout->addWidget(clearRecent_);
  clearRecent_->setCheckable(true);
  clearRecent_->setToolTip(tr("Empties File > Open Recent when applied"));
  lutMemory_->setRange(16, kMaxLutMiB);
  lutMemory_->setSuffix(tr(" MiB"));
  lutDisk_->setRange(0, kMaxLutMiB);
  lutDisk_->setSuffix(tr(" MiB"));
  auto* lutFolder = new QLabel(lutDirectory.isEmpty() ? tr("memory only") : lutDirectory, this);
  lutFolder->setTextInteractionFlags(Qt::TextSelectableByMouse);
  lutFolder->setToolTip(tr("Set by XDG_CACHE_HOME"));

  auto* form = new QFormLayout(this);
  form->addRow(tr("Screenshot folder"), folderRow);
  form->addRow(tr("Recent files"), recentRow);
  form->addRow(tr("Lookup tables in memory"), lutMemory_);
  form->addRow(tr("Lookup tables on disk"), lutDisk_);
  form->addRow(tr("Lookup-table cache"), lutFolder);
  form->addRow(QString(), restoreLayout_);
  form->addRow(buttons_);
  setPreferences(preferences);

  connect(buttons_, &QDialogButtonBox::accepted, this,
          [this]
          {
            emit applied(this->preferences());
            accept();
          });
  connect(buttons_, &QDialogButtonBox::rejected, this, &QDialog::reject);
  connect(buttons_->button(QDialogButtonBox::Apply), &QPushButton::clicked, this,
          [this]
          {
            emit applied(this->preferences());
            clearRecent_->setChecked(false); // done once
          });
}

Preferences PreferencesDialog::preferences() const
{
  Preferences p;
  p.screenshotFolder = screenshotFolder_->text().trimmed();
  p.recentCount = recentCount_->value();
  p.clearRecent = clearRecent_->isChecked();
  p.lutMemoryMiB = lutMemory_->value();
  p.lutDiskMiB = lutDisk_->value();
  p.restoreLayout = restoreLayout_->isChecked();
  return p;
}

void PreferencesDialog::setPreferences(const Preferences& p)
{
  screenshotFolder_->setText(p.screenshotFolder);
  recentCount_->setValue(p.recentCount);
  clearRecent_->setChecked(p.clearRecent);
  lutMemory_->setValue(p.lutMemoryMiB);
  lutDisk_->setValue(p.lutDiskMiB);
  restoreLayout_->setChecked(p.restoreLayout);
}
} // namespace aniso
