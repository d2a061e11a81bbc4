// The settings of the LEADR and microstructure models in the Lights dock (offscreen platform).
// Checks, against the parameter declaration (core/parameters/parameters.cxx) as the reference:
// each surface model's panel holds a control for every key surfaceModelKeys lists, each key is
// declared with the range `aniso render` accepts for its option, the panel shows only while its
// model is chosen, and a control's edit is one undoable change of the scene key.
#include "core/leadr/leadr.h"
#include "core/microstructure/microstructure.h"
#include "scene/SceneEditor.h"
#include "scene/SceneShading.h"
#include "widgets/LightsDock.h"
#include "widgets/ParameterControls.h"
#include "widgets/ParameterPanel.h"

#include <QComboBox>
#include <QUndoStack>
#include <QtTest>
#include <string>

using aniso::SceneModel;

class TestSurfaceModelDock : public QObject
{
  Q_OBJECT

private slots:
  void panelsFollowTheModel()
  {
    SceneModel model;
    aniso::SceneEditor editor(&model);
    aniso::LightsDock dock(&editor);
    auto* leadr = dock.findChild<aniso::ParameterPanel*>("leadrParameters");
    auto* micro = dock.findChild<aniso::ParameterPanel*>("microstructureParameters");
    QVERIFY(leadr && micro);
    for (const char* name : {"leadr", "microstructure"})
    {
      aniso::ParameterPanel* panel = std::string(name) == "leadr" ? leadr : micro;
      QVERIFY(!aniso::surfaceModelKeys(name).empty());
      for (std::string_view key : aniso::surfaceModelKeys(name))
      {
        QVERIFY2(panel->control(key), std::string(key).c_str());
        QVERIFY(aniso::isSceneKey(key));
      }
    }
    QVERIFY(aniso::surfaceModelKeys("as-env").empty());
    // The ranges the models accept themselves.
    QCOMPARE(aniso::parameterSpec("leadr-roughness").minimum, aniso::kLeadrMinAlpha);
    QCOMPARE(aniso::parameterSpec("leadr-roughness").maximum, aniso::kLeadrMaxAlpha);
    QCOMPARE(aniso::parameterSpec("structure-depth").maximum, aniso::kMicroMaxDepth);
    QCOMPARE(aniso::parameterSpec("micro-grid").maximum, 64.0);

    QVERIFY(leadr->isHidden() && micro->isHidden());
    editor.edit("model", aniso::textValue("leadr"));
    QVERIFY(!leadr->isHidden() && micro->isHidden());
    editor.edit("model", aniso::textValue("microstructure"));
    QVERIFY(leadr->isHidden() && !micro->isHidden());

    // The structure's combo box edits the scene once, undoably.
    auto* structure = dynamic_cast<aniso::ChoiceControl*>(micro->control("structure"));
    QVERIFY(structure);
    const int before = editor.undoStack()->count();
    const int grooves = structure->comboBox()->findText("grooves");
    QVERIFY(grooves >= 0);
    structure->comboBox()->setCurrentIndex(grooves);
    emit structure->comboBox()->activated(grooves);
    QCOMPARE(model.text("structure"), std::string("grooves"));
    QCOMPARE(editor.undoStack()->count(), before + 1);
    editor.undoStack()->undo();
    QCOMPARE(model.text("structure"), std::string("pyramids"));
    QCOMPARE(structure->comboBox()->currentText(), QString("pyramids"));

    editor.edit("model", aniso::textValue("banks"));
    QVERIFY(leadr->isHidden() && micro->isHidden());
  }
};

QTEST_MAIN(TestSurfaceModelDock)
#include "test_lights_dock_surface_models.moc"
