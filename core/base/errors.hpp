#pragma once
// The one small exception hierarchy of morphogen. Messages name the bad value
// and where it came from (file, key path, line), so a user can fix it without
// reading code. Exit codes of the CLI map from these types (run/exit_codes.hpp).
#include <stdexcept>
#include <string>

namespace morphogen {

struct Error : std::runtime_error {
    using std::runtime_error::runtime_error;
};
// A config value or key is wrong; the message lists every problem found.
struct ConfigError : Error { using Error::Error; };
// A mesh breaks an invariant (open, non-manifold, inward, degenerate, ...).
struct MeshError : Error { using Error::Error; };
// A file could not be read or written, or its contents are malformed.
struct IoError : Error { using Error::Error; };
// A checkpoint is truncated, corrupt or does not match the run.
struct CheckpointError : Error { using Error::Error; };

}  // namespace morphogen
