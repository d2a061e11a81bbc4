// The material dock's quality control: choosing "error" in its quality-mode box sets the model's
// quality-mode (one undoable edit), enables the error-target control and disables
// target-samples, and back; the error-target control edits the model's error-target; a mode
// changed elsewhere (a session, an undo) switches the controls the same way.
#include "scene/SceneEditor.h"
#include "widgets/MaterialDock.h"
#include "widgets/ParameterControls.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QUndoStack>
#include <QtTest>

using aniso::SceneModel;

class TestQualityDock : public QObject
{
  Q_OBJECT

private slots:
  void switchesModes()
  {
    SceneModel model;
    aniso::SceneEditor editor(&model);
    aniso::MaterialDock dock(&editor);
    auto* mode = dock.findChild<aniso::ChoiceControl*>("quality-mode");
    auto* samples = dock.findChild<aniso::NumberControl*>("target-samples");
    auto* error = dock.findChild<aniso::NumberControl*>("error-target");
    QVERIFY(mode && samples && error);

    // The declared default: by sample count.
    QCOMPARE(model.text("quality-mode"), std::string("samples"));
    QVERIFY(samples->isEnabled());
    QVERIFY(!error->isEnabled());

    QComboBox* box = mode->comboBox();
    const int errorIndex = box->findText("error");
    QVERIFY(errorIndex >= 0);
    box->setCurrentIndex(errorIndex);
    emit box->activated(errorIndex);
    QCOMPARE(model.text("quality-mode"), std::string("error"));
    QVERIFY(!samples->isEnabled());
    QVERIFY(error->isEnabled());
    QCOMPARE(editor.undoStack()->count(), 1);

    // The error target's exact spin box sets the model's value.
    error->spinBox()->setValue(0.005);
    emit error->spinBox()->editingFinished();
    QCOMPARE(model.real("error-target"), 0.005);

    // Undo of both edits: the value, then the mode, and the controls follow.
    while (editor.undoStack()->canUndo())
    {
      editor.undoStack()->undo();
    }
    QCOMPARE(model.real("error-target"), 0.01);
    QCOMPARE(model.text("quality-mode"), std::string("samples"));
    QVERIFY(samples->isEnabled());
    QVERIFY(!error->isEnabled());
  }
};

QTEST_MAIN(TestQualityDock)
#include "test_material_dock_quality.moc"
