// How a core algorithm runs two independent pieces of work at the same time without the
// cores depending on a thread library: the caller passes a RunTogether (the command line
// oneTBB's parallel_invoke, the MeshLab plugin a std::thread). The default runs them one
// after the other. Whatever runs them, the result is the same: the algorithms only hand
// work that shares no mutable state to it, and combine the results in a fixed order.
#pragma once

#include <exception>
#include <functional>
#include <thread>

namespace cadlod {

using Task = std::function<void()>;
using RunTogether = std::function<void(const Task&, const Task&)>;

inline void runInSequence(const Task& a, const Task& b)
{
    a();
    b();
}

// `b` on the calling thread (so it may report progress to a GUI), `a` on a thread of its own.
// An exception in `a` (e.g. out of memory) is rethrown here, after both have ended.
inline void runOnTwoThreads(const Task& a, const Task& b)
{
    std::exception_ptr failure;
    std::thread other([&] {
        try {
            a();
        } catch (...) {
            failure = std::current_exception();
        }
    });
    try {
        b();
    } catch (...) {
        other.join();
        throw;
    }
    other.join();
    if (failure)
        std::rethrow_exception(failure);
}

}  // namespace cadlod
