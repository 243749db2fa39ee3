#include "run/persistence/checkpoint.hpp"

#include "core/base/atomic_file.hpp"
#include "core/base/errors.hpp"
#include "core/base/json_text.hpp"
#include "evolution/ga/ga_state_json.hpp"
#include "evolution/genome_blob.hpp"
#include "core/growth/network/network.hpp"
#include "run/persistence/checkpoint_checks.hpp"
#include "run/config/config_migration.hpp"
#include "run/config/experiment_config.hpp"
#include "core/base/fnv_hash.hpp"
#include "run/searches/run_search.hpp"

#include <stdexcept>
#include <string_view>

namespace morphogen {

using nlohmann::json;

namespace {
constexpr const char* format_name = "morphogen-checkpoint";
constexpr const char* genome_encoding = "f64le";

json content_of(const RunState& state, GenomeBlobWriter* genomes) {
    if (!state.search) throw std::logic_error("a checkpoint needs the search's state");
    json history = json::array();
    for (const HistoryRow& row : state.history) history.push_back(history_row_to_json(row));
    json content{{"config", state.config},
                 {"seed", state.seed},
                 {"history", std::move(history)},
                 {"lineage", {{"bytes", state.lineage_bytes}, {"hash", state.lineage_hash}}},
                 {"elapsed_s", state.elapsed_s}};
    // The search's genomes before the pending births': the binary part's order.
    content[state.search->key()] = state.search->to_json(genomes);
    if (!state.pending.empty()) {
        json pending = json::array();
        for (const Individual& child : state.pending) pending.push_back(individual_to_json(child, genomes));
        content["pending"] = std::move(pending);
    }
    return content;
}

// The path of the first key in `stored` that `canonical` (the content written
// again from what was read) does not have, at any depth; empty when none.
// The hash guards against accidents only: a key added by hand with the hash
// recomputed is caught here.
std::string unknown_key(const json& stored, const json& canonical, const std::string& path) {
    if (stored.is_object() && canonical.is_object()) {
        for (const auto& [key, value] : stored.items()) {
            const std::string here = path.empty() ? key : path + "." + key;
            if (!canonical.contains(key)) return here;
            if (std::string inner = unknown_key(value, canonical[key], here); !inner.empty()) return inner;
        }
    } else if (stored.is_array() && canonical.is_array()) {
        for (std::size_t i = 0; i < stored.size() && i < canonical.size(); ++i)
            if (std::string inner = unknown_key(stored[i], canonical[i], path + "[" + std::to_string(i) + "]");
                !inner.empty())
                return inner;
    }
    return {};
}

// FNV-1a 64 of the content's dump, continued over the binary part word by
// word (Fnv1a64::update_words; its length is a multiple of 8).
std::string content_hash(const std::string& dumped_content, std::string_view genomes) {
    Fnv1a64 h;
    h.update(dumped_content);
    h.update_words(genomes);
    return h.hex();
}

// The header line of formats 2 and 3 without its "\n": the document's canonical dump
// (keys sorted), built around the content's dump so it is dumped only once.
std::string format2_header(const std::string& dumped_content, std::string_view genomes, std::uint64_t count,
                           std::uint64_t dimension) {
    return "{\"content\":" + dumped_content + ",\"format\":\"" + format_name + "\",\"genomes\":{\"count\":" +
           std::to_string(count) + ",\"dimension\":" + std::to_string(dimension) + ",\"encoding\":\"" +
           genome_encoding + "\"},\"hash\":\"" + content_hash(dumped_content, genomes) +
           "\",\"version\":" + std::to_string(checkpoint_version) + "}";
}

std::string sealed_format2(const json& content, std::string_view genomes, std::uint64_t count,
                           std::uint64_t dimension) {
    std::string out = format2_header(content.dump(), genomes, count, dimension);
    out.reserve(out.size() + 1 + genomes.size());
    out += '\n';
    out.append(genomes);
    return out;
}

// Genomes a state holds (its members and best, and the pending births), for reserving.
std::size_t genome_doubles(const RunState& state) {
    if (!state.search) return 0;
    const SearchView v = state.search->view();
    const std::size_t D = *v.best ? (*v.best)->params.size() : (v.members.empty() ? 0 : v.members.front()->params.size());
    return (v.members.size() + 1 + state.pending.size()) * D;
}

// A verified envelope: the content as stored and, from format 2, the binary part
// (a view into the checked text).
struct Envelope {
    int version = 0;
    json content;
    std::string_view genomes;
    std::uint64_t count = 0;
    std::uint64_t dimension = 0;
};

Envelope open_envelope(const std::string& text, const std::string& source) {
    auto refuse = [&](const std::string& why) -> CheckpointError {
        return CheckpointError("checkpoint " + source + " refused: " + why);
    };
    if (text.empty()) throw refuse("the file is empty");
    // The header never holds a raw newline (dump() escapes it in strings).
    const std::size_t newline = text.find('\n');
    const std::string_view header = std::string_view(text).substr(0, newline);
    json document;
    try {
        document = read_json_object(header);
    } catch (const JsonTextError& e) {
        throw refuse(std::string("invalid JSON (truncated, corrupt or hostile) at ") + e.what());
    }
    if (!document.is_object() || !document.contains("format") || document["format"] != format_name)
        throw refuse("not a morphogen checkpoint (\"format\" is not \"" + std::string(format_name) + "\")");
    if (!document.contains("version") || !document["version"].is_number_integer())
        throw refuse("it has no version number");
    const std::string versions = "this build reads versions 1 to " + std::to_string(checkpoint_version);
    if (document["version"] > checkpoint_version)
        throw refuse("version " + document["version"].dump() + " was written by a newer morphogen (" + versions +
                     "): resume it with that build");
    if (document["version"] < 1)
        throw refuse("version " + document["version"].dump() + " is not supported (" + versions + ")");
    Envelope envelope;
    envelope.version = document["version"].get<int>();
    if (!document.contains("content") || !document.contains("hash") || !document["hash"].is_string())
        throw refuse("\"content\" or \"hash\" is missing");
    if (envelope.version == 1) {
        if (document.size() != 4) throw refuse("unexpected keys besides format, version, hash, content");
        const std::string expected = fnv1a64_hex(document["content"].dump());
        if (document["hash"] != expected)
            throw refuse("content hash mismatch (corrupt): stored " + document["hash"].get<std::string>() +
                         ", computed " + expected);
        if (checkpoint_text(document["content"]) != text)
            throw refuse("the file is not in the form morphogen writes (edited or corrupt)");
        envelope.content = std::move(document["content"]);
        return envelope;
    }
    if (document.size() != 5) throw refuse("unexpected keys besides format, version, genomes, hash, content");
    const json& genomes = document.contains("genomes") ? document["genomes"] : json();
    if (!genomes.is_object() || genomes.size() != 3 || !genomes.contains("count") ||
        !genomes["count"].is_number_unsigned() || !genomes.contains("dimension") ||
        !genomes["dimension"].is_number_unsigned() || !genomes.contains("encoding") ||
        genomes["encoding"] != genome_encoding)
        throw refuse("\"genomes\" is not {\"count\": N, \"dimension\": D, \"encoding\": \"" +
                     std::string(genome_encoding) + "\"}");
    envelope.count = genomes["count"].get<std::uint64_t>();
    envelope.dimension = genomes["dimension"].get<std::uint64_t>();
    if (newline == std::string::npos) throw refuse("truncated: the header line has no end");
    envelope.genomes = std::string_view(text).substr(newline + 1);
    // count x dimension x 8 bytes, compared without overflow; dimension is 0
    // exactly when there are no genomes (so no byte of the header is free).
    const std::uint64_t size = envelope.genomes.size();
    const bool sized = envelope.dimension == 0
                           ? size == 0 && envelope.count == 0
                           : envelope.count > 0 && size % (8 * envelope.dimension) == 0 &&
                                 size / (8 * envelope.dimension) == envelope.count &&
                                 envelope.dimension < (std::uint64_t{1} << 56);
    if (!sized)
        throw refuse("its binary part holds " + std::to_string(size) + " bytes, the header announces " +
                     std::to_string(envelope.count) + " genomes x " + std::to_string(envelope.dimension) +
                     " doubles (truncated or corrupt)");
    const std::string expected = content_hash(document["content"].dump(), envelope.genomes);
    if (document["hash"] != expected)
        throw refuse("content hash mismatch (corrupt): stored " + document["hash"].get<std::string>() +
                     ", computed " + expected);
    if (document.dump() != header) throw refuse("the file is not in the form morphogen writes (edited or corrupt)");
    // Versions 2 and 3 differ only in the config's format, which the version
    // must tell (the hash does not cover it): 3 has format_version, 2 (0.1.0) not.
    const json& content = document["content"];
    const bool versioned_config = content.is_object() && content.contains("config") &&
                                  content["config"].is_object() && content["config"].contains(config_format_key);
    if (versioned_config != (envelope.version == checkpoint_version))
        throw refuse("version " + std::to_string(envelope.version) + " with a config " +
                     (versioned_config ? "with" : "without") + " format_version (edited or corrupt)");
    envelope.content = std::move(document["content"]);
    return envelope;
}

// Replaces the "genome": k of an individual object by its "params" array.
void inline_genome(json& individual, GenomeBlobReader& genomes, const std::string& path) {
    if (!individual.is_object() || !individual.contains("genome")) return;
    const json& index = individual["genome"];
    if (!index.is_number_unsigned()) throw std::invalid_argument(path + ".genome: expected a non-negative integer");
    individual["params"] = genomes.take(index.get<std::uint64_t>(), path + ".genome");
    individual.erase("genome");
}

void inline_genomes(json& content, GenomeBlobReader& genomes) {
    const auto inline_one = [&](json& individual, const std::string& path) { inline_genome(individual, genomes, path); };
    for (const SearchKind& kind : search_kinds())
        if (content.contains(kind.key)) kind.each_genome(content[kind.key], inline_one);
    if (content.contains("pending") && content["pending"].is_array())
        for (std::size_t i = 0; i < content["pending"].size(); ++i)
            inline_genome(content["pending"][i], genomes, "pending[" + std::to_string(i) + "]");
    genomes.check_all_taken("the checkpoint");
}
}  // namespace

std::string checkpoint_text(const json& content) {
    const json document{{"format", format_name},
                        {"version", 1},
                        {"hash", fnv1a64_hex(content.dump())},
                        {"content", content}};
    return document.dump() + "\n";
}

json checkpoint_content(const std::string& text, const std::string& source) {
    Envelope envelope = open_envelope(text, source);
    if (envelope.version >= 2) {
        try {
            GenomeBlobReader genomes(envelope.genomes, envelope.count, envelope.dimension);
            inline_genomes(envelope.content, genomes);
        } catch (const std::invalid_argument& e) {
            throw CheckpointError("checkpoint " + source + " refused: its genomes do not fit: " + e.what());
        }
    }
    return std::move(envelope.content);
}

CheckpointParts checkpoint_parts(const std::string& bytes, const std::string& source) {
    Envelope envelope = open_envelope(bytes, source);
    if (envelope.version < 2) throw CheckpointError("checkpoint " + source + " is not in format 2 or later");
    return {std::move(envelope.content), std::string(envelope.genomes), envelope.count, envelope.dimension};
}

std::string checkpoint_bytes(const CheckpointParts& parts) {
    return sealed_format2(parts.content, parts.genomes, parts.count, parts.dimension);
}

std::string checkpoint_bytes(const RunState& state) {
    GenomeBlobWriter genomes;
    genomes.reserve(genome_doubles(state));
    const json content = content_of(state, &genomes);
    return sealed_format2(content, genomes.bytes(), genomes.count(), genomes.dimension());
}

void save_checkpoint(const std::filesystem::path& path, const RunState& state) {
    // The header and the genomes written as two parts: the genomes are never copied.
    GenomeBlobWriter genomes;
    genomes.reserve(genome_doubles(state));
    const json content = content_of(state, &genomes);
    const std::string header = format2_header(content.dump(), genomes.bytes(), genomes.count(), genomes.dimension()) + "\n";
    const std::string_view parts[] = {header, genomes.bytes()};
    write_file_atomically(path, parts);
}

namespace {

// "checkpoint <path> refused: <why>".
struct Refusal {
    std::string source;
    CheckpointError operator()(const std::string& why) const {
        return CheckpointError("checkpoint " + source + " refused: " + why);
    }
};

// The content's config, read and checked to be a resolved one. A config
// without format_version is of format 1 (0.1.0's checkpoints, versions 1 and
// 2) and must hold all of what it migrates to; a versioned one must be
// exactly what it migrates to (run/config/config_migration.hpp: the keys
// format 2 left out at first). Version 1 is also how tools seal an edited
// content (checkpoint_text), so it may hold either format.
ExperimentConfig stored_config(const json& stored, const Refusal& refuse) {
    const bool current = stored.is_object() && stored.contains(config_format_key);
    const json migrated = migrate_config(stored);
    ExperimentConfig config;
    try {
        config = read_experiment_config(migrated, "checkpoint config");
    } catch (const ConfigError& e) {
        throw refuse(std::string("its config is not valid: ") + e.what());
    }
    if (current ? config.resolved != migrated : !holds_all_of(config.resolved, stored))
        throw refuse("its config is not a resolved config");
    return config;
}

// The births conceived but not yet inserted, the search's state, the history
// rows, lineage.csv's length and hash and the elapsed time.
void read_run_content(RunState& state, const json& content, const ExperimentConfig& config,
                      GenomeBlobReader* genomes, const Refusal& refuse) {
    const std::size_t dimension = parameter_count(config.network.layers());
    const auto P = static_cast<std::uint64_t>(config.evolution.population);
    // Before the search state, whose reader checks that every genome was taken.
    if (content.contains("pending")) {
        const json& pending = content.at("pending");
        if (!pending.is_array() || pending.empty()) throw refuse("its pending births are not a non-empty array");
        for (std::size_t i = 0; i < pending.size(); ++i)
            state.pending.push_back(
                individual_from_json(pending[i], dimension, "pending[" + std::to_string(i) + "]", genomes));
    }
    const SearchKind& search = search_kind(config.algorithm);
    if (!content.contains(search.key))
        throw refuse(std::string("its config is a ") + algorithm_name(config.algorithm) + " run but it holds no " +
                     search.key + " state");
    state.search = search.load(content.at(search.key), config, dimension, genomes);
    for (const json& row : content.at("history")) state.history.push_back(history_row_from_json(row));
    if (state.history.size() != state.births() / P)
        throw refuse(std::to_string(state.history.size()) + " history rows for " + std::to_string(state.births()) +
                     " births");
    for (const HistoryRow& row : state.history)
        if (row.qd != search.qd_history) throw refuse("its history rows do not fit its algorithm");
    for (std::size_t g = 0; g < state.history.size(); ++g)
        if (state.history[g].generation != g) throw refuse("history rows out of order");
    state.lineage_bytes = content.at("lineage").at("bytes").get<std::uint64_t>();
    state.lineage_hash = content.at("lineage").at("hash").get<std::string>();
    state.elapsed_s = content.at("elapsed_s").get<double>();
}

}  // namespace

RunState load_checkpoint(const std::filesystem::path& path) {
    std::string text;
    try {
        text = read_file_bytes(path, memory_bound("checkpoints (this machine's memory)"));
    } catch (const IoError& e) {  // not refused: a file that cannot be read (exit 3)
        throw IoError("checkpoint cannot be read: " + std::string(e.what()));
    }
    const Envelope envelope = open_envelope(text, path.string());
    const json& content = envelope.content;
    const Refusal refuse{path.string()};
    RunState state;
    try {
        const json& stored = content.at("config");
        state.seed = content.at("seed").get<std::uint64_t>();
        const ExperimentConfig config = stored_config(stored, refuse);
        state.config = config.resolved;
        if (config.run.seed != state.seed) throw refuse("its seed differs from its config's run.seed");
        const std::size_t dimension = parameter_count(config.network.layers());
        if (content.size() != (content.contains("pending") ? 7u : 6u)) throw refuse("unexpected keys in its content");
        // From format 2 the genomes come from the binary part, never through JSON numbers.
        std::optional<GenomeBlobReader> blob;
        if (envelope.version >= 2) {
            if (envelope.count > 0 && envelope.dimension != dimension)
                throw refuse("its genomes have " + std::to_string(envelope.dimension) + " parameters, its network " +
                             std::to_string(dimension));
            blob.emplace(envelope.genomes, envelope.count, envelope.dimension);
        }
        read_run_content(state, content, config, blob ? &*blob : nullptr, refuse);
        {
            GenomeBlobWriter rewritten;
            const json canonical = content_of(state, envelope.version >= 2 ? &rewritten : nullptr);
            if (const std::string key = unknown_key(content, canonical, ""); !key.empty())
                throw refuse("unknown key " + key + " in its content");
        }
        try {
            check_checkpoint_content(state, config);
        } catch (const std::invalid_argument& e) {
            throw refuse(std::string("it contradicts itself: ") + e.what());
        }
    } catch (const CheckpointError&) {
        throw;
    } catch (const std::exception& e) {
        throw refuse(std::string("its content does not fit: ") + e.what());
    }
    return state;
}

}  // namespace morphogen
