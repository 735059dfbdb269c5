// How the assembly cores run many independent pieces of work (the parts' chains, the
// proxies of the clusters of one height) at once: on oneTBB's worker threads, each task
// writing only its own results, by index, so that the output is the same whichever thread
// ran what and in what order.
#pragma once

#include "assembly/progress_spans.h"

#include <cstddef>
#include <functional>

namespace cadlod {

// What task i is given to report its progress with: the caller's spans when it runs on the
// calling thread, silent ones elsewhere (MeshLab's callback belongs to the GUI's thread, the
// command's bar is one per process).
using IndexedTask = std::function<void(std::size_t i, const ProgressSpans& progress)>;

// task(0) ... task(count - 1), at once where there are threads for them. A task waiting for
// work of its own (a chain measuring beside collapsing) never picks up another task of the
// list meanwhile, so a thread's progress spans stay nested. Rethrows a task's exception
// after the running tasks have ended.
void runTasks(std::size_t count, const IndexedTask& task, const ProgressSpans& progress);

}  // namespace cadlod
