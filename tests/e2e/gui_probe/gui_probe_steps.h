// The probe's scenario runner: steps tried in order on a timer, each until it says it is
// done. A step may run a filter or a modal dialog, which spins the event loop again
// (MeshLab's progress callback does): the timer then fires inside the step, and only the
// watchers run, so that they see what the GUI shows meanwhile.
#pragma once

#include <QApplication>
#include <QElapsedTimer>
#include <QTimer>
#include <QWidget>

#include <cstdlib>
#include <functional>
#include <memory>
#include <vector>

namespace cadlod_probe {

using Step = std::function<bool()>;  // true: done, go on with the next step
using Steps = std::vector<Step>;

inline void runSteps(Steps steps, Steps watchers, std::function<void(const QString&)> report)
{
    constexpr int kTickMs = 200;
    constexpr qint64 kGiveUpMs = 180000;
    struct State {
        Steps steps, watchers;
        std::function<void(const QString&)> report;
        std::size_t next = 0;
        bool inStep = false;
        QElapsedTimer clock;
    };
    auto state = std::make_shared<State>();
    state->steps = std::move(steps);
    state->watchers = std::move(watchers);
    state->report = std::move(report);
    state->clock.start();
    auto* timer = new QTimer(qApp);
    QObject::connect(timer, &QTimer::timeout, [state, timer]() {
        for (Step& watch : state->watchers)
            watch();
        if (state->inStep)
            return;
        if (state->clock.elapsed() > kGiveUpMs) {
            state->report(QString("gave up waiting at step %1").arg(state->next));
            for (QWidget* w : QApplication::topLevelWidgets())
                if (w->isVisible())
                    state->report(QString("  window shown: %1 (%2)").arg(w->windowTitle(), w->metaObject()->className()));
            timer->stop();
            std::_Exit(3);
        }
        state->inStep = true;
        const bool done = state->steps[state->next]();
        state->inStep = false;
        if (done && ++state->next == state->steps.size()) {
            state->report("done");
            timer->stop();
            std::_Exit(0);  // no "save changes?" question on the way out
        }
    });
    timer->start(kTickMs);
}

}  // namespace cadlod_probe
