// The subcommands: each adds itself to the application and runs when chosen.
#pragma once
#include "support/run_together.h"

#include <CLI/CLI.hpp>

namespace cadlod::cli {

void addConvertCommand(CLI::App& app);
void addSimplifyCommand(CLI::App& app);
void addReportCommand(CLI::App& app);
void addInfoCommand(CLI::App& app);

// Limits oneTBB to `threads` workers (0: all cores) for the rest of the process.
void limitThreads(int threads);

// Runs two tasks on oneTBB's workers (one after the other when it has one).
void runOnWorkers(const Task& a, const Task& b);

}  // namespace cadlod::cli
