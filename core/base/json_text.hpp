#pragma once
// The one strict reader for every JSON document a user hands morphogen
// (experiment configs, genome files, checkpoints). It accepts exactly one JSON
// object and nothing else, so a damaged or hostile file is refused, never
// crashes, hangs or is half-read:
//   - nesting deeper than max_json_depth is refused while parsing (the parse is
//     iterative; nlohmann's copy, dump and comparison recurse, so a deeper
//     document would overflow the stack later);
//   - a number beyond the range of a double (1e309) is refused;
//   - a NUL byte anywhere is refused (nlohmann's lexer would take it for the
//     end of the input and ignore what follows), as is anything after the
//     document;
//   - a document that is not an object (null, [], 3) is refused;
//   - a duplicate key in an object is refused (readers differ on which wins).
// Errors carry line, column (1-based, in bytes) and the key path of the value
// being read ("growth.speed", "network.hidden[2]") where there is one.
// Callers turn JsonTextError into their own error type (ConfigError for a
// config, IoError for a genome file, CheckpointError for a checkpoint).
#include <nlohmann/json.hpp>

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

namespace morphogen {

// Containers (objects and arrays) nested deeper than this are refused. The
// deepest document morphogen writes nests 6 levels (a checkpoint's genomes).
inline constexpr std::size_t max_json_depth = 256;

// Deliberately not a morphogen::Error: every caller must decide which error
// (and exit code) a malformed document of its kind is.
struct JsonTextError : std::runtime_error {
    JsonTextError(std::size_t line, std::size_t column, std::string key_path, std::string reason);
    std::size_t line;
    std::size_t column;
    std::string key_path;  // "" at the top of the document
    std::string reason;    // one line, e.g. "duplicate key \"steps\""
    // what() is "line L, column C[, in PATH]: REASON", one line; callers prefix
    // "invalid JSON at " and the file.
};

// Parses `text` as one JSON object (see above); throws JsonTextError.
nlohmann::json read_json_object(std::string_view text);

}  // namespace morphogen
