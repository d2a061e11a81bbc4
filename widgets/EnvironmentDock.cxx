#include "widgets/EnvironmentDock.h"

#include "core/error.h"
#include "widgets/EnvironmentThumbnails.h"
#include "widgets/ParameterPanel.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFutureWatcher>
#include <QGroupBox>
#include <QListWidget>
#include <QPushButton>
#include <QSignalBlocker>
#include <QTimer>
#include <QVBoxLayout>
#include <QtConcurrent>

namespace aniso
{
namespace
{
constexpr int kThumbnailWidth = 112;
constexpr int kSpecRole = Qt::UserRole;
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
      panel_(new ParameterPanel(editor, this)), list_(new QListWidget(this))
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
          });

  auto* top = new QWidget(this);
  auto* layout = new QVBoxLayout(top);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(list_);
  layout->addWidget(open);
  setWidget(scrollableColumn({top, panel_}, this));
  sync();
}

EnvironmentDock::~EnvironmentDock() = default;

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
} // namespace aniso
