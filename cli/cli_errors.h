// The command line's exit codes and the errors that lead to them.
#pragma once
#include <stdexcept>
#include <string>

namespace cadlod::cli {

enum ExitCode { kOk = 0, kInputError = 1, kUsageError = 2 };

// An input that cannot be read or an output that cannot be written: exit code 1.
struct InputError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Arguments that make no sense together (found after parsing): exit code 2.
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

}  // namespace cadlod::cli
