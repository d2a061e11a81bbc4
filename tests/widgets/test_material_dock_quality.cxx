// The material dock's quality control: the declared default is "error" (the still view stops by
// the error it estimates from its own frames, target-samples the most); choosing "samples" in
// its quality-mode box sets the model's quality-mode (one undoable edit) and disables the
// error-target control, and back; target-samples stays enabled in both modes (a count, or the
// most); the error-target control edits the model's error-target; a mode changed elsewhere (an
// undo) switches the controls the same way.
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

    // The declared default: by the estimated error, target-samples the most.
    QCOMPARE(model.text("quality-mode"), std::string("error"));
    QVERIFY(samples->isEnabled());
    QVERIFY(error->isEnabled());

    QComboBox* box = mode->comboBox();
    const int samplesIndex = box->findText("samples");
    QVERIFY(samplesIndex >= 0);
    box->setCurrentIndex(samplesIndex);
    emit box->activated(samplesIndex);
    QCOMPARE(model.text("quality-mode"), std::string("samples"));
    QVERIFY(samples->isEnabled());
    QVERIFY(!error->isEnabled());
    QCOMPARE(editor.undoStack()->count(), 1);

    // Back to error; its exact spin box sets the model's value.
    const int errorIndex = box->findText("error");
    box->setCurrentIndex(errorIndex);
    emit box->activated(errorIndex);
    QVERIFY(error->isEnabled());
    error->spinBox()->setValue(0.005);
    emit error->spinBox()->editingFinished();
    QCOMPARE(model.real("error-target"), 0.005);

    // Undo of the edits: the value, then the modes, and the controls follow.
    editor.undoStack()->undo();
    QCOMPARE(model.real("error-target"), 0.01);
    editor.undoStack()->undo();
    QCOMPARE(model.text("quality-mode"), std::string("samples"));
    QVERIFY(!error->isEnabled());
    editor.undoStack()->undo();
    QCOMPARE(model.text("quality-mode"), std::string("error"));
    QVERIFY(samples->isEnabled());
    QVERIFY(error->isEnabled());
  }
};

QTEST_MAIN(TestQualityDock)
#include "test_material_dock_quality.moc"
