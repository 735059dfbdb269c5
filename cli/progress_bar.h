// Progress on stderr: one bar for the whole job, redrawn in place on a terminal and fitted
// to its width; plain lines when piped (one per phase or step and one per 10 % of the job).
// The job is made of phases (reading, LOD chain, writing), each a share of the bar; within
// a phase, spans split its share further (the parts of an assembly, the hierarchy's
// proxies). The percentage shown never goes back. vcglib's callbacks are plain function
// pointers, so there is one process-wide progress reporter.
#pragma once
#include <string>

namespace cadlod::cli::progress {

void enable(bool on);

// Starts the phase `name`, which fills [from, to] % of the whole bar; reports (and spans)
// after it run 0..100 within that share. Ends the spans of the phase before it.
void phase(int from, int to, const std::string& name);

// The current step is at `percent` (0..100) of the innermost phase or span; `text` names the
// step unless a labelled span hides it.
void report(int percent, const std::string& text);

// Until endSpan, reports fill [from, to] of the current phase or span. A span with a label
// shows its label in place of the steps inside it: one of the many runs of a job (a part of
// an assembly) is named once, not by each of its own steps. An empty label only maps.
void beginSpan(int from, int to, const std::string& label);
void endSpan();

// A span for the scope it lives in.
class Span {
public:
    Span(int from, int to, const std::string& label = "") { beginSpan(from, to, label); }
    ~Span() { endSpan(); }
    Span(const Span&) = delete;
    Span& operator=(const Span&) = delete;
};

// The job is complete: the bar at 100 %, its line ended.
void done();
// Ends the current bar line (on a terminal), e.g. before an error message.
void finish();

// vcg::CallBackPos-compatible.
bool callback(const int percent, const char* text);

// The bar's line for `percent` and `text`, at most `columns` - 1 characters (the last
// column is left free so that no terminal wraps the line) and padded to that width, so
// that it covers a longer line before it. A text too long is cut at a word boundary.
std::string fitLine(int percent, const std::string& text, int columns);

// The terminal's width on stderr (TIOCGWINSZ), else $COLUMNS, else 80.
int terminalColumns();

}  // namespace cadlod::cli::progress
