#include "run/persistence/archive_csv.hpp"

#include "run/loop/run_records.hpp"

namespace morphogen {

std::string archive_csv(const Archive& archive) {
    std::string text = "cell,";
    for (const DescriptorRange& range : archive.ranges()) text += range.name + ',';
    text += archive_header_tail;
    for (const auto& [cell, elite] : archive.elites()) {
        text += std::to_string(cell) + ',';
        for (double d : elite.descriptors) text += format_number(d) + ',';
        text += format_number(elite.fitness) + ',' + std::to_string(elite.id) + '\n';
    }
    return text;
}

}  // namespace morphogen
