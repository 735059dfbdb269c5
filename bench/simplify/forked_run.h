// Runs one benchmark case in a child process, so that its peak memory and any crash belong
// to that run alone; the result (trivially copyable) comes back through a pipe.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <type_traits>

namespace cadlod::bench {

// `run()` returns a Result; a child that dies or writes short gives Result{} with ok false.
template <class Result, class Run>
Result runForked(Run run)
{
    static_assert(std::is_trivially_copyable_v<Result>, "the result crosses a pipe as bytes");
    std::fflush(stdout);
    int fds[2];
    if (pipe(fds) != 0)
        return {};
    const pid_t pid = fork();
    if (pid == 0) {
        close(fds[0]);
        const Result r = run();
        const ssize_t written = write(fds[1], &r, sizeof r);
        _exit(written == ssize_t(sizeof r) ? 0 : 1);
    }
    close(fds[1]);
    Result r;
    const ssize_t got = read(fds[0], &r, sizeof r);
    close(fds[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    if (got != ssize_t(sizeof r))
        r.ok = false;
    return r;
}

}  // namespace cadlod::bench
