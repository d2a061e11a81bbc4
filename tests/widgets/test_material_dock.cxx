// The material dock: the logarithmic slider mapping and the roughness view follow their stated
// formulas (computed here independently), a slider drag sets the model and is one undo step,
// spin boxes set exact values, the link keeps n_v / n_u, and the metal presets set and
// recognise their F0.
#include "scene/SceneEditor.h"
#include "widgets/MaterialDock.h"
#include "widgets/ParameterControls.h"
#include "widgets/SliderMapping.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QSignalSpy>
#include <QSlider>
#include <QUndoStack>
#include <QtTest>
#include <cmath>

using aniso::numberValue;

class TestMaterialDock : public QObject
{
  Q_OBJECT

private slots:
  // Position p of S = 1000 steps gives n = 10^(p/S log10(1 + 1e6)) - 1 (to 3 significant
  // digits), and each position maps back to itself.
  void logarithmicSliderFollowsItsFormula()
  {
    const aniso::ParameterSpec& nu = aniso::parameterSpec("nu");
    QCOMPARE(aniso::sliderValue(nu, 0), 0.0);
    QCOMPARE(aniso::sliderValue(nu, aniso::kSliderSteps), 1e6);
    for (int p : {1, 137, 500, 717, 998})
    {
      const double exact = std::pow(10.0, p / 1000.0 * std::log10(1.0 + 1e6)) - 1.0;
      const double v = aniso::sliderValue(nu, p);
      QVERIFY2(std::abs(v - exact) <= 5e-3 * exact, qPrintable(QString::number(p)));
    }
    QCOMPARE(aniso::sliderValue(nu, 500), 999.0);
    QCOMPARE(aniso::sliderPosition(nu, 20000.0),
             static_cast<int>(std::lround(1000.0 * std::log10(20001.0) / std::log10(1e6 + 1.0))));
    for (int p = 0; p <= aniso::kSliderSteps; ++p)
    {
      QCOMPARE(aniso::sliderPosition(nu, aniso::sliderValue(nu, p)), p);
    }
    // A range above 0 is purely logarithmic: each decade of the error target's 1e-4..1 takes a
    // quarter of the slider, 1% in the middle.
    const aniso::ParameterSpec& error = aniso::parameterSpec("error-target");
    QCOMPARE(aniso::sliderValue(error, 250), 1e-3);
    QCOMPARE(aniso::sliderValue(error, 500), 1e-2);
    QCOMPARE(aniso::sliderValue(error, 750), 0.1);
    QCOMPARE(aniso::sliderPosition(error, 0.02),
             static_cast<int>(std::lround(1000.0 * (std::log10(0.02) + 4.0) / 4.0)));
    for (int p = 0; p <= aniso::kSliderSteps; ++p)
    {
      QCOMPARE(aniso::sliderPosition(error, aniso::sliderValue(error, p)), p);
    }
    // Linear parameters land on their declared step.
    const aniso::ParameterSpec& exposure = aniso::parameterSpec("exposure");
    QCOMPARE(aniso::sliderValue(exposure, 500), 0.0);
    QCOMPARE(aniso::sliderValue(exposure, 503), 0.1);
  }

  // alpha = sqrt(2 / (n + 2)) and back: n = 0 is alpha = 1, alpha = 0.1 is n = 198.
  void roughnessViewFollowsItsFormula()
  {
    QCOMPARE(aniso::roughnessFromExponent(0.0), 1.0);
    QCOMPARE(aniso::roughnessFromExponent(100.0), std::sqrt(2.0 / 102.0));
    QVERIFY(std::abs(aniso::exponentFromRoughness(0.1) - 198.0) < 1e-9);
    QCOMPARE(aniso::exponentFromRoughness(0.0), 1e6);
    for (double n : {0.0, 1.0, 70.0, 20000.0, 1e6})
    {
      const double back = aniso::exponentFromRoughness(aniso::roughnessFromExponent(n));
      QVERIFY(std::abs(back - n) <= 1e-9 * std::max(1.0, n));
    }
  }

  // A drag of the n_u slider sets the model at every step to the mapped value and leaves one
  // undo command.
  void sliderDragSetsModelInOneUndoStep()
  {
    aniso::SceneModel model;
    model.setValue("nu", aniso::numberValue(1000.0)); // from the brushed aluminium's n_u
    aniso::SceneEditor editor(&model);
    aniso::MaterialDock dock(&editor);
    auto* nu = dock.findChild<aniso::NumberControl*>("nu");
    QVERIFY(nu);
    QSlider* slider = nu->slider();
    slider->setSliderDown(true);
    for (int p : {600, 650, 700, 717})
    {
      slider->setValue(p);
      QCOMPARE(model.real("nu"), aniso::sliderValue(aniso::parameterSpec("nu"), p));
    }
    slider->setSliderDown(false);
    QCOMPARE(editor.undoStack()->count(), 1);
    QCOMPARE(nu->spinBox()->value(), model.real("nu"));
    editor.undoStack()->undo();
    QCOMPARE(model.real("nu"), 1000.0);
    QCOMPARE(slider->value(), aniso::sliderPosition(aniso::parameterSpec("nu"), 1000.0));
  }

  // The spin box sets exactly the typed value; the roughness view follows.
  void spinBoxIsExact()
  {
    aniso::SceneModel model;
    aniso::SceneEditor editor(&model);
    aniso::MaterialDock dock(&editor);
    auto* nv = dock.findChild<aniso::NumberControl*>("nv");
    nv->spinBox()->setValue(12345.6);
    QCOMPARE(model.real("nv"), 12345.6);
    auto* alphaV = dock.findChild<QDoubleSpinBox*>("alpha-v");
    QVERIFY(std::abs(alphaV->value() - std::sqrt(2.0 / 12347.6)) < 1e-4);
    auto* alphaU = dock.findChild<QDoubleSpinBox*>("alpha-u");
    alphaU->setValue(0.1);
    QVERIFY(std::abs(model.real("nu") - 198.0) < 1e-9);
  }

  // Linked, moving n_u moves n_v by the same factor (one undo step for both); at the top of the
  // range the ratio is kept by holding the moved exponent back.
  void linkKeepsTheRatio()
  {
    aniso::SceneModel model;
    // From the brushed aluminium's lobe.
    model.setValues({{"nu", aniso::numberValue(1000.0)}, {"nv", aniso::numberValue(50.0)}});
    aniso::SceneEditor editor(&model);
    aniso::MaterialDock dock(&editor);
    dock.findChild<QCheckBox*>("link")->setChecked(true);
    auto* nu = dock.findChild<aniso::NumberControl*>("nu");
    auto* nv = dock.findChild<aniso::NumberControl*>("nv");
    nu->spinBox()->setValue(2000.0); // n_u : n_v was 1000 : 50
    QCOMPARE(model.real("nv"), 100.0);
    QCOMPARE(editor.undoStack()->count(), 1);
    // A drag keeps the ratio captured when it began.
    nu->slider()->setSliderDown(true);
    for (int p : {400, 800, 700})
    {
      nu->slider()->setValue(p);
      QVERIFY(std::abs(model.real("nv") / model.real("nu") - 0.05) < 1e-12);
    }
    nu->slider()->setSliderDown(false);
    QCOMPARE(editor.undoStack()->count(), 2);
    nv->spinBox()->setValue(1e5); // would need n_u = 2e6
    QCOMPARE(model.real("nu"), 1e6);
    QCOMPARE(model.real("nv"), 5e4);
    editor.undoStack()->undo();
    editor.undoStack()->undo();
    editor.undoStack()->undo();
    QCOMPARE(model.real("nu"), 1000.0);
    QCOMPARE(model.real("nv"), 50.0);
  }

  // Choosing a metal sets its tabulated F0; an F0 equal to a preset shows that preset.
  void metalPresetsSetAndRecogniseF0()
  {
    aniso::SceneModel model;
    aniso::SceneEditor editor(&model);
    aniso::MaterialDock dock(&editor);
    auto* presets = dock.findChild<QComboBox*>("f0-preset");
    QCOMPARE(presets->currentText(), QString("Aluminium")); // the declared default F0
    const int gold = presets->findText("Gold");
    emit presets->activated(gold);
    QCOMPARE(model.color("f0"), (std::array<double, 3>{1.000, 0.766, 0.336}));
    model.setValue("f0", aniso::colorValue(0.955, 0.638, 0.538));
    QCOMPARE(presets->currentText(), QString("Copper"));
    model.setValue("f0", aniso::colorValue(0.5, 0.5, 0.5));
    QCOMPARE(presets->currentText(), QString("Custom"));
    QCOMPARE(aniso::metalPresets().size(), std::size_t(7));
  }

  // Choice parameters come as combo boxes of their declared choices.
  void choicesAreOffered()
  {
    aniso::SceneModel model;
    aniso::SceneEditor editor(&model);
    aniso::MaterialDock dock(&editor);
    auto* method = dock.findChild<aniso::ChoiceControl*>("method");
    QCOMPARE(method->comboBox()->count(), 2);
    emit method->comboBox()->activated(method->comboBox()->findText("split-sum"));
    QCOMPARE(model.text("method"), std::string("split-sum"));
    model.setValue("method", aniso::textValue("exact"));
    QCOMPARE(method->comboBox()->currentText(), QString("exact"));
  }
};

QTEST_MAIN(TestMaterialDock)
#include "test_material_dock.moc"
