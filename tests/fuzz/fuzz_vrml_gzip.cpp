// libFuzzer target: the gzip path (.wrz) — inflating with a bound, then importing the
// inflated text. The bound must hold and a failure must come with a message.
#include "scene_checks.h"
#include "vrml/importer.h"
#include "vrml/source_text.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

namespace {
constexpr std::size_t kBound = std::size_t(16) << 20;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace cadlod::vrml;
    SourceText source = decodeSourceBytes(std::string(reinterpret_cast<const char*>(data), size), "fuzz.wrz", kBound);
    if (!source.ok()) return 0;
    if (source.wasGzip && source.text.size() > kBound) std::abort();
    ImportOptions options;
    options.maxInlineDepth = 0;
    options.maxInflatedBytes = kBound;
    const auto result = importVrmlText(std::move(source.text), "/nonexistent/cadlod-fuzz/input.wrz", options);
    if (result.ok()) cadlod::fuzz::requireValidScene(result.scene);
    return 0;
}
