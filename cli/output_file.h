// Where the command line writes: never over an existing file unless forced, always through
// a temporary file in the same directory renamed into place when complete (the
// OpenFlight core's atomic_file.h), so an interrupted run leaves no truncated output.
// Every output path is checked before any work, and a run's outputs (the model and its
// report) are renamed into place together, after all of them are written.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace cadlod::cli {

// Checks that `path` can be written: its folder exists and is writable (else InputError),
// it is not a folder, and it does not exist unless `force` (else UsageError).
void checkWritable(const std::string& path, bool force);

// Lets `write(temporaryPath)` write the file, then renames it over `path`; throws
// InputError (exit 1) when writing or renaming fails.
void writeAtomically(const std::string& path, const std::function<bool(const std::string&)>& write);

// Writes `bytes` to `file` (an existing temporary) and flushes them to disk.
bool writeBytesTo(const std::string& file, const std::vector<std::uint8_t>& bytes);

// The outputs of one run. add() checks each path (checkWritable; the same path twice is a
// UsageError); write() fills its temporary; commit() renames them all into place. Any
// temporary not committed is removed when the set goes out of scope (e.g. on an error).
class OutputSet {
public:
    explicit OutputSet(bool force) : force_(force) {}
    ~OutputSet();
    OutputSet(const OutputSet&) = delete;
    OutputSet& operator=(const OutputSet&) = delete;

    // `option` names the path in messages ("-o", "--report").
    void add(const std::string& path, const std::string& option);
    // Throws InputError when the temporary cannot be made or `write` fails.
    void write(const std::string& path, const std::function<bool(const std::string& temporary)>& write);
    void commit();

private:
    struct Output {
        std::string path, option, temporary;
    };
    Output& find(const std::string& path);
    bool force_;
    std::vector<Output> outputs_;
};

// Lower-case extension of `path` without the dot ("" when none); ".wrl.gz" gives "gz".
std::string extensionOf(const std::string& path);

}  // namespace cadlod::cli
