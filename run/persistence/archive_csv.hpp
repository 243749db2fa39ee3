#pragma once
// archive.csv of a MAP-Elites run: header `cell,<descriptor names>,fitness,id`
// and one row per occupied cell in cell order; numbers in shortest round-trip
// form (run_records.hpp), ids as in lineage.csv. Rewritten atomically with
// every checkpoint, so it always shows the archive the checkpoint holds.
#include "evolution/archives/archive.hpp"

#include <string>

namespace morphogen {

std::string archive_csv(const Archive& archive);

}  // namespace morphogen
