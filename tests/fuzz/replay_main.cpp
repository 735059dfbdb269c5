// Runs a fuzz target's LLVMFuzzerTestOneInput over files and directories without
// libFuzzer: the regression inputs under regressions/<target>/ replay in the normal build.
// With --max-rss-mb N it fails when the process peaked above N MiB: an input that once
// amplified a small file into hundreds of MiB must fail again if that comes back.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <sys/resource.h>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace fs = std::filesystem;

static void replayFile(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::printf("replay %s (%zu bytes)\n", path.string().c_str(), bytes.size());
    std::fflush(stdout);
    LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
}

static long peakRssMiB()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss / 1024;  // ru_maxrss is in KiB on Linux
}

int main(int argc, char** argv)
{
    std::size_t replayed = 0;
    long maxRssMiB = 0;
    for (int i = 1; i < argc; ++i) {
        if (std::string(argv[i]) == "--max-rss-mb" && i + 1 < argc) {
            maxRssMiB = std::stol(argv[++i]);
            continue;
        }
        const fs::path arg(argv[i]);
        if (fs::is_directory(arg)) {
            std::vector<fs::path> files;
            for (const auto& entry : fs::directory_iterator(arg))
                if (entry.is_regular_file() && entry.path().filename() != "README.md") files.push_back(entry.path());
            std::sort(files.begin(), files.end());
            for (const auto& f : files) replayFile(f), ++replayed;
        } else {
            replayFile(arg), ++replayed;
        }
    }
    std::printf("%zu inputs replayed without a crash, peak RSS %ld MiB\n", replayed, peakRssMiB());
    if (maxRssMiB > 0 && peakRssMiB() > maxRssMiB) {
        std::printf("FAIL: peak RSS above the %ld MiB bound\n", maxRssMiB);
        return 1;
    }
    return replayed == 0 ? 1 : 0;
}
