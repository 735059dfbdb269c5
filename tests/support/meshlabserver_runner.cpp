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

}  // namespace

ServerRun runMeshlabServer(const std::vector<std::string>& args, int timeoutSeconds)
{
    const std::string dir = scratchDir("meshlabserver-runs");
    static int counter = 0;
    // ctest runs test processes in parallel: the pid keeps their files apart.
    const std::string logFile =
        dir + "/run-" + std::to_string(getpid()) + "-" + std::to_string(++counter) + ".log";
    const std::string outFile = logFile + ".out";

    std::ostringstream cmd;
    cmd << "DISPLAY=" << shellQuote(xvfbDisplay());
    if (*CADLOD_SANITIZER_PRELOAD)
        cmd << " LD_PRELOAD=" << shellQuote(CADLOD_SANITIZER_PRELOAD);
    cmd << " timeout -k 5 " << timeoutSeconds << " "
        << shellQuote(CADLOD_STAGE_MESHLABSERVER) << " -l " << shellQuote(logFile);
    for (const std::string& a : args)
        cmd << ' ' << shellQuote(a);
    cmd << " >" << shellQuote(outFile) << " 2>&1";

    ServerRun run;
    const int status = std::system(cmd.str().c_str());
    run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    run.timedOut = run.exitCode == 124 || run.exitCode == 137;
    run.output = readText(outFile) + readText(logFile);
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
