#include "report/report_data.hpp"

#include "core/base/atomic_file.hpp"
#include "core/base/errors.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string_view>

namespace morphogen {

namespace {

namespace fs = std::filesystem;

// Complete lines only: a run in progress may be halfway through appending one.
std::vector<std::string_view> complete_lines(std::string_view text) {
    std::vector<std::string_view> lines;
    std::size_t start = 0;
    for (std::size_t end; (end = text.find('\n', start)) != std::string_view::npos; start = end + 1) {
        std::string_view line = text.substr(start, end - start);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        lines.push_back(line);
    }
    return lines;
}

std::vector<std::string_view> split_cells(std::string_view line) {
    std::vector<std::string_view> cells;
    std::size_t start = 0;
    for (std::size_t comma; (comma = line.find(',', start)) != std::string_view::npos; start = comma + 1)
        cells.push_back(line.substr(start, comma - start));
    cells.push_back(line.substr(start));
    return cells;
}

[[noreturn]] void fail(const fs::path& path, std::size_t line, const std::string& what) {
    throw IoError(path.string() + ": line " + std::to_string(line) + ": " + what);
}

std::optional<double> parse_cell(std::string_view cell, const fs::path& path, std::size_t line,
                                 const std::string& column) {
    if (cell.empty()) return std::nullopt;
    double value = 0;
    const auto [end, ec] = std::from_chars(cell.data(), cell.data() + cell.size(), value);
    if (ec != std::errc() || end != cell.data() + cell.size() || !std::isfinite(value))
        fail(path, line, column + " is \"" + std::string(cell.substr(0, 40)) + "\", not a finite number");
    return value;
}

}  // namespace

NumericCsv read_numeric_csv(const fs::path& path, const std::vector<std::string>& required) {
    std::error_code ec;
    if (!fs::exists(fs::symlink_status(path, ec))) throw IoError(path.string() + " is missing");
    const std::string text = read_file_bytes(path, memory_bound("run records (this machine's memory)"));
    const std::vector<std::string_view> lines = complete_lines(text);
    if (lines.empty() && text.empty()) throw IoError(path.string() + ": empty (no header line)");
    if (lines.empty())
        throw IoError(path.string() + ": no header line (" + std::to_string(text.size()) + " bytes without an end of line)");
    NumericCsv csv;
    for (std::string_view name : split_cells(lines[0])) {
        if (csv.columns.count(std::string(name))) fail(path, 1, "column " + std::string(name) + " appears twice");
        csv.names.emplace_back(name);
        csv.columns[std::string(name)];
    }
    for (const std::string& name : required)
        if (!csv.columns.count(name)) fail(path, 1, "no " + name + " column in the header");
    for (std::size_t i = 1; i < lines.size(); ++i) {
        const std::vector<std::string_view> cells = split_cells(lines[i]);
        if (cells.size() != csv.names.size())
            fail(path, i + 1, std::to_string(cells.size()) + " cells, the header has " + std::to_string(csv.names.size()));
        for (std::size_t c = 0; c < cells.size(); ++c)
            csv.columns[csv.names[c]].push_back(parse_cell(cells[c], path, i + 1, csv.names[c]));
    }
    csv.rows = lines.size() - 1;
    return csv;
}

Lineage read_lineage(const fs::path& path) {
    const NumericCsv csv = read_numeric_csv(path, {"id", "parent1", "parent2", "fitness"});
    constexpr double max_id = 9007199254740992.0;  // 2^53: every id below is exact as a double
    auto as_id = [&](const std::optional<double>& v, std::size_t row, const char* column, bool required)
        -> std::optional<std::uint64_t> {
        if (!v) {
            if (required) fail(path, row + 2, std::string(column) + " is empty");
            return std::nullopt;
        }
        if (*v < 0 || *v >= max_id || std::floor(*v) != *v)
            fail(path, row + 2, std::string(column) + " is not a birth index");
        return static_cast<std::uint64_t>(*v);
    };
    Lineage lineage;
    lineage.parent1.reserve(csv.rows);
    for (std::size_t row = 0; row < csv.rows; ++row) {
        const std::uint64_t id = *as_id(csv.columns.at("id")[row], row, "id", true);
        if (id != row) fail(path, row + 2, "id " + std::to_string(id) + " where " + std::to_string(row) + " was expected");
        const auto p1 = as_id(csv.columns.at("parent1")[row], row, "parent1", false);
        const auto p2 = as_id(csv.columns.at("parent2")[row], row, "parent2", false);
        if ((p1 && *p1 >= id) || (p2 && *p2 >= id)) fail(path, row + 2, "a parent born after its child");
        lineage.parent1.push_back(p1);
        lineage.parent2.push_back(p2);
        lineage.fitness.push_back(csv.columns.at("fitness")[row]);
    }
    return lineage;
}

std::uint64_t generation_of(std::uint64_t id, const std::vector<std::uint64_t>& births) {
    return static_cast<std::uint64_t>(std::upper_bound(births.begin(), births.end(), id) - births.begin());
}

std::vector<std::uint64_t> ancestry(const Lineage& lineage, std::uint64_t id, const fs::path& source) {
    if (id >= lineage.size())
        throw IoError(source.string() + ": has no row for individual " + std::to_string(id) + " (" +
                      std::to_string(lineage.size()) + " rows)");
    std::vector<std::uint64_t> line{id};
    // Parents are born before their children (read_lineage checks), so this ends.
    while (lineage.parent1[line.back()]) line.push_back(*lineage.parent1[line.back()]);
    return line;
}

}  // namespace morphogen
