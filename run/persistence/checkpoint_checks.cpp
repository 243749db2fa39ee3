#include "run/persistence/checkpoint_checks.hpp"

#include "evolution/ga/population_stats.hpp"
#include "evolution/emitters/emitter_registry.hpp"
#include "evolution/execution/schedule.hpp"
#include "core/growth/network/network.hpp"
#include "run/loop/run_records.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace morphogen {

namespace {
[[noreturn]] void contradiction(const std::string& what) { throw std::invalid_argument(what); }

std::string at(const char* field, std::size_t index) { return std::string(field) + "[" + std::to_string(index) + "]"; }

bool is_vertex_count(double size) { return std::isfinite(size) && size >= 0 && size == std::floor(size); }

void check_size(const Individual& ind, const std::string& where) {
    if (!is_vertex_count(ind.size))
        contradiction(where + ".size is " + format_number(ind.size) + ", not a vertex count (a whole number >= 0)");
}

bool same(const Individual& a, const Individual& b) {
    return a.id == b.id && a.parent1 == b.parent1 && a.parent2 == b.parent2 && a.params == b.params &&
           (a.fitness == b.fitness || (!a.valid() && !b.valid())) && a.size == b.size;
}

SearchView view_of(const RunState& state) {
    if (!state.search) throw std::logic_error("a checkpoint's content needs the search's state");
    return state.search->view();
}

void check_history(const RunState& state, std::uint64_t P) {
    const SearchView v = view_of(state);
    double previous_elapsed = 0.0;
    for (std::size_t g = 0; g < state.history.size(); ++g) {
        const HistoryRow& row = state.history[g];
        const std::string where = at("history", g);
        if (row.births != (g + 1) * P)
            contradiction(where + ".births is " + std::to_string(row.births) + ", generation " + std::to_string(g) +
                          " ends at birth " + std::to_string((g + 1) * P));
        if (row.invalid > P)
            contradiction(where + ".invalid is " + std::to_string(row.invalid) + ", more than the " +
                          std::to_string(P) + " births of a generation");
        const bool any = row.best || row.mean || row.median || row.worst || row.mean_vertices;
        const bool all = row.best && row.mean && row.median && row.worst && row.mean_vertices;
        if (any != all) contradiction(where + ": some population statistics are missing and others are not");
        if (all) {
            if (!(*row.worst <= *row.median && *row.median <= *row.best))
                contradiction(where + ": worst, median and best are not in order");
            if (!(*row.mean_vertices >= 0)) contradiction(where + ".mean_vertices is negative");
            if (!*v.best || *row.best > (*v.best)->fitness)
                contradiction(where + ".best is better than the best individual ever born (" +
                              std::string(state.search->key()) + ".best)");
        }
        if (!std::isfinite(row.births_per_s) || row.births_per_s < 0)
            contradiction(where + ".births_per_s is " + format_number(row.births_per_s) + ", not a rate >= 0");
        if (!std::isfinite(row.elapsed_s) || row.elapsed_s < previous_elapsed)
            contradiction(where + ".elapsed_s is " + format_number(row.elapsed_s) +
                          ", negative or before the previous row's");
        previous_elapsed = row.elapsed_s;
    }
    if (previous_elapsed > state.elapsed_s)
        contradiction("elapsed_s is " + format_number(state.elapsed_s) + ", before the last history row's " +
                      format_number(previous_elapsed));
}

// One lineage.csv row, parsed.
struct LineageRow {
    std::uint64_t id = 0;
    std::string_view text;  // the row with its newline
    std::size_t columns = 0;  // descriptor cells after the fitness
    bool valid = false;
    double fitness = 0.0;
    std::optional<std::uint64_t> parent1, parent2;
    std::vector<double> descriptors;  // a valid birth's descriptor cells, when they all read as numbers
};

std::uint64_t parse_u64(std::string_view cell, const std::string& where) {
    std::uint64_t value = 0;
    const auto [end, error] = std::from_chars(cell.data(), cell.data() + cell.size(), value);
    if (error != std::errc() || end != cell.data() + cell.size()) contradiction(where + ": not a birth index");
    return value;
}

std::vector<LineageRow> parse_lineage(std::string_view lineage, std::uint64_t births, const std::string& name,
                                      std::string_view header) {
    if (lineage.substr(0, header.size()) != header) contradiction("lineage.csv does not start with its header");
    const auto commas = std::count(header.begin(), header.end(), ',');
    std::vector<LineageRow> rows;
    std::size_t pos = header.size();
    while (pos < lineage.size()) {
        const std::size_t end = lineage.find('\n', pos);
        const std::string where = "lineage.csv row " + std::to_string(rows.size() + 1);
        if (end == std::string_view::npos) contradiction(where + " has no end of line");
        LineageRow row;
        row.text = lineage.substr(pos, end + 1 - pos);
        const std::string_view line = lineage.substr(pos, end - pos);
        if (std::count(line.begin(), line.end(), ',') != commas)
            contradiction(where + " does not have " + std::to_string(commas + 1) + " cells");
        row.id = parse_u64(line.substr(0, line.find(',')), where);
        if (row.id != rows.size()) contradiction(where + " has id " + std::to_string(row.id) + ", not " +
                                                 std::to_string(rows.size()));
        // id,birth,parent1,parent2,fitness,...: the parents are cells 2 and 3.
        std::size_t cell = line.find(',', line.find(',') + 1) + 1;
        for (std::optional<std::uint64_t>* parent : {&row.parent1, &row.parent2}) {
            const std::size_t end_of_cell = line.find(',', cell);
            if (const std::string_view text = line.substr(cell, end_of_cell - cell); !text.empty())
                *parent = parse_u64(text, where);
            cell = end_of_cell + 1;
        }
        std::size_t fitness_start = 0;  // after the 4th comma
        for (int k = 0; k < 4; ++k) fitness_start = line.find(',', fitness_start) + 1;
        const std::string_view fitness = line.substr(fitness_start, line.find(',', fitness_start) - fitness_start);
        row.columns = static_cast<std::size_t>(commas) - 4;
        if (!fitness.empty()) {
            const auto [stop, error] = std::from_chars(fitness.data(), fitness.data() + fitness.size(), row.fitness);
            if (error != std::errc() || stop != fitness.data() + fitness.size() || !std::isfinite(row.fitness))
                contradiction(where + ": the fitness is not a number");
            row.valid = true;
            std::size_t at = line.find(',', fitness_start);
            for (std::size_t d = 0; d < row.columns && at != std::string_view::npos; ++d) {
                const std::size_t next = line.find(',', at + 1);
                const std::string_view text = line.substr(at + 1, next - at - 1);
                double value = 0;
                const auto [stop, error] = std::from_chars(text.data(), text.data() + text.size(), value);
                if (text.empty() || error != std::errc() || stop != text.data() + text.size()) break;
                row.descriptors.push_back(value);
                at = next;
            }
            if (row.descriptors.size() != row.columns) row.descriptors.clear();
        }
        rows.push_back(row);
        pos = end + 1;
    }
    if (rows.size() != births)
        contradiction(name + ".births is " + std::to_string(births) + " but lineage.csv records " +
                      std::to_string(rows.size()) + " births");
    return rows;
}

// A GA's state does not keep its members' descriptors, so only the cells up
// to the fitness are compared then; a MAP-Elites elite keeps them, and its
// whole row is.
void check_recorded(const Individual& ind, const std::vector<LineageRow>& rows, const std::string& where) {
    const LineageRow& row = rows.at(ind.id);
    std::string_view recorded = row.text;
    std::string expected = format_lineage_row(ind, ind.descriptors.empty() ? 0 : row.columns);
    if (ind.descriptors.empty() && row.columns > 0) {
        expected.pop_back();  // compare "id,...,fitness," with the row's start
        expected += ',';
        recorded = recorded.substr(0, expected.size());
    }
    if (expected != recorded)
        contradiction(where + " (id " + std::to_string(ind.id) + ") differs from its lineage.csv row");
}

std::uint64_t invalid_between(const std::vector<LineageRow>& rows, std::uint64_t first, std::uint64_t end) {
    std::uint64_t invalid = 0;
    for (std::uint64_t i = first; i < end; ++i) invalid += rows[i].valid ? 0 : 1;
    return invalid;
}

// The checkpoint is taken at a generation's end, so its last history row
// summarises the population (or the archive) it holds.
void check_last_row(const RunState& state, const ExperimentConfig& config, std::uint64_t P) {
    if (state.history.empty() || state.births() != state.history.size() * P) return;
    const std::size_t g = state.history.size() - 1;
    const HistoryRow& row = state.history[g];
    HistoryRow expected;
    state.search->fill(expected, config);
    const std::string source = view_of(state).members_source;
    check_row_stats(row, g, {expected.best, expected.mean, expected.median, expected.worst, expected.mean_vertices},
                    true, source);
    if (expected.qd && (row.coverage != expected.coverage || row.qd_score != expected.qd_score))
        contradiction(at("history", g) + " has coverage " + format_number(row.coverage) + " and qd_score " +
                      format_number(row.qd_score) + ", but " + source + " gives " + format_number(expected.coverage) +
                      " and " + format_number(expected.qd_score));
}

// One entry per birth of lineage.csv, for the search's own checks.
std::vector<RecordedBirth> recorded_births(const std::vector<LineageRow>& rows) {
    std::vector<RecordedBirth> recorded;
    recorded.reserve(rows.size());
    for (const LineageRow& row : rows)
        recorded.push_back({row.valid, row.fitness, row.parent1, row.parent2, row.descriptors});
    return recorded;
}
}  // namespace

// A history row's fitness columns (and, with `sizes`, its mean vertices)
// against the statistics of the members they summarise.
void check_row_stats(const HistoryRow& row, std::size_t g, const PopulationStats& stats, bool sizes,
                     const std::string& source) {
    const auto check = [&](const char* column, const std::optional<double>& recorded,
                           const std::optional<double>& recomputed) {
        if (recorded == recomputed) return;
        const auto text = [](const std::optional<double>& v) { return v ? format_number(*v) : std::string("empty"); };
        contradiction(at("history", g) + "." + column + " is " + text(recorded) + ", but " + source + " gives " +
                      text(recomputed));
    };
    check("best", row.best, stats.best);
    check("mean", row.mean, stats.mean);
    check("median", row.median, stats.median);
    check("worst", row.worst, stats.worst);
    if (sizes) check("mean_vertices", row.mean_vertices, stats.mean_size);
}

void check_parents_recorded_valid(std::span<const Individual> pending, std::span<const RecordedBirth> recorded,
                                  const BirthSchedule& schedule) {
    for (std::size_t i = 0; i < pending.size(); ++i) {
        const Individual& child = pending[i];
        const std::uint64_t source = schedule.source(child.id);
        for (const std::optional<std::uint64_t>& parent : {child.parent1, child.parent2})
            if (parent && (*parent >= source || *parent >= recorded.size() || !recorded[*parent].valid))
                contradiction(at("pending", i) + " (birth " + std::to_string(child.id) + ") has parent " +
                              std::to_string(*parent) + ", not a valid birth before its source state (" +
                              std::to_string(source) + " births) in lineage.csv");
    }
}

BirthReplay birth_replay(const ExperimentConfig& config) {
    const std::vector<int> layers = config.network.layers();
    return {config.evolution, config.run.seed, neuron_blocks(layers), parameter_count(layers),
            config.qd.emitters.empty() && config.algorithm == Algorithm::map_elites ? default_emitters() : config.qd.emitters};
}

// The pending births are exactly those the run's schedule keeps (births
// conceived from an earlier state), unevaluated, with parents that existed in
// the state each was conceived from.
void check_pending(const RunState& state, const ExperimentConfig& config, std::uint64_t births) {
    const BirthSchedule schedule = birth_schedule(config.evolution);
    const std::uint64_t begin = schedule.kept_begin(births), end = schedule.kept_end(births);
    if (state.pending.size() != end - begin)
        contradiction("pending holds " + std::to_string(state.pending.size()) + " births, but after " +
                      std::to_string(births) + " births the schedule (" + schedule.describe() + ") keeps " +
                      std::to_string(end - begin));
    for (std::size_t i = 0; i < state.pending.size(); ++i) {
        const Individual& child = state.pending[i];
        const std::string where = at("pending", i);
        if (child.id != begin + i)
            contradiction(where + " is birth " + std::to_string(child.id) + ", expected " + std::to_string(begin + i));
        if (child.valid() || child.size != 0.0) contradiction(where + " has a fitness or size before its evaluation");
        const std::uint64_t source = schedule.source(child.id);
        if ((child.parent1 && *child.parent1 >= source) || (child.parent2 && *child.parent2 >= source))
            contradiction(where + " has a parent born after the " + std::to_string(source) +
                          " births it was conceived from");
    }
}

void check_checkpoint_content(const RunState& state, const ExperimentConfig& config) {
    const auto P = static_cast<std::uint64_t>(config.evolution.population);
    const SearchView v = view_of(state);
    const std::string name = state.search->key();
    const std::uint64_t births = v.births;
    if (!std::isfinite(state.elapsed_s) || state.elapsed_s < 0)
        contradiction("elapsed_s is " + format_number(state.elapsed_s) + ", not a duration >= 0");
    if (births > (config.run.generations + 1) * P)
        contradiction(name + ".births is " + std::to_string(births) + ", beyond the " +
                      std::to_string((config.run.generations + 1) * P) + " births of its run.generations " +
                      std::to_string(config.run.generations));
    if (state.lineage_bytes < std::string_view(lineage_header).size())
        contradiction("lineage.bytes is " + std::to_string(state.lineage_bytes) +
                      ", shorter than lineage.csv's header");
    if (state.lineage_hash.size() != 16 ||
        state.lineage_hash.find_first_not_of("0123456789abcdef") != std::string::npos)
        contradiction("lineage.hash is not 16 lower-case hex digits");

    const std::optional<Individual>& best = *v.best;
    if (best) check_size(*best, name + ".best");
    bool any_valid = false;
    for (std::size_t i = 0; i < v.members.size(); ++i) {
        const Individual& member = *v.members[i];
        const std::string where = at(v.members_name.c_str(), i);
        check_size(member, where);
        if (v.members_are_first_births && births <= P && (member.id != i || member.parent1))
            contradiction(where + ": in generation 0 slot " + std::to_string(i) + " holds birth " +
                          std::to_string(i) + ", which has no parents");
        any_valid = any_valid || member.valid();
        if (best && member.valid() && member.fitness > best->fitness)
            contradiction(where + " (id " + std::to_string(member.id) + ") is better than " + name + ".best");
        if (best && member.id == best->id && !(same(member, *best) && member.descriptors == best->descriptors))
            contradiction(where + " has " + name + ".best's id " + std::to_string(member.id) + " but differs from it");
    }
    if (any_valid && !best) contradiction(name + ".best is null though the population has valid members");
    for (const HistoryRow& row : state.history)
        if (row.new_cells > P || row.coverage > 1.0)
            contradiction("history: new_cells or coverage out of range in generation " + std::to_string(row.generation));
    check_history(state, P);
    check_last_row(state, config, P);
    check_pending(state, config, births);
}

void check_checkpoint_against_lineage(const RunState& state, std::string_view lineage, std::uint64_t P,
                                      std::string_view header, const BirthReplay* pending_parents) {
    const SearchView v = view_of(state);
    const std::string name = state.search->key();
    const std::optional<Individual>& best = *v.best;
    const std::vector<LineageRow> rows = parse_lineage(lineage, v.births, name, header);
    for (std::size_t i = 0; i < v.members.size(); ++i) check_recorded(*v.members[i], rows, at(v.members_name.c_str(), i));
    const LineageRow* first_best = nullptr;
    for (const LineageRow& row : rows)
        if (row.valid && (first_best == nullptr || row.fitness > first_best->fitness)) first_best = &row;
    if (best) {
        check_recorded(*best, rows, name + ".best");
        if (first_best == nullptr || first_best->id != best->id)
            contradiction(name + ".best (id " + std::to_string(best->id) +
                          ") is not the first birth of the highest fitness in lineage.csv");
    } else if (first_best != nullptr) {
        contradiction(name + ".best is null but lineage.csv records valid birth " + std::to_string(first_best->id));
    }
    for (std::size_t g = 0; g < state.history.size(); ++g) {
        const std::uint64_t invalid = invalid_between(rows, g * P, (g + 1) * P);
        if (state.history[g].invalid != invalid)
            contradiction(at("history", g) + ".invalid is " + std::to_string(state.history[g].invalid) +
                          ", lineage.csv records " + std::to_string(invalid) + " invalid births in generation " +
                          std::to_string(g));
    }
    const std::vector<RecordedBirth> recorded = recorded_births(rows);
    state.search->check_history(state.history, recorded, P);
    if (pending_parents != nullptr)
        state.search->check_pending_parents(state.pending, recorded, *pending_parents,
                                            birth_schedule(pending_parents->params));
    const std::uint64_t current = state.history.size() * P;
    if (v.invalid_in_generation != invalid_between(rows, current, v.births))
        contradiction(name + ".invalid_in_generation is " + std::to_string(v.invalid_in_generation) +
                      ", lineage.csv records " + std::to_string(invalid_between(rows, current, v.births)));
}

}  // namespace morphogen
