#include "assembly/parallel_tasks.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <thread>

namespace cadlod {

void runTasks(std::size_t count, const IndexedTask& task, const ProgressSpans& progress)
{
    const std::thread::id caller = std::this_thread::get_id();
    const ProgressSpans silent;
    tbb::parallel_for(std::size_t(0), count, [&](std::size_t i) {
        tbb::this_task_arena::isolate([&] { task(i, std::this_thread::get_id() == caller ? progress : silent); });
    });
}

}  // namespace cadlod
