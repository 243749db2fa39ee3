#pragma once
// Exit codes of the morphogen CLI (documented in README.md and docs/limits.md).
namespace morphogen::exit_code {
inline constexpr int ok = 0;
inline constexpr int failure = 1;       // a run-time failure not covered below
inline constexpr int usage = 2;         // bad command line or invalid config
inline constexpr int io = 3;            // a file could not be read or written
inline constexpr int mesh = 4;          // a mesh (e.g. a seed file) is invalid
inline constexpr int checkpoint = 5;    // a checkpoint was refused
inline constexpr int interrupted = 130; // stopped by Ctrl-C/SIGTERM after saving
}  // namespace morphogen::exit_code
