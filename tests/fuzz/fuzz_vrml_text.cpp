// libFuzzer target: the VRML lexer, parser (VRML97 and 1.0, PROTO expansion) and
// evaluator on plain text from memory. Inlines and EXTERNPROTOs are not followed
// (maxInlineDepth 0): a fuzzed URL must never make the target read arbitrary files.
#include "scene_checks.h"
#include "vrml/importer.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    cadlod::vrml::ImportOptions options;
    options.maxInlineDepth = 0;
    options.maxInflatedBytes = std::size_t(64) << 20;
    const auto result = cadlod::vrml::importVrmlText(std::string(reinterpret_cast<const char*>(data), size),
                                                     "/nonexistent/cadlod-fuzz/input.wrl", options);
    if (result.ok()) cadlod::fuzz::requireValidScene(result.scene);
    return 0;
}
