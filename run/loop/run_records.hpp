#pragma once
// The rows of history.csv and lineage.csv. Numbers are written in shortest
// round-trip form (std::to_chars), so the files are exact records: parsing a
// cell gives back the very double that was computed. An empty cell means "no
// value" (an invalid individual's fitness; stats of a population with no
// valid member).
#include "evolution/individual.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace morphogen {

inline constexpr const char* history_header =
    "generation,births,best,mean,median,worst,mean_vertices,invalid,births_per_s,elapsed_s\n";
// MAP-Elites runs (statistics over the archive's elites; docs/algorithm.md §9.7).
inline constexpr const char* history_header_qd =
    "generation,births,best,mean,median,worst,mean_vertices,invalid,coverage,qd_score,new_cells,births_per_s,"
    "elapsed_s\n";
inline const char* history_header_for(bool qd) { return qd ? history_header_qd : history_header; }
inline constexpr const char* archive_header_tail = "fitness,id\n";  // archive.csv: cell,<descriptors>,fitness,id
inline constexpr const char* lineage_header = "id,birth,parent1,parent2,fitness\n";
// lineage.csv's header for a config with a `descriptors` list: one more
// column per descriptor, named by its measure; exactly lineage_header when
// there is none (runs without descriptors are as before).
std::string lineage_header_for(const std::vector<std::string>& descriptor_names);

struct HistoryRow {
    std::uint64_t generation = 0;
    std::uint64_t births = 0;  // births so far, this generation's included
    std::optional<double> best, mean, median, worst, mean_vertices;  // over valid members of the population
    std::uint64_t invalid = 0;  // invalid births in this generation
    double births_per_s = 0.0;  // timing: differs between runs
    double elapsed_s = 0.0;
    // MAP-Elites runs only (qd): occupied / all cells, sum of (fitness - qd_offset), cells first filled this generation.
    bool qd = false;
    double coverage = 0.0, qd_score = 0.0;
    std::uint64_t new_cells = 0;
};

// Shortest text that parses back to exactly `value` (finite values only).
std::string format_number(double value);
// With the QD columns exactly when row.qd.
std::string format_history_row(const HistoryRow& row);
// id,birth,parent1,parent2,fitness (birth repeats the id: ids are birth
// indices), then `descriptor_columns` cells: the individual's descriptors when
// it has exactly that many, all empty otherwise (an invalid birth, or a GA
// birth whose measures could not be taken).
std::string format_lineage_row(const Individual& individual, std::size_t descriptor_columns = 0);

// The QD keys (coverage, qd_score, new_cells) only when row.qd, so GA
// checkpoints are as before; read back when present.
nlohmann::json history_row_to_json(const HistoryRow& row);
// Throws std::invalid_argument naming the defect.
HistoryRow history_row_from_json(const nlohmann::json& value);

}  // namespace morphogen
