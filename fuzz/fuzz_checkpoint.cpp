// Fuzz target "checkpoint": the bytes as checkpoint.json, read by
// run/persistence/checkpoint.hpp load_checkpoint (as `resume` reads it).
//
// Nearly every mutation breaks the content hash, which stops the reader early.
// So when the first line is JSON holding a "content", that content is also
// sealed again with a correct hash (format 2 with the bytes after the line as
// its genomes when the line announces them, else format 1) and read: what a
// hand edit with the hash recomputed looks like, and the only way to reach
// the content checks.
#include "fuzz/fuzz_target.hpp"
#include "fuzz/path_readers.hpp"
#include "run/persistence/checkpoint.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <string_view>

namespace morphogen::fuzz {
std::string input_from_file(const std::string&, std::string bytes) { return bytes; }

namespace {
// Nesting depth of JSON text (brackets outside strings). The harness must not
// trip over deep nesting itself: that is the reader's case (step 1).
int nesting_depth(std::string_view text) {
    int depth = 0, deepest = 0;
    bool in_string = false, escaped = false;
    for (char c : text) {
        if (in_string) {
            if (escaped) escaped = false;
            else if (c == '\\') escaped = true;
            else if (c == '"') in_string = false;
        } else if (c == '"') {
            in_string = true;
        } else if (c == '[' || c == '{') {
            deepest = std::max(deepest, ++depth);
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    return deepest;
}
}  // namespace
}  // namespace morphogen::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace morphogen;
    using namespace morphogen::fuzz;
    const std::string_view text = as_text(data, size);
    accepts([&] { (void)load_checkpoint_bytes(text); });

    // Format 2 is a JSON header line and a binary part; format 1 one JSON line.
    const std::size_t newline = text.find('\n');
    const std::string_view header = text.substr(0, newline);
    if (nesting_depth(header) > 100) return 0;
    nlohmann::json document;
    try {
        document = nlohmann::json::parse(header);
    } catch (const nlohmann::json::exception&) {
        return 0;
    }
    if (!document.is_object() || !document.contains("content")) return 0;
    std::string sealed;
    const nlohmann::json& genomes = document.contains("genomes") ? document["genomes"] : nlohmann::json();
    if (genomes.is_object() && genomes.contains("count") && genomes["count"].is_number_unsigned() &&
        genomes.contains("dimension") && genomes["dimension"].is_number_unsigned() && newline != std::string_view::npos) {
        CheckpointParts parts{document["content"], std::string(text.substr(newline + 1)),
                              genomes["count"].get<std::uint64_t>(), genomes["dimension"].get<std::uint64_t>()};
        sealed = checkpoint_bytes(parts);
    } else {
        sealed = checkpoint_text(document["content"]);
    }
    if (sealed != text) accepts([&] { (void)load_checkpoint_bytes(sealed); });
    return 0;
}
