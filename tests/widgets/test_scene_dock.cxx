// The scene dock (widgets/SceneDock) on the offscreen platform: it lists the model's parts under
// their files with their materials, its selection is the model's both ways, its check boxes
// show and hide parts, Assign and a dropped material give the selection a library material, Make
// unique splits a material off, libraries are saved and loaded (the file read back with
// readMaterialLibrary, the independent reader), and the material dock marks the values the
// selected parts' materials differ in as mixed. Every edit is one undo step.
#include "core/parameters/material_library.h"
#include "scene/SceneEditor.h"
#include "widgets/MaterialDock.h"
#include "widgets/SceneDock.h"

#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTreeWidget>
#include <QUndoStack>
#include <QtTest>

using aniso::ScenePart;

namespace
{
ScenePart part(const std::string& name, const std::string& group, const std::string& material)
{
  ScenePart p;
  p.name = name;
  p.mesh = "/data/" + group;
  p.block = name;
  p.group = group;
  p.material = material;
  return p;
}

void gearbox(aniso::SceneModel& model)
{
  model.setParts({part("housing", "gearbox.obj", "brushed steel"),
                  part("shaft", "gearbox.obj", "turned brass"),
                  part("bolt", "bolt.stl", "brushed steel")},
                 aniso::builtinMaterials());
}

// Every label text of the dock's widgets.
QStringList labels(QWidget* dock)
{
  QStringList texts;
  for (QLabel* label : dock->findChildren<QLabel*>())
  {
    texts << label->text();
  }
  return texts;
}
} // namespace

class TestSceneDock : public QObject
{
  Q_OBJECT

private slots:
  void listsPartsUnderTheirFiles()
  {
    aniso::SceneModel model;
    aniso::SceneEditor editor(&model);
    aniso::SceneDock dock(&editor);
    gearbox(model);
    dock.setTriangleCounts([](int part) { return part == 2 ? -1LL : 100LL * (part + 1); });
    QTreeWidget* tree = dock.tree();
    QCOMPARE(tree->topLevelItemCount(), 2);
    QCOMPARE(tree->topLevelItem(0)->text(0), QString("gearbox.obj"));
    QCOMPARE(tree->topLevelItem(0)->childCount(), 2);
    QCOMPARE(dock.partItem(1)->text(0), QString("shaft"));
    QCOMPARE(dock.partItem(1)->text(1), QString("turned brass"));
    QCOMPARE(dock.partItem(1)->text(2), QString("200"));
    QCOMPARE(dock.partItem(2)->text(2), QString("not loaded"));
    // The library: the scene's materials, then the built-in metals it lacks (none here).
    QCOMPARE(dock.library()->count(), int(aniso::builtinMaterials().materials().size()));
  }

  void selectionIsTheModels()
  {
    aniso::SceneModel model;
    aniso::SceneEditor editor(&model);
    aniso::SceneDock dock(&editor);
    gearbox(model);
    dock.partItem(0)->setSelected(true);
    dock.partItem(2)->setSelected(true);
    QCOMPARE(model.selection(), (std::vector<int>{0, 2}));
    model.setSelection({1});
    QVERIFY(dock.partItem(1)->isSelected());
    QVERIFY(!dock.partItem(0)->isSelected());
    QCOMPARE(editor.undoStack()->count(), 0); // selecting is not an edit
  }

  void checkBoxesShowAndHide()
  {
    aniso::SceneModel model;
    aniso::SceneEditor editor(&model);
    aniso::SceneDock dock(&editor);
    gearbox(model);
    dock.partItem(1)->setCheckState(0, Qt::Unchecked);
    QTRY_VERIFY(!model.parts()[1].visible);
    QCOMPARE(editor.undoStack()->count(), 1);
    QCOMPARE(dock.partItem(1)->checkState(0), Qt::Unchecked);
    editor.undoStack()->undo();
    QVERIFY(model.parts()[1].visible);
    QCOMPARE(dock.partItem(1)->checkState(0), Qt::Checked);
  }

  void assignDropAndMakeUnique()
  {
    aniso::SceneModel model;
    aniso::SceneEditor editor(&model);
    aniso::SceneDock dock(&editor);
    gearbox(model);
    // The same parts keep their rows through assignments and material edits (their columns
    // updated; a tree of hundreds of parts is not made again at every slider step).
    // (A mark on each row, which a row made again would not carry.)
    constexpr int kMark = Qt::UserRole + 99;
    for (int i = 0; i < 3; ++i)
    {
      dock.partItem(i)->setData(1, kMark, i + 1);
    }
    model.setSelection({0, 1});
    dock.assignToSelection("satin gold");
    QCOMPARE(model.parts()[0].material, std::string("satin gold"));
    QCOMPARE(model.parts()[1].material, std::string("satin gold"));
    QCOMPARE(model.parts()[2].material, std::string("brushed steel"));
    QCOMPARE(dock.partItem(0)->text(1), QString("satin gold"));
    QCOMPARE(dock.partItem(2)->text(1), QString("brushed steel"));
    editor.edit("nu", aniso::numberValue(321.0));
    QCOMPARE(model.partMaterial(0).value("nu").number[0], 321.0);
    for (int i = 0; i < 3; ++i)
    {
      QCOMPARE(dock.partItem(i)->data(1, kMark).toInt(), i + 1);
    }
    // A drop on an unselected part gives it alone the material; on a selected one, the
    // selection.
    dock.dropMaterial("polished chromium", 2);
    QCOMPARE(model.parts()[2].material, std::string("polished chromium"));
    QCOMPARE(model.parts()[0].material, std::string("satin gold"));
    dock.dropMaterial("brushed copper", 1);
    QCOMPARE(model.parts()[0].material, std::string("brushed copper"));
    QCOMPARE(model.parts()[1].material, std::string("brushed copper"));
    model.setSelection({1});
    dock.uniqueButton()->click();
    QCOMPARE(model.parts()[1].material, std::string("brushed copper (shaft)"));
    QCOMPARE(dock.partItem(1)->text(1), QString("brushed copper (shaft)"));
    QCOMPARE(editor.undoStack()->count(), 5); // the n_u edit among them
  }

  void librariesAreSavedAndLoaded()
  {
    QTemporaryDir dir;
    aniso::SceneModel model;
    aniso::SceneEditor editor(&model);
    aniso::SceneDock dock(&editor);
    gearbox(model);
    model.setSelection({1});
    editor.makeUnique({1}); // alone with its material already: nothing
    editor.assignMaterial({1}, "satin gold");
    editor.makeUnique({0});
    editor.edit("nu", aniso::numberValue(42.0));
    const QString file = dir.filePath("mine.json");
    dock.saveLibrary(file);
    const aniso::MaterialLibrary written = aniso::readMaterialLibrary(file.toStdString());
    QVERIFY(written == model.materials());

    aniso::SceneModel other;
    aniso::SceneEditor otherEditor(&other);
    aniso::SceneDock otherDock(&otherEditor);
    otherDock.loadLibrary(file);
    QVERIFY(other.materials().contains("brushed steel (housing)"));
    QCOMPARE(otherEditor.undoStack()->count(), 1);
    QSignalSpy errors(&otherDock, &aniso::SceneDock::errorOccurred);
    otherDock.loadLibrary(dir.filePath("absent.json"));
    QCOMPARE(errors.count(), 1);
    QVERIFY(errors.at(0).at(0).toString().contains("absent.json"));
  }

  // Two selected parts of materials with different n_u: the material dock says n_u is mixed,
  // and not F0 where they agree.
  void mixedValuesAreMarked()
  {
    aniso::SceneModel model;
    aniso::SceneEditor editor(&model);
    aniso::MaterialDock materials(&editor);
    aniso::MaterialLibrary library;
    aniso::Material a = aniso::defaultMaterial("a");
    aniso::Material b = aniso::defaultMaterial("b");
    b.values["nu"] = aniso::numberValue(10.0);
    library.put(a);
    library.put(b);
    model.setParts({part("one", "f.obj", "a"), part("two", "f.obj", "b")}, library);
    QVERIFY(labels(&materials).contains("n_u (mixed)"));
    QVERIFY(!labels(&materials).contains("F0 (mixed)"));
    model.setSelection({0});
    QVERIFY(!labels(&materials).contains("n_u (mixed)"));
    QVERIFY(labels(&materials).contains("n_u"));
  }
};

QTEST_MAIN(TestSceneDock)
#include "test_scene_dock.moc"
