#include "engine/plant_record.hpp"

#include "core/base/fnv_hash.hpp"

#include <bit>
#include <cstdio>
#include <cstring>

namespace morphogen {

std::string genome_hash(std::span<const double> params) {
    std::string bytes(params.size() * 8, '\0');
    for (std::size_t i = 0; i < params.size(); ++i) {
        auto word = std::bit_cast<std::uint64_t>(params[i]);
        for (int b = 0; b < 8; ++b) bytes[8 * i + b] = static_cast<char>((word >> (8 * b)) & 0xff);
    }
    Fnv1a64 hash;
    hash.update(bytes);
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash.value()));
    return text;
}

nlohmann::json record_json(const PlantRecord& record) {
    nlohmann::json json = {{"id", record.id}, {"genome_hash", record.genome_hash}};
    if (record.fitness) json["fitness"] = *record.fitness;
    nlohmann::json measures = nlohmann::json::object();
    for (const auto& [name, value] : record.measures) measures[name] = value;
    if (!measures.empty()) json["measures"] = measures;
    if (!record.run.empty()) json["run"] = record.run;
    if (record.birth) json["birth_id"] = *record.birth;
    if (!record.parents.empty()) json["parents"] = record.parents;  // glTF tools drop empty arrays
    if (record.cell) json["cell"] = *record.cell;
    return json;
}

}  // namespace morphogen
