#include "meshlabserver_runner.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace fs = std::filesystem;

namespace cadlod::test {
namespace {

std::string shellQuote(const std::string& s)
{
    std::string q = "'";
    for (char c : s)
        q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

std::string xvfbDisplay()
{
    std::ifstream in(CADLOD_XVFB_DISPLAY_FILE);
    std::string display;
    if (!(in >> display))
        throw std::runtime_error("no Xvfb display in " CADLOD_XVFB_DISPLAY_FILE
                                 " (the xvfb ctest fixture did not run)");
    return display;
}

std::string environmentPrefix()
{
    std::string env = "DISPLAY=" + shellQuote(xvfbDisplay());
    if (*CADLOD_SANITIZER_PRELOAD)
        env += " LD_PRELOAD=" + shellQuote(CADLOD_SANITIZER_PRELOAD);
    return env;
}

// Runs `command` under `timeout`; `redirections` say where its output goes.
ServerRun runWithTimeout(const std::string& environment, const std::string& command, int timeoutSeconds,
                         const std::string& redirections)
{
    const std::string line = environmentPrefix() + " " + environment + " timeout -k 5 " +
                             std::to_string(timeoutSeconds) + " " + command + " " + redirections;
    ServerRun run;
    const int status = std::system(line.c_str());
    run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    run.timedOut = run.exitCode == 124 || run.exitCode == 137;
    return run;
}

ServerRun runCommand(const std::string& command, const std::string& logFile, int timeoutSeconds)
{
    const std::string outFile = logFile + ".out";
    ServerRun run = runWithTimeout("", command, timeoutSeconds, ">" + shellQuote(outFile) + " 2>&1");
    run.output = readText(outFile) + readText(logFile);
    return run;
}

// A fresh base name for this process's next run (ctest runs test processes in parallel).
std::string nextRunBase()
{
    static int counter = 0;
    return scratchDir("meshlabserver-runs") + "/run-" + std::to_string(getpid()) + "-" +
           std::to_string(++counter);
}

}  // namespace

ServerRun completeMlx(const std::string& script, const std::string& completed)
{
    const std::string base = nextRunBase();
    return runCommand(shellQuote(CADLOD_MLX_COMPLETE) + " " + shellQuote(CADLOD_STAGE_PLUGIN_DIR) + " " +
                          shellQuote(script) + " " + shellQuote(completed),
                      base + ".log", 60);
}

namespace {

// Appends `args` to `command`, each -s script replaced by its completed form (files named
// after `base`); false, with the completion's run in `failure`, when one cannot be completed.
bool appendArguments(std::string& command, const std::vector<std::string>& args, const std::string& base,
                     ServerRun& failure)
{
    for (std::size_t i = 0; i < args.size(); ++i) {
        std::string arg = args[i];
        if (i > 0 && args[i - 1] == "-s") {
            const std::string completed = base + "-script" + std::to_string(i) + ".mlx";
            ServerRun completion = completeMlx(arg, completed);
            if (!completion.ok()) {
                failure = completion;
                return false;
            }
            arg = completed;
        }
        command += " " + shellQuote(arg);
    }
    return true;
}

}  // namespace

ServerRun runMeshlabServer(const std::vector<std::string>& args, int timeoutSeconds)
{
    std::string command = shellQuote(CADLOD_STAGE_MESHLABSERVER);
    const std::string base = nextRunBase();
    command += " -l " + shellQuote(base + ".log");
    ServerRun failure;
    if (!appendArguments(command, args, base, failure))
        return failure;
    return runCommand(command, base + ".log", timeoutSeconds);
}

ServerRun runMeshlabServerAsDocumented(const std::vector<std::string>& args, const std::string& environment,
                                       int timeoutSeconds)
{
    std::string command = shellQuote(CADLOD_STAGE_MESHLABSERVER);
    const std::string base = nextRunBase();
    ServerRun failure;
    if (!appendArguments(command, args, base, failure))
        return failure;
    const std::string outFile = base + ".stdout", errFile = base + ".stderr";
    ServerRun run = runWithTimeout(environment, command, timeoutSeconds,
                                   ">" + shellQuote(outFile) + " 2>" + shellQuote(errFile));
    run.standardOutput = readText(outFile);
    run.standardError = readText(errFile);
    run.output = run.standardOutput + run.standardError;
    return run;
}

std::string scratchDir(const std::string& testName)
{
    const fs::path dir = fs::path(CADLOD_TEST_SCRATCH_DIR) / testName;
    fs::create_directories(dir);
    return dir.string();
}

void writeText(const std::string& path, const std::string& text)
{
    std::ofstream out(path, std::ios::binary);
    out << text;
    if (!out)
        throw std::runtime_error("cannot write " + path);
}

std::string readText(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string mlxParam(const std::string& type, const std::string& name, const std::string& value)
{
    return "  <Param type=\"" + type + "\" name=\"" + name + "\" value=\"" + value + "\"/>\n";
}

std::string mlxFilter(const std::string& name, const std::vector<std::string>& params)
{
    std::string s = " <filter name=\"" + name + "\">\n";
    for (const std::string& p : params)
        s += p;
    return s + " </filter>\n";
}

std::string mlxScript(const std::vector<std::string>& filterBlocks)
{
    std::string s = "<!DOCTYPE FilterScript>\n<FilterScript>\n";
    for (const std::string& f : filterBlocks)
        s += f;
    return s + "</FilterScript>\n";
}

}  // namespace cadlod::test
