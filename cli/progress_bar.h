// Progress on stderr: a bar redrawn in place on a terminal, plain lines when piped (one per
// stage and per 10 %). vcglib's callbacks are plain function pointers, so there is one
// process-wide progress reporter.
#pragma once
#include <string>

namespace cadlod::cli::progress {

void enable(bool on);
// The stage `text` is at `percent` (0..100).
void report(int percent, const std::string& text);
// Until endSpan, reports fill [from, to] of the bar and show `label` alone: one bar for a
// job made of many runs (the parts of an assembly), each naming itself once.
void beginSpan(int from, int to, const std::string& label);
void endSpan();
// Ends the current bar line (on a terminal).
void finish();
// vcg::CallBackPos-compatible.
bool callback(const int percent, const char* text);

}  // namespace cadlod::cli::progress
