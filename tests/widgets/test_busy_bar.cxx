// The busy bar (widgets/BusyBar) on the offscreen platform: while shown it steps once every
// kStepMs and repaints once a step (a window holding an OpenGL view composes itself again at every
// repaint of a child), it stops when hidden, and its block moves along the bar and back. Qt's own
// busy QProgressBar, shown for the same time beside it, is counted as the reference it replaces.
#include "widgets/BusyBar.h"

#include <QElapsedTimer>
#include <QEvent>
#include <QImage>
#include <QProgressBar>
#include <QVBoxLayout>
#include <QtTest>
#include <vector>

namespace
{
class PaintCounter : public QObject
{
public:
  int paints = 0;

protected:
  bool eventFilter(QObject* watched, QEvent* event) override
  {
    if (event->type() == QEvent::Paint)
    {
      ++paints;
    }
    return QObject::eventFilter(watched, event);
  }
};

// The block's left edge in a grab of BAR: the first column whose middle pixel is the highlight.
int blockLeft(aniso::BusyBar& bar)
{
  const QImage image = bar.grab().toImage();
  const QColor highlight = bar.palette().color(QPalette::Highlight);
  for (int x = 0; x < image.width(); ++x)
  {
    if (image.pixelColor(x, image.height() / 2) == highlight)
    {
      return x;
    }
  }
  return -1;
}
} // namespace

class TestBusyBar : public QObject
{
  Q_OBJECT

private slots:
  void stepsSlowlyWhileShownAndStopsWhenHidden()
  {
    QWidget window;
    auto* layout = new QVBoxLayout(&window);
    auto* ours = new aniso::BusyBar(&window);
    auto* qts = new QProgressBar(&window);
    qts->setRange(0, 0);
    qts->setTextVisible(false);
    layout->addWidget(ours);
    layout->addWidget(qts);
    PaintCounter oursPainted;
    PaintCounter qtsPainted;
    ours->installEventFilter(&oursPainted);
    qts->installEventFilter(&qtsPainted);
    window.resize(200, 60);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(ours->animating());

    const int paintsBefore = oursPainted.paints;
    const int qtPaintsBefore = qtsPainted.paints;
    QElapsedTimer clock;
    clock.start();
    QTest::qWait(1500);
    const double seconds = static_cast<double>(clock.elapsed()) * 1e-3;
    const int paints = oursPainted.paints - paintsBefore;
    const int qtPaints = qtsPainted.paints - qtPaintsBefore;
    qInfo("%.2f s: the busy bar stepped %d times and painted %d times; Qt's busy bar painted %d "
          "times",
          seconds, ours->steps(), paints, qtPaints);
    // One step every 250 ms: 6 in 1.5 s (a timer may fire late, never early); a paint a step.
    const int most = static_cast<int>(seconds * 1000.0 / aniso::BusyBar::kStepMs) + 1;
    QVERIFY(ours->steps() >= 3);
    QVERIFY(ours->steps() <= most);
    QVERIFY(paints <= ours->steps() + 1);
    // Qt's own animates at the display's rate; where it animates at all here, several times as
    // often.
    if (qtPaints > 0)
    {
      QVERIFY2(paints * 3 < qtPaints,
               qPrintable(QString("%1 against %2").arg(paints).arg(qtPaints)));
    }

    // Hidden: no timer runs, no step is taken.
    ours->hide();
    QVERIFY(!ours->animating());
    const int stepsHidden = ours->steps();
    QTest::qWait(600);
    QCOMPARE(ours->steps(), stepsHidden);
    // Shown again: it starts over and runs.
    ours->show();
    QVERIFY(ours->animating());
    QCOMPARE(ours->steps(), 0);
  }

  // The block goes from the left end to the right end in kPositions - 1 steps and back.
  void theBlockGoesAlongAndBack()
  {
    aniso::BusyBar bar;
    bar.resize(121, 8);
    bar.show();
    QVERIFY(QTest::qWaitForWindowExposed(&bar));
    std::vector<int> lefts;
    int last = bar.steps();
    lefts.push_back(blockLeft(bar));
    while (static_cast<int>(lefts.size()) < 2 * (aniso::BusyBar::kPositions - 1) + 1)
    {
      QVERIFY(QTest::qWaitFor([&] { return bar.steps() != last; }, 2000));
      last = bar.steps();
      lefts.push_back(blockLeft(bar));
    }
    const int n = aniso::BusyBar::kPositions;
    QCOMPARE(lefts.front(), 1);
    for (int i = 1; i < n; ++i)
    {
      QVERIFY2(lefts[std::size_t(i)] > lefts[std::size_t(i) - 1], qPrintable(QString::number(i)));
    }
    // At the right end: the block's right edge one pixel inside the frame.
    const int block = (bar.width() - 2) / n;
    QCOMPARE(lefts[std::size_t(n) - 1] + block, bar.width() - 1);
    for (int i = n; i < 2 * (n - 1) + 1; ++i)
    {
      QVERIFY(lefts[std::size_t(i)] < lefts[std::size_t(i) - 1]);
    }
    QCOMPARE(lefts.back(), 1);
  }
};

QTEST_MAIN(TestBusyBar)
#include "test_busy_bar.moc"
