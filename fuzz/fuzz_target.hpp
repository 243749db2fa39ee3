#pragma once
// What every morphogen fuzz target shares (docs/limits.md, "Fuzzing").
//
// A target feeds its bytes to one reader. The only accepted outcomes are a
// normal return and morphogen's documented failures (morphogen::Error and its
// subclasses, core/base/errors.hpp). Anything else is a finding: another exception
// (reported with its type and message, then abort()), a crash, a sanitizer
// report, or a hang (libFuzzer's -timeout; the corpus replay's alarm).
//
// The same target sources are linked two ways: with libFuzzer (clang, build-fuzz/,
// MORPHOGEN_FUZZ=ON) and with replay_main.cpp (any compiler, the normal build),
// which calls LLVMFuzzerTestOneInput on every file of tests/corpus/<target>/.
#include "core/base/errors.hpp"

#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace morphogen::fuzz {

// Reports a finding on stderr ("fuzz finding: ...") and aborts, so libFuzzer
// saves the input and the replay test fails.
[[noreturn]] void finding(const std::string& what);

// Runs `read`; returns true if it returned normally, false if it threw a
// morphogen::Error. Any other exception is a finding.
template <class Read>
bool accepts(Read&& read);

// The bytes of a corpus file as the target's LLVMFuzzerTestOneInput expects
// them. Identity for every target except mesh, which prefixes the format byte
// chosen by the file's extension (fuzz_mesh.cpp). Defined by each target.
std::string input_from_file(const std::string& filename, std::string bytes);

// ---------------------------------------------------------------- implementation

[[noreturn]] void report_exception(const std::exception& e);  // finding(): type and message
[[noreturn]] void report_unknown_exception();  // finding(): not a std::exception

template <class Read>
bool accepts(Read&& read) {
    try {
        read();
        return true;
    } catch (const Error&) {
        return false;
    } catch (const std::exception& e) {
        report_exception(e);
    } catch (...) {
        report_unknown_exception();
    }
}

inline std::string_view as_text(const std::uint8_t* data, std::size_t size) {
    return {reinterpret_cast<const char*>(data), size};
}

}  // namespace morphogen::fuzz
