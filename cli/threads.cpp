#include "commands.h"

#include <tbb/global_control.h>
#include <tbb/parallel_invoke.h>

#include <memory>

namespace cadlod::cli {

void limitThreads(int threads)
{
    static std::unique_ptr<tbb::global_control> control;
    if (threads > 0)
        control = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                        std::size_t(threads));
}

void runOnWorkers(const Task& a, const Task& b)
{
    tbb::parallel_invoke(a, b);
}

}  // namespace cadlod::cli
