#pragma once
// The lookup-tables view: the current half-vector LUT (half vectors as colour, log2 pdf in false
// colour) and BRDF LUT (s red, b green), their parameters and how long they took, and a busy
// bar while a new bake runs on the LutScheduler's workers.
#include <QWidget>

class QLabel;

namespace aniso
{
class BusyBar;
class LutScheduler;
struct LutResult;

class LutView : public QWidget
{
  Q_OBJECT

public:
  explicit LutView(LutScheduler* scheduler, QWidget* parent = nullptr);

  QString infoText() const;

private:
  void show(const LutResult& result);

  LutScheduler* scheduler_;
  QLabel* halfVectors_;
  QLabel* pdf_;
  QLabel* brdf_;
  QLabel* info_;
  BusyBar* progress_;
};
} // namespace aniso
