#include "scene/SceneEditor.h"

#include "core/error.h"

#include <QUndoCommand>
#include <QUndoStack>
#include <algorithm>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace aniso
{
namespace
{
// The values of VALUES that are scene-scope (material keys live in the library).
SceneModel::Values sceneScope(const SceneModel::Values& values)
{
  SceneModel::Values kept;
  for (const auto& [key, value] : values)
  {
    if (!isMaterialKey(key))
    {
      kept.emplace(key, value);
    }
  }
  return kept;
}

bool touchesMaterials(const SceneModel::Values& values)
{
  for (const auto& [key, value] : values)
  {
    if (isMaterialKey(key))
    {
      return true;
    }
  }
  return false;
}

// A change of the library, kept as the materials it touched (before and after) and, when it
// added, removed or reordered materials, both orders of names: an undo step holds a few
// materials instead of two copies of the whole library. Two copies cost 46 KiB a step with the
// eight built-in metals alone, the bulk of the window's memory growth over 10 000 edits
// (bench_soak, docs/RELIABILITY.md). Undo and redo run in the stack's order, so the library
// they start from is the other side of the change, whose untouched materials are the same.
class LibraryChange
{
public:
  LibraryChange() = default;
  LibraryChange(const MaterialLibrary& before, const MaterialLibrary& after)
  {
    touchedBefore_ = differing(before, after);
    touchedAfter_ = differing(after, before);
    if (names(before) != names(after))
    {
      orderBefore_ = names(before);
      orderAfter_ = names(after);
    }
  }

  // The library before the change, from CURRENT (the library after it), and the reverse.
  MaterialLibrary before(const MaterialLibrary& current) const
  {
    return rebuilt(orderBefore_, touchedBefore_, current);
  }
  MaterialLibrary after(const MaterialLibrary& current) const
  {
    return rebuilt(orderAfter_, touchedAfter_, current);
  }
  bool empty() const { return touchedBefore_.empty() && touchedAfter_.empty(); }

private:
  static std::vector<std::string> names(const MaterialLibrary& library)
  {
    std::vector<std::string> out;
    for (const Material& m : library.materials())
    {
      out.push_back(m.name);
    }
    return out;
  }
  // The materials of A that B lacks or holds otherwise.
  static std::vector<Material> differing(const MaterialLibrary& a, const MaterialLibrary& b)
  {
    std::vector<Material> out;
    for (const Material& m : a.materials())
    {
      const Material* other = b.find(m.name);
      if (!other || *other != m)
      {
        out.push_back(m);
      }
    }
    return out;
  }
  // CURRENT's materials in ORDER (empty: CURRENT's own), TOUCHED's where it has one.
  static MaterialLibrary rebuilt(const std::vector<std::string>& order,
                                 const std::vector<Material>& touched,
                                 const MaterialLibrary& current)
  {
    MaterialLibrary library;
    const auto add = [&](const std::string& name)
    {
      const auto it = std::find_if(touched.begin(), touched.end(),
                                   [&](const Material& m) { return m.name == name; });
      library.put(it != touched.end() ? *it : current.at(name));
    };
    if (order.empty())
    {
      for (const Material& m : current.materials())
      {
        add(m.name);
      }
    }
    else
    {
      for (const std::string& name : order)
      {
        add(name);
      }
    }
    return library;
  }

  std::vector<Material> touchedBefore_;
  std::vector<Material> touchedAfter_;
  std::vector<std::string> orderBefore_; // both empty when the names and their order stay
  std::vector<std::string> orderAfter_;
};

// Applies a set of values; undo restores the values it replaced. Material keys were set in the
// edited parts' materials: undo and redo restore the library as it was before and after, so they
// reach the same materials whatever is selected by then.
class ChangeValuesCommand : public QUndoCommand
{
public:
  ChangeValuesCommand(SceneEditor* editor, SceneModel::Values before, SceneModel::Values after,
                      int dragId)
      : editor_(editor), before_(std::move(before)), after_(std::move(after)), dragId_(dragId),
        materials_(touchesMaterials(after_))
  {
    QString names;
    for (const auto& [key, value] : after_)
    {
      names += (names.isEmpty() ? "" : ", ") +
               QString::fromStdString(std::string(sceneKey(key).spec.label));
    }
    setText(QObject::tr("Change %1").arg(names));
    if (materials_)
    {
      libraryBefore_ = editor_->model()->materials();
    }
  }

  void undo() override { restore(before_, true); }
  void redo() override
  {
    if (!haveAfter_)
    {
      // The first redo sets the values as an edit (into the edited materials) and remembers
      // what that changed in the library.
      attempt([&] { editor_->model()->setValues(after_); });
      if (materials_)
      {
        library_ = LibraryChange(libraryBefore_, editor_->model()->materials());
        libraryBefore_ = MaterialLibrary{};
      }
      haveAfter_ = true;
      return;
    }
    restore(after_, false);
  }
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
    if (materials_)
    {
      // Merged just after NEXT was done: the model holds the library after both.
      const MaterialLibrary& last = editor_->model()->materials();
      library_ = LibraryChange(library_.before(next->library_.before(last)), last);
    }
    // A drag that ends where it started changes nothing: the stack drops the command.
    setObsolete(after_ == before_ && library_.empty());
    return true;
  }

private:
  // VALUES, with the library of the side of the change they belong to (BEFORE or after).
  void restore(const SceneModel::Values& values, bool before)
  {
    attempt(
        [&]
        {
          SceneModel* model = editor_->model();
          if (materials_)
          {
            const MaterialLibrary& current = model->materials();
            model->setParts(model->parts(),
                            before ? library_.before(current) : library_.after(current));
            model->setValues(sceneScope(values));
          }
          else
          {
            model->setValues(values);
          }
        });
  }
  void attempt(const std::function<void()>& action)
  {
    try
    {
      action();
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
  bool materials_;
  bool haveAfter_ = false;
  MaterialLibrary libraryBefore_; // until the first redo
  LibraryChange library_;
};

// Replaces the parts and the library; undo restores them.
class ChangePartsCommand : public QUndoCommand
{
public:
  ChangePartsCommand(SceneEditor* editor, std::vector<ScenePart> parts,
                     const MaterialLibrary& library, const QString& text)
      : editor_(editor), partsBefore_(editor->model()->parts()), partsAfter_(std::move(parts)),
        library_(editor->model()->materials(), library)
  {
    setText(text);
  }

  void undo() override { apply(partsBefore_, true); }
  void redo() override { apply(partsAfter_, false); }

private:
  // PARTS with the library of the side of the change they belong to (BEFORE or after).
  void apply(const std::vector<ScenePart>& parts, bool before)
  {
    try
    {
      const MaterialLibrary& current = editor_->model()->materials();
      editor_->model()->setParts(parts,
                                 before ? library_.before(current) : library_.after(current));
    }
    catch (const Error& e)
    {
      emit editor_->errorOccurred(QString::fromStdString(e.what()));
    }
  }

  SceneEditor* editor_;
  std::vector<ScenePart> partsBefore_;
  std::vector<ScenePart> partsAfter_;
  LibraryChange library_;
};

class ReplaceSceneCommand : public QUndoCommand
{
public:
  ReplaceSceneCommand(SceneEditor* editor, SceneModel::Values values, CameraState camera,
                      std::vector<ScenePart> parts, const MaterialLibrary& library,
                      const QString& text)
      : editor_(editor), beforeValues_(editor->model()->values()),
        beforeCamera_(editor->model()->camera()), beforeParts_(editor->model()->parts()),
        afterValues_(std::move(values)), afterCamera_(camera), afterParts_(std::move(parts)),
        library_(editor->model()->materials(), library)
  {
    setText(text);
  }

  void undo() override { apply(beforeValues_, beforeCamera_, beforeParts_, true); }
  void redo() override { apply(afterValues_, afterCamera_, afterParts_, false); }

private:
  // The values, camera and parts of one side of the change (BEFORE or after) with its library.
  void apply(const SceneModel::Values& values, const CameraState& camera,
             const std::vector<ScenePart>& parts, bool before)
  {
    try
    {
      SceneModel* model = editor_->model();
      const MaterialLibrary library =
          before ? library_.before(model->materials()) : library_.after(model->materials());
      if (parts.empty())
      {
        model->setValues(values); // a scene of one part (the mesh key's)
      }
      else
      {
        // The mesh key first (it makes the scene one part), then the parts and their library,
        // then the scene-scope values (material keys follow the library).
        SceneModel::Values mesh;
        mesh.emplace("mesh", values.at("mesh"));
        model->setValues(mesh);
        model->setParts(parts, library);
        model->setValues(sceneScope(values));
      }
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
  std::vector<ScenePart> beforeParts_;
  SceneModel::Values afterValues_;
  CameraState afterCamera_;
  std::vector<ScenePart> afterParts_;
  LibraryChange library_;
};
} // namespace

SceneEditor::SceneEditor(SceneModel* model, QObject* parent)
    : QObject(parent), model_(model), stack_(new QUndoStack(this))
{
  stack_->setUndoLimit(kUndoLimit);
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
  auto [parts, library] = onePartScene(values, model_->materials());
  replaceScene(values, camera, std::move(parts), std::move(library), text);
}

void SceneEditor::replaceScene(const SceneModel::Values& values, const CameraState& camera,
                               std::vector<ScenePart> parts, MaterialLibrary library,
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
  if (values.find("mesh") == values.end())
  {
    throw errorAbout("scene", "a scene needs its mesh key");
  }
  SceneModel probe; // the same checks setParts makes, on a model of no consequence
  probe.setParts(parts, library);
  stack_->push(new ReplaceSceneCommand(this, values, camera, std::move(parts), std::move(library),
                                       text));
}

void SceneEditor::editParts(std::vector<ScenePart> parts, MaterialLibrary library,
                            const QString& text)
{
  if (parts == model_->parts() && library == model_->materials())
  {
    return;
  }
  SceneModel probe;
  probe.setParts(parts, library); // throws the same errors, changing nothing of ours
  stack_->push(new ChangePartsCommand(this, std::move(parts), library, text));
}

void SceneEditor::makeUnique(const std::vector<int>& parts)
{
  std::vector<ScenePart> next = model_->parts();
  MaterialLibrary library = model_->materials();
  bool any = false;
  for (int i : parts)
  {
    if (i < 0 || i >= int(next.size()))
    {
      continue;
    }
    ScenePart& part = next[std::size_t(i)];
    int users = 0;
    for (const ScenePart& p : next)
    {
      users += p.material == part.material ? 1 : 0;
    }
    if (users < 2)
    {
      continue; // already its own
    }
    Material copy = library.at(part.material);
    copy.name = library.uniqueName(part.material + " (" + part.name + ")");
    library.put(copy);
    part.material = copy.name;
    any = true;
  }
  if (any)
  {
    editParts(std::move(next), std::move(library), tr("Make material unique"));
  }
}

void SceneEditor::assignMaterial(const std::vector<int>& parts, const std::string& material)
{
  std::vector<ScenePart> next = model_->parts();
  MaterialLibrary library = model_->materials();
  if (!library.contains(material))
  {
    const Material* builtin = builtinMaterials().find(material);
    if (!builtin)
    {
      throw errorAbout(material, "no such material");
    }
    library.put(*builtin);
  }
  for (int i : parts)
  {
    if (i >= 0 && i < int(next.size()))
    {
      next[std::size_t(i)].material = material;
    }
  }
  editParts(std::move(next), std::move(library),
            tr("Assign %1").arg(QString::fromStdString(material)));
}

void SceneEditor::setPartsVisible(const std::vector<int>& parts, bool visible)
{
  std::vector<ScenePart> next = model_->parts();
  for (int i : parts)
  {
    if (i >= 0 && i < int(next.size()))
    {
      next[std::size_t(i)].visible = visible;
    }
  }
  editParts(std::move(next), model_->materials(), visible ? tr("Show parts") : tr("Hide parts"));
}
} // namespace aniso
