#include "widgets/EnvironmentDock.h"

#include "core/env/env_source_text.h"
#include "core/env/env_sources.h"
#include "core/env/environment.h"
#include "core/error.h"
#include "widgets/EnvironmentThumbnails.h"
#include "widgets/ParameterPanel.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFutureWatcher>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QSignalBlocker>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>
#include <QtConcurrent>
#include <algorithm>
#include <atomic>
#include <deque>

namespace aniso
{
namespace
{
constexpr int kThumbnailWidth = 112;
constexpr int kPreviewWidth = 224;
constexpr int kSpecRole = Qt::UserRole;

// What the worker hands the dock: the analysis and the marked preview, or why it failed.
struct SourcesOfEnvironment
{
  QString spec;
  std::shared_ptr<const EnvAnalysis> analysis;
  QImage preview;
  QString error;
};

// ALIVE false (the dock is gone) skips the work not yet begun: the pool's queue would otherwise
// hold the analyses of closed docks, and the application's exit wait for them.
SourcesOfEnvironment analysed(const QString& spec, const std::atomic<bool>& alive)
{
  SourcesOfEnvironment result;
  result.spec = spec;
  try
  {
    if (!alive)
    {
      return result;
    }
    const std::shared_ptr<Environment> env = openEnvironment(spec.toStdString());
    if (!alive)
    {
      return result;
    }
    result.analysis = sharedEnvironmentAnalysis(*env);
    result.preview = markedSources(environmentThumbnail(*env, kPreviewWidth), *result.analysis);
  }
  catch (const std::exception& e)
  {
    // Error's messages and the standard library's (bad_alloc on a huge file) alike.
    result.error = QString::fromStdString(e.what());
  }
  return result;
}

// The analyses shown last, in any dock of the process, the latest first: sharedEnvironmentAnalysis
// keeps a result only while someone holds it, so going back to an environment, or a new window
// on the same one, finds it here instead of analysing again. At most kRecentAnalyses, and
// kRecentBytes of their images (an HDRI of 1024 x 512 holds 12 MB). UI thread only.
constexpr std::size_t kRecentAnalyses = 4;
constexpr std::size_t kRecentBytes = std::size_t(64) << 20;

void keepRecent(const std::shared_ptr<const EnvAnalysis>& analysis)
{
  static std::deque<std::shared_ptr<const EnvAnalysis>> recent;
  recent.erase(std::remove(recent.begin(), recent.end(), analysis), recent.end());
  recent.push_front(analysis);
  std::size_t bytes = 0;
  for (auto it = recent.begin(); it != recent.end(); ++it)
  {
    bytes += ((*it)->excess.data.size() + (*it)->residual.data.size()) * sizeof(float);
    if (it != recent.begin() &&
        (std::size_t(it - recent.begin()) >= kRecentAnalyses || bytes > kRecentBytes))
    {
      recent.erase(it, recent.end());
      break;
    }
  }
}

// The name the user knows an environment by: a file's name, or the built-in's spec.
QString environmentName(const QString& spec)
{
  return spec.startsWith("builtin:") ? spec : QFileInfo(spec).fileName();
}

QString degreesText(double degrees)
{
  return QString::number(degrees, 'f', 1) + QChar(0x00B0);
}
} // namespace

QString blenderHdriDirectory()
{
  return "/usr/share/blender/datafiles/studiolights/world";
}

QString environmentFileFilter()
{
  return QObject::tr("Environments (*.hdr *.exr *.tif *.tiff *.png *.jpg *.jpeg);;"
                     "All files (*)");
}

EnvironmentDock::EnvironmentDock(SceneEditor* editor, const QString& hdriDirectory, QWidget* parent)
    : QDockWidget(tr("Environment"), parent), editor_(editor),
      panel_(new ParameterPanel(editor, this)), list_(new QListWidget(this)),
      preview_(new QLabel(this)), sources_(new QTableWidget(0, 5, this)), summary_(new QLabel(this))
{
  setObjectName("EnvironmentDock");
  list_->setObjectName("environments");
  list_->setViewMode(QListView::IconMode);
  list_->setIconSize(QSize(kThumbnailWidth, kThumbnailWidth / 2));
  list_->setFlow(QListView::LeftToRight);
  list_->setWrapping(true);
  list_->setResizeMode(QListView::Adjust);
  list_->setMovement(QListView::Static);
  list_->setUniformItemSizes(true);
  list_->setGridSize(QSize(kThumbnailWidth + 12, kThumbnailWidth / 2 + 28));
  list_->setTextElideMode(Qt::ElideRight);
  list_->setMinimumHeight(3 * (kThumbnailWidth / 2 + 28) + 8);

  addItem(tr("Studio (built-in)"), "builtin:studio");
  addItem(tr("White (built-in)"), "builtin:white");
  const QDir dir(hdriDirectory);
  const QStringList files =
      dir.entryList({"*.exr", "*.hdr"}, QDir::Files | QDir::Readable, QDir::Name);
  for (const QString& file : files)
  {
    QString name = QFileInfo(file).completeBaseName();
    name[0] = name[0].toUpper();
    addItem(name, dir.absoluteFilePath(file));
  }
  connect(list_, &QListWidget::itemClicked, this,
          [this](QListWidgetItem* item) { select(item->data(kSpecRole).toString()); });
  connect(list_, &QListWidget::itemActivated, this,
          [this](QListWidgetItem* item) { select(item->data(kSpecRole).toString()); });

  auto* open = new QPushButton(tr("Open file…"), this);
  open->setObjectName("open-environment");
  connect(open, &QPushButton::clicked, this, &EnvironmentDock::openFile);

  for (const char* key :
       {"env-rotation", "exposure", "background", "background-color", "tone-mapping", "cube-size"})
  {
    panel_->addParameter(key);
  }
  connect(panel_, &ParameterPanel::errorOccurred, this, &EnvironmentDock::errorOccurred);
  connect(editor->model(), &SceneModel::valueChanged, this,
          [this](const QString& key)
          {
            if (key == "env")
            {
              sync();
            }
            else if (key == "env-rotation")
            {
              showSourceRows(); // the world's azimuths
            }
          });

  preview_->setObjectName("environment-preview");
  preview_->setAlignment(Qt::AlignCenter);
  preview_->setMinimumHeight(kPreviewWidth / 2);
  preview_->setToolTip(tr("The environment's bright sources, marked where they are"));
  sources_->setObjectName("environment-sources");
  sources_->setHorizontalHeaderLabels(
      {tr("Kind"), tr("Azimuth"), tr("Elevation"), tr("Solid angle"), tr("Power")});
  sources_->horizontalHeaderItem(1)->setToolTip(
      tr("Degrees in the world (after the rotation) from -Y, counter-clockwise seen from above, "
         "as aniso render --azimuth takes them"));
  sources_->horizontalHeaderItem(2)->setToolTip(tr("Degrees above the horizon"));
  sources_->horizontalHeaderItem(3)->setToolTip(
      tr("Steradians, and the apex angle of a cone of that solid angle"));
  sources_->horizontalHeaderItem(4)->setToolTip(tr("Share of the environment's power"));
  sources_->verticalHeader()->hide();
  sources_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  sources_->horizontalHeader()->setStretchLastSection(true);
  sources_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  sources_->setSelectionMode(QAbstractItemView::NoSelection);
  sources_->setMaximumHeight(5 * sources_->verticalHeader()->defaultSectionSize() +
                             sources_->horizontalHeader()->sizeHint().height() + 4);
  summary_->setObjectName("environment-summary");
  summary_->setWordWrap(true);
  auto* analysis = new QGroupBox(tr("Sources"), this);
  auto* analysisLayout = new QVBoxLayout(analysis);
  analysisLayout->addWidget(preview_);
  analysisLayout->addWidget(summary_);
  analysisLayout->addWidget(sources_);

  auto* top = new QWidget(this);
  auto* layout = new QVBoxLayout(top);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(list_);
  layout->addWidget(open);
  setWidget(scrollableColumn({top, analysis, panel_}, this));
  sync();
}

EnvironmentDock::~EnvironmentDock()
{
  *alive_ = false;
}

QListWidgetItem* EnvironmentDock::addItem(const QString& label, const QString& spec)
{
  auto* item = new QListWidgetItem(label, list_);
  item->setData(kSpecRole, spec);
  item->setToolTip(spec);
  // The preview is made on a worker thread; the item gets it when ready.
  ++pending_;
  auto* watcher = new QFutureWatcher<QImage>(this);
  connect(watcher, &QFutureWatcher<QImage>::finished, this,
          [this, watcher, spec]
          {
            const QImage image = watcher->result();
            watcher->deleteLater();
            for (int i = 0; i < list_->count(); ++i)
            {
              QListWidgetItem* it = list_->item(i);
              if (it->data(kSpecRole).toString() == spec && !image.isNull())
              {
                it->setIcon(QIcon(QPixmap::fromImage(image)));
              }
            }
            if (--pending_ == 0)
            {
              emit thumbnailsReady();
            }
          });
  const std::string path = spec.toStdString();
  watcher->setFuture(QtConcurrent::run(
      [path]
      {
        try
        {
          return environmentThumbnail(path, kThumbnailWidth);
        }
        catch (const Error&)
        {
          // An unreadable file keeps a plain item; choosing it reports the error.
          return QImage();
        }
      }));
  return item;
}

void EnvironmentDock::openFile()
{
  const QString path = QFileDialog::getOpenFileName(this, tr("Open an environment"), QString(),
                                                    environmentFileFilter());
  if (!path.isEmpty())
  {
    select(path);
  }
}

void EnvironmentDock::select(const QString& spec)
{
  if (opener_)
  {
    // The list shows the scene's environment until the opener changes it.
    opener_(spec);
    sync();
    return;
  }
  panel_->submit("env", textValue(spec.toStdString()), false);
  sync();
}

void EnvironmentDock::sync()
{
  const QString current = QString::fromStdString(editor_->model()->text("env"));
  QListWidgetItem* match = nullptr;
  for (int i = 0; i < list_->count(); ++i)
  {
    if (list_->item(i)->data(kSpecRole).toString() == current)
    {
      match = list_->item(i);
    }
  }
  if (!match)
  {
    match = addItem(QFileInfo(current).fileName(), current);
  }
  analyse(current);
  const QSignalBlocker block(list_);
  list_->setCurrentItem(match);
  // Once the list has laid its items out.
  QTimer::singleShot(0, list_,
                     [this]
                     {
                       if (QListWidgetItem* item = list_->currentItem())
                       {
                         list_->scrollToItem(item);
                       }
                     });
}

void EnvironmentDock::analyse(const QString& spec)
{
  if (spec == requestedSpec_)
  {
    return;
  }
  requestedSpec_ = spec;
  summary_->setText(tr("Analysing %1…").arg(environmentName(spec)));
  // One analysis at a time: the running one's end starts the latest request.
  if (!analysing_)
  {
    startAnalysis(spec);
  }
}

void EnvironmentDock::startAnalysis(const QString& spec)
{
  analysing_ = true;
  auto* watcher = new QFutureWatcher<SourcesOfEnvironment>(this);
  connect(watcher, &QFutureWatcher<SourcesOfEnvironment>::finished, this,
          [this, watcher]
          {
            const SourcesOfEnvironment result = watcher->result();
            watcher->deleteLater();
            analysing_ = false;
            if (result.spec != requestedSpec_)
            {
              startAnalysis(requestedSpec_);
              return;
            }
            sources_->setRowCount(0);
            if (!result.analysis)
            {
              analysedSpec_.clear();
              analysis_.reset();
              preview_->clear();
              const QString name = environmentName(result.spec);
              summary_->setText(tr("No analysis of %1").arg(name));
              emit errorOccurred(tr("%1: environment analysis failed: %2").arg(name, result.error));
              emit sourcesShown();
              return;
            }
            analysedSpec_ = result.spec;
            analysis_ = result.analysis;
            keepRecent(analysis_);
            preview_->setPixmap(QPixmap::fromImage(result.preview));
            summary_->setText(QString::fromStdString(analysisSummary(*analysis_)));
            showSourceRows();
            emit sourcesShown();
          });
  watcher->setFuture(QtConcurrent::run([spec, alive = alive_] { return analysed(spec, *alive); }));
}

void EnvironmentDock::showSourceRows()
{
  sources_->setRowCount(analysis_ ? int(analysis_->sources.size()) : 0);
  const double rotation = editor_->model()->real("env-rotation");
  for (int row = 0; row < sources_->rowCount(); ++row)
  {
    const EnvSource& source = analysis_->sources[std::size_t(row)];
    const SkyAngles angles = skyAnglesOf(source.direction, rotation);
    const QStringList cells = {
        QString::fromUtf8(spelling(source.kind)), degreesText(angles.azimuthDegrees),
        degreesText(angles.elevationDegrees),
        QString::number(source.solidAngle, 'g', 2) + " sr (" +
            QString::number(equivalentDiameterDegrees(source.solidAngle), 'g', 2) + QChar(0x00B0) +
            ")",
        QString::fromStdString(percentText(source.powerShare))};
    for (int column = 0; column < cells.size(); ++column)
    {
      sources_->setItem(row, column, new QTableWidgetItem(cells[column]));
    }
  }
}
} // namespace aniso
