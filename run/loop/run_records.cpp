#include "run/loop/run_records.hpp"

#include <charconv>
#include <cmath>
#include <stdexcept>

namespace morphogen {

using nlohmann::json;

std::string format_number(double value) {
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

namespace {
std::string cell(const std::optional<double>& value) { return value ? format_number(*value) : std::string(); }

json optional_json(const std::optional<double>& value) { return value ? json(*value) : json(nullptr); }

std::optional<double> optional_from(const json& object, const char* key) {
    const json& value = object.at(key);
    if (value.is_null()) return std::nullopt;
    if (!value.is_number() || !std::isfinite(value.get<double>()))
        throw std::invalid_argument(std::string("history.") + key + ": expected a finite number or null");
    return value.get<double>();
}
}  // namespace

std::string format_history_row(const HistoryRow& r) {
    return std::to_string(r.generation) + ',' + std::to_string(r.births) + ',' + cell(r.best) + ',' + cell(r.mean) +
           ',' + cell(r.median) + ',' + cell(r.worst) + ',' + cell(r.mean_vertices) + ',' +
           std::to_string(r.invalid) + ',' +
           (r.qd ? format_number(r.coverage) + ',' + format_number(r.qd_score) + ',' + std::to_string(r.new_cells) + ','
                 : std::string()) +
           format_number(r.births_per_s) + ',' + format_number(r.elapsed_s) + '\n';
}

std::string lineage_header_for(const std::vector<std::string>& descriptor_names) {
    std::string header = lineage_header;
    header.pop_back();  // the newline
    for (const std::string& name : descriptor_names) header += ',' + name;
    return header + '\n';
}

std::string format_lineage_row(const Individual& ind, std::size_t descriptor_columns) {
    std::string row = std::to_string(ind.id) + ',' + std::to_string(ind.id) + ',';
    if (ind.parent1) row += std::to_string(*ind.parent1);
    row += ',';
    if (ind.parent2) row += std::to_string(*ind.parent2);
    row += ',';
    if (ind.valid()) row += format_number(ind.fitness);
    const bool measured = ind.descriptors.size() == descriptor_columns;
    for (std::size_t k = 0; k < descriptor_columns; ++k) {
        row += ',';
        if (measured) row += format_number(ind.descriptors[k]);
    }
    row += '\n';
    return row;
}

json history_row_to_json(const HistoryRow& r) {
    json row{{"generation", r.generation},        {"births", r.births},
                {"best", optional_json(r.best)},     {"mean", optional_json(r.mean)},
                {"median", optional_json(r.median)}, {"worst", optional_json(r.worst)},
                {"mean_vertices", optional_json(r.mean_vertices)}, {"invalid", r.invalid},
                {"births_per_s", r.births_per_s},    {"elapsed_s", r.elapsed_s}};
    if (r.qd) {
        row["coverage"] = r.coverage;
        row["qd_score"] = r.qd_score;
        row["new_cells"] = r.new_cells;
    }
    return row;
}

HistoryRow history_row_from_json(const json& value) {
    try {
        HistoryRow r;
        r.generation = value.at("generation").get<std::uint64_t>();
        r.births = value.at("births").get<std::uint64_t>();
        r.best = optional_from(value, "best");
        r.mean = optional_from(value, "mean");
        r.median = optional_from(value, "median");
        r.worst = optional_from(value, "worst");
        r.mean_vertices = optional_from(value, "mean_vertices");
        r.invalid = value.at("invalid").get<std::uint64_t>();
        r.births_per_s = value.at("births_per_s").get<double>();
        r.elapsed_s = value.at("elapsed_s").get<double>();
        if (value.contains("coverage")) {
            r.qd = true;
            r.coverage = value.at("coverage").get<double>();
            r.qd_score = value.at("qd_score").get<double>();
            r.new_cells = value.at("new_cells").get<std::uint64_t>();
            if (!std::isfinite(r.coverage) || !std::isfinite(r.qd_score) || r.coverage < 0 || r.coverage > 1)
                throw std::invalid_argument("history row: coverage or qd_score out of range");
        }
        return r;
    } catch (const json::exception& e) {
        throw std::invalid_argument(std::string("history row: ") + e.what());
    }
}

}  // namespace morphogen
