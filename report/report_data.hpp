#pragma once
// What `morphogen report` reads from a run directory besides the checkpoint:
// history.csv and lineage.csv, parsed by their header names (columns may be
// added), and the ancestry of one individual. Read-only; a run in progress
// may be appending, so a last line without its newline is ignored.
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace morphogen {

// A CSV of numbers with a header: columns[name] holds one value per row, none
// for an empty cell. Throws IoError naming the file (and line) for a missing
// file, a missing required column, a cell that is not a number, or a row with
// the wrong number of cells.
struct NumericCsv {
    std::vector<std::string> names;  // header order
    std::map<std::string, std::vector<std::optional<double>>> columns;
    std::size_t rows = 0;
};
NumericCsv read_numeric_csv(const std::filesystem::path& path, const std::vector<std::string>& required);

// lineage.csv reduced to what an ancestry needs, indexed by id (ids are birth
// indices 0, 1, 2, ... in order). Throws IoError as read_numeric_csv, and for
// ids out of order or a parent that is not born before its child.
struct Lineage {
    std::vector<std::optional<std::uint64_t>> parent1, parent2;
    std::vector<std::optional<double>> fitness;  // none: invalid
    std::size_t size() const { return parent1.size(); }
};
Lineage read_lineage(const std::filesystem::path& path);

// The generation that birth `id` belongs to: the first history row whose
// births (so far, that generation's included) exceed id; past the last row,
// the generation after it. `births` ascends.
std::uint64_t generation_of(std::uint64_t id, const std::vector<std::uint64_t>& births);

// The line of first parents from `id` back to an individual of the initial
// population: id first. Throws IoError (naming lineage.csv) if id is not in it.
std::vector<std::uint64_t> ancestry(const Lineage& lineage, std::uint64_t id, const std::filesystem::path& source);

}  // namespace morphogen
