#pragma once
// The window's preferences (Edit > Preferences): what the window keeps in QSettings between
// runs, edited in one dialog. Load and save go through QSettings (the application's
// organisation and name; tests set their own).
#include <QDialog>
#include <QString>

class QCheckBox;
class QDialogButtonBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;

namespace aniso
{
struct Preferences
{
  // Screenshots and turntables are offered in this folder; empty: the user's Pictures folder.
  // Each export sets it to the folder written to.
  QString screenshotFolder;
  int recentCount = 8;      // files File > Open Recent keeps, 0 to 30
  bool clearRecent = false; // applying empties File > Open Recent
  // The lookup tables' cache (core/lut/lut_cache.h): bytes kept in memory and on disk, MiB.
  int lutMemoryMiB = 256;
  int lutDiskMiB = 512;
  // The window's docks and size as left at the last exit; false: the default layout at the
  // next start.
  bool restoreLayout = true;

  bool operator==(const Preferences& o) const;
  bool operator!=(const Preferences& o) const { return !(*this == o); }
};

// The QSettings keys (also read where the value is used).
namespace preference_keys
{
inline const char* const kScreenshotFolder = "screenshot/folder";
inline const char* const kRecentCount = "recent/count";
inline const char* const kRecentFiles = "recentFiles";
inline const char* const kLutMemory = "lut/memoryMiB";
inline const char* const kLutDisk = "lut/diskMiB";
inline const char* const kRestoreLayout = "window/restoreLayout";
} // namespace preference_keys

// The saved preferences, defaults where none is saved, values clamped to their ranges.
Preferences loadPreferences();
// Writes every value (clearRecent empties the recent files).
void savePreferences(const Preferences& preferences);

class PreferencesDialog : public QDialog
{
  Q_OBJECT

public:
  // Shows PREFERENCES; Apply and OK emit applied with the edited values.
  explicit PreferencesDialog(const Preferences& preferences, const QString& lutDirectory,
                             QWidget* parent = nullptr);

  Preferences preferences() const;
  void setPreferences(const Preferences& preferences);

  QLineEdit* screenshotFolderEdit() const { return screenshotFolder_; }
  QSpinBox* recentCountBox() const { return recentCount_; }
  QPushButton* clearRecentButton() const { return clearRecent_; }
  QSpinBox* lutMemoryBox() const { return lutMemory_; }
  QSpinBox* lutDiskBox() const { return lutDisk_; }
  QDialogButtonBox* buttons() const { return buttons_; }

signals:
  void applied(const Preferences& preferences);

private:
  QLineEdit* screenshotFolder_;
  QSpinBox* recentCount_;
  QPushButton* clearRecent_;
  QSpinBox* lutMemory_;
  QSpinBox* lutDisk_;
  QCheckBox* restoreLayout_;
  QDialogButtonBox* buttons_;
};
} // namespace aniso
