#include "core/growth/genome_io.hpp"

#include "core/base/atomic_file.hpp"
#include "core/base/config_reader.hpp"
#include "core/base/errors.hpp"
#include "core/base/json_text.hpp"

#include <cmath>
#include <fstream>

namespace morphogen {

using nlohmann::json;

json genome_to_json(const Genome& genome) {
    return json{{"format", "morphogen-genome"}, {"version", 1}, {"layers", genome.layers}, {"params", genome.params}};
}

Genome genome_from_json(const json& document, const std::string& source) {
    auto fail = [&](const std::string& why) { throw IoError(source + ": not a valid genome file: " + why); };
    if (!document.is_object()) fail("expected a JSON object");
    if (!document.contains("format") || document["format"] != "morphogen-genome")
        fail("\"format\" must be \"morphogen-genome\"");
    if (!document.contains("version") || !document["version"].is_number_integer())
        fail("\"version\" is missing");
    if (document["version"].get<long long>() != 1)
        fail("version " + document["version"].dump() + " is not supported (this build reads version 1)");
    for (const auto& [key, value] : document.items())
        if (key != "format" && key != "version" && key != "layers" && key != "params")
            fail("unknown key " + json(key).dump(-1, ' ', false, json::error_handler_t::replace));
    Genome genome;
    const json* layers = document.contains("layers") ? &document["layers"] : nullptr;
    if (layers == nullptr || !layers->is_array() || layers->size() < 2) fail("\"layers\" must list at least two sizes");
    for (const json& size : *layers) {
        if (!size.is_number_integer() || size.get<long long>() < 1 || size.get<long long>() > 100000)
            fail("layer size " + size.dump() + " is not a positive integer");
        genome.layers.push_back(size.get<int>());
    }
    const json* params = document.contains("params") ? &document["params"] : nullptr;
    if (params == nullptr || !params->is_array()) fail("\"params\" must be a list of numbers");
    genome.params.reserve(params->size());
    for (std::size_t i = 0; i < params->size(); ++i) {
        const json& p = (*params)[i];
        if (!p.is_number() || !std::isfinite(p.get<double>()))
            fail("params[" + std::to_string(i) + "] is " + p.dump() + ", not a finite number");
        genome.params.push_back(p.get<double>());
    }
    if (genome.params.size() != parameter_count(genome.layers))
        fail("layers " + layers->dump() + " need " + std::to_string(parameter_count(genome.layers)) +
             " params, found " + std::to_string(genome.params.size()));
    // Finite parameters near the largest double can still overflow when the
    // network folds them (network.cpp): refuse them here, naming this file.
    try {
        (void)Network(genome);
    } catch (const ConfigError& e) {
        std::string why = e.what();
        if (why.rfind("network: ", 0) == 0) why.erase(0, 9);
        fail(why);
    }
    return genome;
}

void save_genome(const Genome& genome, const std::string& path) {
    write_file_atomically(path, genome_to_json(genome).dump() + "\n");
}

Genome load_genome(const std::string& path) {
    json document;
    try {
        document = read_json_object(read_document_file(path, memory_bound("genome files (this machine's memory)")));
    } catch (const JsonTextError& e) {
        throw IoError(path + ": not a valid genome file: invalid JSON at " + e.what());
    }
    return genome_from_json(document, path);
}

}  // namespace morphogen
