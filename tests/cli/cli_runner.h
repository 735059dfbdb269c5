// Runs the cadlod executable for the tests: exit code and stderr, without DISPLAY.
#pragma once
#include <string>
#include <vector>

namespace cadlod::test {

struct CliRun {
    int exitCode = -1;
    std::string stdoutText;
    std::string stderrText;
};

// `cadlod args...` under `env -u DISPLAY`, in the current directory.
CliRun runCadlod(const std::vector<std::string>& args);

// A fresh empty directory for one test.
std::string freshDirectory(const std::string& name);

std::string readFile(const std::string& path);
bool fileExists(const std::string& path);
std::vector<std::string> filesIn(const std::string& dir);

}  // namespace cadlod::test
