#pragma once
// Tests whose point is scale (many genomes, many trials, long growth) run a
// part of their work in the ASan/UBSan build, where code runs 5-15 times
// slower; the optimised build runs them whole. scripts/test.sh runs both, so
// each such test still runs whole once, and its every path runs instrumented.

namespace morphogen::testing {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kBuiltWithSanitizers = true;
#else
inline constexpr bool kBuiltWithSanitizers = false;
#endif

// `whole` in the optimised build; `reduced` under the sanitizers.
constexpr int whole_or_under_sanitizers(int whole, int reduced) { return kBuiltWithSanitizers ? reduced : whole; }

}  // namespace morphogen::testing
