// Runs one benchmark case in a child process, so that its peak memory and any crash belong
// to that run alone; the result (trivially copyable) comes back through a pipe. A run that
// goes on past its time limit is stopped (SIGALRM) and counts as failed: a peer that loops
// on some input (CGAL's edge collapse on two castle demo models, alien_mirror and the office)
// must not stall the whole bench.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <type_traits>

namespace cadlod::bench {

// `run()` returns a Result; a child that dies, writes short or outlives `limitSeconds` (0: no
// limit) gives Result{} with ok false, and `timedOut` (when given) says whether it was the limit.
template <class Result, class Run>
Result runForked(Run run, unsigned limitSeconds = 0, bool* timedOut = nullptr)
{
    static_assert(std::is_trivially_copyable_v<Result>, "the result crosses a pipe as bytes");
    std::fflush(stdout);
    int fds[2];
    if (pipe(fds) != 0)
        return {};
    const pid_t pid = fork();
    if (pid == 0) {
        close(fds[0]);
        if (limitSeconds > 0)
            alarm(limitSeconds);
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
    if (timedOut)
        *timedOut = WIFSIGNALED(status) && WTERMSIG(status) == SIGALRM;
    if (got != ssize_t(sizeof r))
        r = Result{};
    return r;
}

}  // namespace cadlod::bench
