// Runs the staged meshlabserver (a private MeshLab with cadlod's plugins, see
// cmake/Stage.cmake) on the test run's Xvfb display, with a hard timeout: a plugin
// that opens a dialog would otherwise block for ever.
#pragma once

#include <string>
#include <vector>

namespace cadlod::test {

struct ServerRun {
    int exitCode = -1;
    bool timedOut = false;
    std::string output;  // stdout + stderr + the -l log file
    std::string standardOutput, standardError;  // apart: runMeshlabServerAsDocumented only
    bool ok() const { return exitCode == 0 && !timedOut; }
};

// Arguments as meshlabserver takes them, e.g. {"-i", in, "-o", out, "-m", "fq", "-s", mlx}.
// Scripts may name only the parameters they change: each -s script is first completed with
// cadlod_mlx_complete (meshlabserver 2020.09 needs every parameter, in order).
ServerRun runMeshlabServer(const std::vector<std::string>& args, int timeoutSeconds = 120);

// Runs it as the README shows a user: no -l (meshlabserver prints the log on stdout),
// `environment` before the command (e.g. "QT_LOGGING_RULES='*.debug=false'"), stdout and
// stderr kept apart so that what each shows can be checked line by line.
ServerRun runMeshlabServerAsDocumented(const std::vector<std::string>& args, const std::string& environment,
                                       int timeoutSeconds = 120);

// Writes the complete form of `script` (every parameter of every filter) to `completed`.
ServerRun completeMlx(const std::string& script, const std::string& completed);

// A fresh directory for one test's files, under the build tree.
std::string scratchDir(const std::string& testName);

// Writes `text` to `path` (an .mlx script or a small input file).
void writeText(const std::string& path, const std::string& text);
std::string readText(const std::string& path);

// An .mlx script applying the given filter blocks in order.
std::string mlxScript(const std::vector<std::string>& filterBlocks);
// <filter name="..."> with <Param .../> lines (already formatted).
std::string mlxFilter(const std::string& name, const std::vector<std::string>& params = {});
std::string mlxParam(const std::string& type, const std::string& name, const std::string& value);

}  // namespace cadlod::test
