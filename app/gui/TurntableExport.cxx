#include "app/gui/TurntableExport.h"

#include "app/gui/StandardViews.h"
#include "app/gui/ViewCamera.h"
#include "app/render_turntable.h"
#include "core/error.h"

#include <QCheckBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QProcess>
#include <QSpinBox>
#include <QStandardPaths>
#include <QToolButton>
#include <algorithm>
#include <cmath>

namespace aniso
{
void checkTurntableOptions(const TurntableOptions& o, const std::string& subject)
{
  if (o.frames < 1 || o.frames > 3600)
  {
    throw errorAbout(subject, "a turntable has 1 to 3600 frames");
  }
  if (o.width < 16 || o.height < 16 || o.width > 8192 || o.height > 8192)
  {
    throw errorAbout(subject, "a turntable frame is 16 to 8192 pixels wide and high");
  }
  if (!(std::abs(o.elevationDegrees) <= 89.0))
  {
    throw errorAbout(subject, "the turntable's elevation is -89 to 89 degrees");
  }
  if (o.framesPerSecond < 1 || o.framesPerSecond > 120)
  {
    throw errorAbout(subject, "the video has 1 to 120 frames per second");
  }
  if (o.prefix.isEmpty())
  {
    throw errorAbout(subject, "no file name for the frames");
  }
}

std::vector<CameraState> turntableCameras(const CameraState& start, const DrawingFrame& drawing,
                                          int frames, double elevationDegrees)
{
  double azimuth = 0.0;
  double elevation = 0.0;
  azimuthElevationOf(start, drawing, azimuth, elevation);
  std::vector<CameraState> cameras;
  cameras.reserve(std::size_t(std::max(frames, 0)));
  for (int k = 0; k < frames; ++k)
  {
    cameras.push_back(orbitCamera(start, drawing, azimuth + 360.0 * k / frames, elevationDegrees));
  }
  return cameras;
}

QString turntableFramePath(const QString& prefix, int frame, int frames)
{
  // The command line's names (aniso render --turntable -o PREFIX.png).
  return QString::fromStdString(
      cli::turntableFramePath((prefix + ".png").toStdString(), frame, frames));
}

QString ffmpegExecutable()
{
  return QStandardPaths::findExecutable("ffmpeg");
}

namespace
{
// PREFIX.mp4 from the frames; the reason on failure.
QString encodeVideo(const TurntableOptions& o, QString& video)
{
  const QString ffmpeg = ffmpegExecutable();
  if (ffmpeg.isEmpty())
  {
    return QObject::tr("ffmpeg is not installed: no video");
  }
  const QString path = o.prefix + ".mp4";
  QProcess process;
  process.setProcessChannelMode(QProcess::MergedChannels);
  process.start(ffmpeg,
                {"-y", "-loglevel", "error", "-framerate", QString::number(o.framesPerSecond), "-i",
                 o.prefix + "_%0" + QString::number(cli::turntableDigits(o.frames)) + "d.png",
                 // yuv420p, which players expect, needs even sizes.
                 "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-pix_fmt", "yuv420p", path});
  if (!process.waitForFinished(600000) || process.exitStatus() != QProcess::NormalExit ||
      process.exitCode() != 0)
  {
    const QString output = QString::fromLocal8Bit(process.readAll()).trimmed();
    return QObject::tr("%1: ffmpeg failed: %2")
        .arg(path, output.isEmpty() ? process.errorString() : output.section('\n', -1));
  }
  video = path;
  return {};
}
} // namespace

TurntableResult exportTurntable(RenderSettings settings, const std::vector<CameraState>& cameras,
                                const TurntableOptions& options,
                                const std::function<bool(int)>& progress)
{
  checkTurntableOptions(options, options.prefix.toStdString());
  const QString folder = QFileInfo(options.prefix).absolutePath();
  if (!QDir().mkpath(folder))
  {
    throw errorAbout(folder.toStdString(), "cannot make the folder");
  }
  settings.width = options.width;
  settings.height = options.height;
  TurntableResult result;
  const int n = static_cast<int>(cameras.size());
  for (int k = 0; k < n; ++k)
  {
    if (progress && !progress(k))
    {
      result.cancelled = true;
      return result;
    }
    settings.camera = placementOf(cameras[std::size_t(k)]);
    const RenderResult frame = renderOffscreen(settings);
    const QString path = turntableFramePath(options.prefix, k, n);
    // As screenshots are written: alpha only with a transparent background.
    cli::writeRendered(path.toStdString(), frame,
                       settings.display.background == BackgroundMode::Transparent);
    result.frames << path;
  }
  if (progress && !progress(n))
  {
    result.cancelled = true;
    return result;
  }
  if (options.video)
  {
    result.videoError = encodeVideo(options, result.video);
  }
  return result;
}

bool askTurntableOptions(QWidget* parent, TurntableOptions& options)
{
  QDialog dialog(parent);
  dialog.setWindowTitle(QObject::tr("Export turntable"));
  auto* pathEdit = new QLineEdit(options.prefix, &dialog);
  pathEdit->setToolTip(QObject::tr("Frames PREFIX_0000.png, …; the video PREFIX.mp4"));
  auto* browse = new QToolButton(&dialog);
  browse->setText(QObject::tr("…"));
  auto* pathRow = new QWidget(&dialog);
  auto* pathLayout = new QHBoxLayout(pathRow);
  pathLayout->setContentsMargins(0, 0, 0, 0);
  pathLayout->addWidget(pathEdit, 1);
  pathLayout->addWidget(browse);
  QObject::connect(browse, &QToolButton::clicked, &dialog,
                   [&dialog, pathEdit]
                   {
                     const QString chosen = QFileDialog::getSaveFileName(
                         &dialog, QObject::tr("Export turntable"), pathEdit->text(),
                         QObject::tr("PNG frames (*)"));
                     if (!chosen.isEmpty())
                     {
                       pathEdit->setText(chosen);
                     }
                   });
  auto* frames = new QSpinBox(&dialog);
  frames->setRange(1, 3600);
  frames->setValue(options.frames);
  auto* width = new QSpinBox(&dialog);
  width->setRange(16, 8192);
  width->setValue(options.width);
  auto* height = new QSpinBox(&dialog);
  height->setRange(16, 8192);
  height->setValue(options.height);
  auto* sizeRow = new QWidget(&dialog);
  auto* sizeLayout = new QHBoxLayout(sizeRow);
  sizeLayout->setContentsMargins(0, 0, 0, 0);
  sizeLayout->addWidget(width);
  sizeLayout->addWidget(new QLabel(QObject::tr("×"), &dialog));
  sizeLayout->addWidget(height);
  auto* elevation = new QDoubleSpinBox(&dialog);
  elevation->setRange(-89.0, 89.0);
  elevation->setSuffix(QObject::tr("°"));
  elevation->setValue(options.elevationDegrees);
  const bool ffmpeg = !ffmpegExecutable().isEmpty();
  auto* video =
      new QCheckBox(ffmpeg ? QObject::tr("Also a video (PREFIX.mp4, %1 frames per second)")
                                 .arg(options.framesPerSecond)
                           : QObject::tr("A video needs ffmpeg, which is not installed"),
                    &dialog);
  video->setChecked(ffmpeg && options.video);
  video->setEnabled(ffmpeg);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &dialog);
  QObject::connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
  QObject::connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
  auto* form = new QFormLayout(&dialog);
  form->addRow(QObject::tr("Files"), pathRow);
  form->addRow(QObject::tr("Frames"), frames);
  form->addRow(QObject::tr("Size"), sizeRow);
  form->addRow(QObject::tr("Elevation"), elevation);
  form->addRow(QString(), video);
  form->addRow(buttons);
  if (dialog.exec() != QDialog::Accepted)
  {
    return false;
  }
  options.prefix = pathEdit->text();
  options.frames = frames->value();
  options.width = width->value();
  options.height = height->value();
  options.elevationDegrees = elevation->value();
  options.video = video->isChecked();
  return true;
}
} // namespace aniso
