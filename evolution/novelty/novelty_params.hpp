#pragma once
// Parameters of novelty search with local competition (docs/algorithm.md
// §14.7; the `evolution` section's novelty_* keys, read only for "nslc").
// Defaults are the documented ones (docs/config-search.md, configs/schema.json).
#include <cstdint>

namespace morphogen {

struct NoveltyParams {
    int k = 15;                    // novelty_k: neighbours that novelty and local competition count
    std::uint64_t archive = 1000;  // novelty_archive: the archive's most points (the oldest leaves first); 0: none
    double archive_rate = 0.05;    // novelty_archive_rate: probability a valid child enters the archive
};

}  // namespace morphogen
