#include "scene/SceneEditor.h"

#include "core/error.h"

#include <QUndoCommand>
#include <QUndoStack>
#include <utility>

namespace aniso
{
namespace
{
// Applies a set of values; undo restores the values it replaced.
class ChangeValuesCommand : public QUndoCommand
{
public:
  ChangeValuesCommand(SceneEditor* editor, SceneModel::Values before, SceneModel::Values after,
                      int dragId)
      : editor_(editor), before_(std::move(before)), after_(std::move(after)), dragId_(dragId)
  {
    QString names;
    for (const auto& [key, value] : after_)
    {
      names += (names.isEmpty() ? "" : ", ") +
               QString::fromStdString(std::string(sceneKey(key).spec.label));
    }
    setText(QObject::tr("Change %1").arg(names));
  }

  void undo() override { apply(before_); }
  void redo() override { apply(after_); }
  int id() const override { return dragId_ == 0 ? -1 : 1; }

  bool mergeWith(const QUndoCommand* other) override
  {
    const auto* next = static_cast<const ChangeValuesCommand*>(other);
    if (next->dragId_ != dragId_ || next->after_.size() != after_.size())
    {
      return false;
    }
    for (const auto& [key, value] : next->after_)
    {
      if (after_.find(key) == after_.end())
      {
        return false;
      }
    }
    after_ = next->after_;
    // A drag that ends where it started changes nothing: the stack drops the command.
    setObsolete(after_ == before_);
    return true;
  }

private:
  void apply(const SceneModel::Values& values)
  {
    try
    {
      editor_->model()->setValues(values);
    }
    catch (const Error& e)
    {
      emit editor_->errorOccurred(QString::fromStdString(e.what()));
    }
  }

  SceneEditor* editor_;
  SceneModel::Values before_;
  SceneModel::Values after_;
  int dragId_;
};

class ReplaceSceneCommand : public QUndoCommand
{
public:
  ReplaceSceneCommand(SceneEditor* editor, SceneModel::Values values, CameraState camera,
                      const QString& text)
      : editor_(editor), beforeValues_(editor->model()->values()),
        beforeCamera_(editor->model()->camera()), afterValues_(std::move(values)),
        afterCamera_(camera)
  {
    setText(text);
  }

  void undo() override { apply(beforeValues_, beforeCamera_); }
  void redo() override { apply(afterValues_, afterCamera_); }

private:
  void apply(const SceneModel::Values& values, const CameraState& camera)
  {
    try
    {
      SceneModel* model = editor_->model();
      model->setValues(values);
      model->setCamera(camera);
    }
    catch (const Error& e)
    {
      emit editor_->errorOccurred(QString::fromStdString(e.what()));
    }
  }

  SceneEditor* editor_;
  SceneModel::Values beforeValues_;
  CameraState beforeCamera_;
  SceneModel::Values afterValues_;
  CameraState afterCamera_;
};
} // namespace

SceneEditor::SceneEditor(SceneModel* model, QObject* parent)
    : QObject(parent), model_(model), stack_(new QUndoStack(this))
{
}

SceneEditor::~SceneEditor() = default;

void SceneEditor::edit(const SceneModel::Values& changes, int dragId)
{
  SceneModel::Values before;
  SceneModel::Values after;
  for (const auto& [key, value] : changes)
  {
    const ParameterValue& current = model_->value(key);
    if (!(current == value))
    {
      model_->check(key, value);
      before.emplace(key, current);
      after.emplace(key, value);
    }
  }
  if (!after.empty())
  {
    stack_->push(new ChangeValuesCommand(this, std::move(before), std::move(after), dragId));
  }
}

void SceneEditor::edit(std::string_view key, const ParameterValue& value, int dragId)
{
  SceneModel::Values one;
  one.emplace(std::string(key), value);
  edit(one, dragId);
}

int SceneEditor::beginDrag()
{
  return ++lastDrag_;
}

void SceneEditor::replaceScene(const SceneModel::Values& values, const CameraState& camera,
                               const QString& text)
{
  for (const auto& [key, value] : values)
  {
    if (!(value == model_->value(key)))
    {
      model_->check(key, value);
    }
  }
  if (camera.set)
  {
    checkCameraState(camera);
  }
  stack_->push(new ReplaceSceneCommand(this, values, camera, text));
}
} // namespace aniso
