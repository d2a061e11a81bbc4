// Maps and environment docks: the TPR and tangent editors compose texts that the core parsers
// read back as the chosen pattern/model, a map that fails to load is reported once and leaves
// the scene as it was, the environment list offers the built-ins and the files of its
// directory with thumbnails (tone-mapped as stated in EnvironmentThumbnails.h, recomputed here),
// and choosing one sets the environment.
#include "core/env/environment.h"
#include "core/error.h"
#include "core/image/image.h"
#include "core/maps/tpr_map.h"
#include "scene/SceneEditor.h"
#include "widgets/AssetControls.h"
#include "widgets/EnvironmentDock.h"
#include "widgets/EnvironmentThumbnails.h"
#include "widgets/MapsDock.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLineEdit>
#include <QListWidget>
#include <QMimeData>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QUrl>
#include <QtTest>
#include <cmath>

using aniso::textValue;

namespace
{
// Loads like the application does: readImage, whose errors name the file.
void installImageValidator(aniso::SceneModel& model, const char* key)
{
  model.setValidator(key,
                     [](const std::string& text, const std::string&)
                     {
                       if (!text.empty())
                       {
                         aniso::readImage(text);
                       }
                     });
}

void writeGarbage(const QString& path)
{
  QFile f(path);
  QVERIFY(f.open(QIODevice::WriteOnly));
  f.write("this is not an image, only text with an image's name");
}
} // namespace

class TestMapsEnvironment : public QObject
{
  Q_OBJECT

private slots:
  // The TPR editor: a pattern chosen in the combo becomes model text that parseTprPattern
  // reads as that pattern; texts from the model show their pattern and parameters.
  void tprEditorComposesParsableText()
  {
    aniso::SceneModel model;
    aniso::SceneEditor editor(&model);
    aniso::MapsDock dock(&editor);
    aniso::TprEditor* tpr = dock.tprEditor();
    QComboBox* box = tpr->patternBox();
    emit box->activated(box->findData("circular"));
    QCOMPARE(model.text("tpr"), std::string("circular:0.5,0.5"));
    QCOMPARE(aniso::parseTprPattern(model.text("tpr")).pattern, aniso::TprPattern::Circular);
    model.setValue("tpr", textValue("spiral:0.25,0.75:30"));
    QCOMPARE(box->currentData().toString(), QString("spiral"));
    QCOMPARE(tpr->text(), QString("spiral:0.25,0.75:30"));
    tpr->findChild<QDoubleSpinBox*>("tpr-pitch")->setValue(45.0);
    const aniso::TprParams p = aniso::parseTprPattern(model.text("tpr"));
    QCOMPARE(p.pattern, aniso::TprPattern::Spiral);
    QCOMPARE(p.pitchDegrees, 45.0);
    QCOMPARE(p.centre.x, 0.25);
    emit box->activated(box->findData(""));
    QCOMPARE(model.text("tpr"), std::string());
  }

  // The tangent editor writes the CLI spelling of the brushing model and keeps an around
  // model's centre.
  void tangentEditorComposesModels()
  {
    aniso::SceneModel model;
    aniso::SceneEditor editor(&model);
    aniso::MapsDock dock(&editor);
    aniso::TangentEditor* t = dock.tangentEditor();
    QCOMPARE(t->text(), QString("auto"));
    emit t->kindBox()->activated(t->kindBox()->findData("around"));
    QCOMPARE(model.text("tangents"), std::string("around:0,0,1"));
    t->component(0)->setValue(1.0);
    QCOMPARE(model.text("tangents"), std::string("around:1,0,1"));
    model.setValue("tangents", textValue("around:0,0,1@1,2,3"));
    t->component(2)->setValue(2.0);
    QCOMPARE(model.text("tangents"), std::string("around:0,0,2@1,2,3"));
  }

  // array:NAME: the edited parts' vector arrays (SceneModel::setPartArrays, as the window tells
  // them) are offered; choosing the kind takes the first, picking another writes it, a model
  // text shows its name; face-u and face-v show as themselves (the texts are BrushingModel.h's
  // spellings).
  void tangentEditorOffersThePartsVectorArrays()
  {
    aniso::SceneModel model;
    aniso::SceneEditor editor(&model);
    aniso::MapsDock dock(&editor);
    aniso::TangentEditor* t = dock.tangentEditor();
    QComboBox* arrays = t->arrayBox();
    QCOMPARE(arrays->count(), 0);
    const std::string part = model.parts().front().name;
    QSignalSpy told(&model, &aniso::SceneModel::partArraysChanged);
    model.setPartArrays(part, {"velocity", "fibre direction"});
    model.setPartArrays(part, {"velocity", "fibre direction"}); // the same: no signal
    QCOMPARE(told.count(), 1);
    QCOMPARE(arrays->count(), 2);
    QCOMPARE(arrays->itemText(1), QString("fibre direction"));
    emit t->kindBox()->activated(t->kindBox()->findData("array"));
    QCOMPARE(model.text("tangents"), std::string("array:velocity"));
    QVERIFY(arrays->isVisibleTo(t));
    arrays->setCurrentIndex(1);
    emit arrays->activated(1);
    QCOMPARE(model.text("tangents"), std::string("array:fibre direction"));
    model.setValue("tangents", textValue("array:velocity"));
    QCOMPARE(arrays->currentText(), QString("velocity"));
    model.setValue("tangents", textValue("face-v"));
    QCOMPARE(t->kindBox()->currentData().toString(), QString("face-v"));
    QCOMPARE(t->text(), QString("face-v"));
    QVERIFY(!arrays->isVisibleTo(t));
  }

  // A corrupt or missing map is reported once, naming the file; the model and the row keep
  // the previous map. A good map is taken.
  void badMapIsReportedAndChangesNothing()
  {
    QTemporaryDir dir;
    const QString good = dir.filePath("normal.exr");
    aniso::Image flat(4, 4, 3);
    for (std::size_t i = 2; i < flat.data.size(); i += 3)
    {
      flat.data[i] = 1.0f;
    }
    aniso::writeImage(good.toStdString(), flat);
    const QString bad = dir.filePath("corrupt.png");
    writeGarbage(bad);

    aniso::SceneModel model;
    installImageValidator(model, "normal-map");
    aniso::SceneEditor editor(&model);
    aniso::MapsDock dock(&editor);
    QSignalSpy errors(&dock, &aniso::MapsDock::errorOccurred);
    aniso::FileRow* row = dock.fileRow("normal-map");
    emit row->edited(good);
    QCOMPARE(model.text("normal-map"), good.toStdString());
    QCOMPARE(errors.count(), 0);
    for (const QString& path : {bad, dir.filePath("missing.exr")})
    {
      emit row->edited(path);
      QCOMPARE(model.text("normal-map"), good.toStdString());
      QCOMPARE(row->text(), good);
    }
    QCOMPARE(errors.count(), 2);
    QVERIFY(errors.at(0).at(0).toString().startsWith(bad + ": "));
    QCOMPARE(editor.undoStack()->count(), 1);
  }

  // A file dropped on a map's row is that map; a corrupt one is refused like a chosen one.
  void droppedFileIsTheMap()
  {
    QTemporaryDir dir;
    const QString good = dir.filePath("height.exr");
    aniso::writeImage(good.toStdString(), aniso::Image(4, 4, 1));
    const QString bad = dir.filePath("height.png");
    writeGarbage(bad);
    aniso::SceneModel model;
    installImageValidator(model, "height-map");
    aniso::SceneEditor editor(&model);
    aniso::MapsDock dock(&editor);
    QSignalSpy errors(&dock, &aniso::MapsDock::errorOccurred);
    aniso::FileRow* row = dock.fileRow("height-map");
    const auto drop = [row](const QString& path)
    {
      QMimeData mime;
      mime.setUrls({QUrl::fromLocalFile(path)});
      QDropEvent event(QPointF(5, 5), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
      // Straight to the widget's handler: QApplication routes drops only during a real drag.
      static_cast<QObject*>(row)->event(&event);
    };
    drop(good);
    QVERIFY2(errors.isEmpty(), errors.isEmpty() ? "" : qPrintable(errors.at(0).at(0).toString()));
    QCOMPARE(model.text("height-map"), good.toStdString());
    drop(bad);
    QCOMPARE(model.text("height-map"), good.toStdString());
    QCOMPARE(row->text(), good);
    QCOMPARE(errors.count(), 1);
  }

  // A constant environment L gives thumbnail texels sRGB(ACES(0.18 L / (L + 1e-4))), by the
  // stated transform computed here independently; the size is WIDTH x WIDTH/2.
  void thumbnailFollowsItsTransform()
  {
    aniso::Image hdr(64, 32, 3);
    std::fill(hdr.data.begin(), hdr.data.end(), 3.0f);
    const aniso::Image t = aniso::toneMappedThumbnail(hdr, 16);
    QCOMPARE(t.width, 16);
    QCOMPARE(t.height, 8);
    const double x = 0.18 * 3.0 / (3.0 + 1e-4);
    const double mapped = x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14);
    const double srgb = 1.055 * std::pow(mapped, 1.0 / 2.4) - 0.055;
    for (float v : t.data)
    {
      QVERIFY(std::abs(v - srgb) < 1e-5);
    }
    QVERIFY_EXCEPTION_THROWN(aniso::toneMappedThumbnail(aniso::Image(), 16), aniso::Error);
  }

  // The list holds the built-ins and the directory's HDRIs with thumbnails (none for a corrupt
  // file); choosing an item sets the environment, a corrupt one is reported and changes nothing.
  void environmentListOffersAndSelects()
  {
    QTemporaryDir dir;
    aniso::Image sky(32, 16, 3);
    std::fill(sky.data.begin(), sky.data.end(), 0.5f);
    aniso::writeImage(dir.filePath("sky.exr").toStdString(), sky);
    writeGarbage(dir.filePath("broken.exr"));

    aniso::SceneModel model;
    model.setValidator("env", [](const std::string& text, const std::string&)
                       { aniso::openEnvironment(text); });
    aniso::SceneEditor editor(&model);
    aniso::EnvironmentDock dock(&editor, dir.path());
    QSignalSpy ready(&dock, &aniso::EnvironmentDock::thumbnailsReady);
    QSignalSpy errors(&dock, &aniso::EnvironmentDock::errorOccurred);
    QListWidget* list = dock.list();
    QCOMPARE(list->count(), 4);
    QCOMPARE(list->currentItem()->data(Qt::UserRole).toString(), QString("builtin:studio"));
    QVERIFY(ready.wait(10000));
    QCOMPARE(dock.pendingThumbnails(), 0);
    QListWidgetItem* skyItem = nullptr;
    QListWidgetItem* brokenItem = nullptr;
    for (int i = 0; i < list->count(); ++i)
    {
      const QString spec = list->item(i)->data(Qt::UserRole).toString();
      QVERIFY(spec.endsWith("broken.exr") || !list->item(i)->icon().isNull());
      if (spec.endsWith("sky.exr"))
      {
        skyItem = list->item(i);
      }
      if (spec.endsWith("broken.exr"))
      {
        brokenItem = list->item(i);
      }
    }
    QVERIFY(skyItem && brokenItem);
    QVERIFY(brokenItem->icon().isNull());
    emit list->itemClicked(skyItem);
    QCOMPARE(model.text("env"), dir.filePath("sky.exr").toStdString());
    emit list->itemClicked(brokenItem);
    QCOMPARE(model.text("env"), dir.filePath("sky.exr").toStdString());
    QCOMPARE(errors.count(), 1);
    QCOMPARE(list->currentItem(), skyItem);
    // An environment set from elsewhere (a session) that is not listed gets an item.
    const QString other = dir.filePath("other.exr");
    aniso::writeImage(other.toStdString(), sky);
    model.setValue("env", textValue(other.toStdString()));
    QCOMPARE(list->count(), 5);
    QCOMPARE(list->currentItem()->data(Qt::UserRole).toString(), other);
  }
};

QTEST_MAIN(TestMapsEnvironment)
#include "test_maps_environment.moc"
