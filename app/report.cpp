#include "report.hpp"

#include "atomic_file.hpp"
#include "checkpoint.hpp"
#include "config_reader.hpp"
#include "errors.hpp"
#include "experiment_config.hpp"
#include "growth_problem.hpp"
#include "mesh_io.hpp"
#include "render.hpp"
#include "report_animation.hpp"
#include "report_assets.hpp"
#include "report_data.hpp"
#include "run_directory.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <set>

#ifndef MORPHOGEN_THREE_DIR
#define MORPHOGEN_THREE_DIR "/usr/share/javascript/three"
#endif

namespace morphogen {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::vector<std::string> history_columns = {"generation", "births",        "best",    "mean",
                                                  "median",     "worst",         "mean_vertices", "invalid",
                                                  "births_per_s", "elapsed_s"};

// Report files are derived and can be written again, so a plain write (no
// fsync) with the reason on failure is enough.
void write_out(const fs::path& path, std::string_view bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (out) out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (out) out.close();
    if (!out) throw IoError(path.string() + ": cannot write: " + std::strerror(errno));
}

void make_dir(const fs::path& dir) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec || !fs::is_directory(dir)) throw IoError(dir.string() + ": cannot create: " + ec.message());
}

// Only the files an earlier report wrote there (stale generations after a
// resume cut them), never anything else in OUT_DIR.
void remove_old_files(const fs::path& dir, const std::string& prefix, const std::string& suffix) {
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
        const std::string name = entry.path().filename().string();
        if (name.size() > prefix.size() + suffix.size() && name.rfind(prefix, 0) == 0 &&
            name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
            fs::remove(entry.path(), ec);
    }
}

std::string four_digits(std::uint64_t n) {
    char text[32];
    std::snprintf(text, sizeof text, "%04llu", static_cast<unsigned long long>(n));
    return text;
}

// best/gen_NNNN.glb by generation.
std::map<std::uint64_t, fs::path> exported_meshes(const fs::path& best_dir) {
    std::map<std::uint64_t, fs::path> found;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(best_dir, ec)) {
        const std::string name = entry.path().filename().string();
        if (name.size() < 12 || name.rfind("gen_", 0) != 0 || name.compare(name.size() - 4, 4, ".glb") != 0) continue;
        const std::string digits = name.substr(4, name.size() - 8);
        if (digits.size() > 18 || !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
            continue;
        found[std::stoull(digits)] = entry.path();
    }
    return found;
}

// `count` of `items` spread evenly, first and last included.
std::vector<std::uint64_t> spread(const std::vector<std::uint64_t>& items, std::size_t count) {
    if (items.size() <= count) return items;
    std::vector<std::uint64_t> chosen;
    for (std::size_t i = 0; i < count; ++i) chosen.push_back(items[(i * (items.size() - 1) + (count - 1) / 2) / (count - 1)]);
    chosen.erase(std::unique(chosen.begin(), chosen.end()), chosen.end());
    return chosen;
}

json optional_number(const std::optional<double>& v) { return v ? json(*v) : json(); }
json optional_id(const std::optional<std::uint64_t>& v) { return v ? json(*v) : json(); }

// A script that hands base64 bytes to the page: morphogenMesh(key, data).
std::string mesh_script(const std::string& key, std::string_view bytes) {
    return "morphogenMesh(" + json(key).dump() + ",\"" + base64(bytes) + "\");\n";
}

struct Reporter {
    RunPaths paths;
    fs::path out;
    ReportOptions options;
    ReportSummary summary;
    json data = json::object();

    void note(const std::string& text) {
        std::cerr << "morphogen report: " << text << '\n';
        summary.notes.push_back(text);
    }
};

// The archive for the heatmap; the r.options.max_elites fittest elites grown
// into elites/cell_NNNN.js for the viewer.
template <typename Growth>
json elites_json(Reporter& r, const Archive& archive, Growth& growth) {
    std::vector<std::pair<std::uint64_t, const Individual*>> by_fitness;  // cell, elite
    for (const auto& [cell, elite] : archive.elites()) by_fitness.emplace_back(cell, &elite);
    std::stable_sort(by_fitness.begin(), by_fitness.end(),
                     [](const auto& a, const auto& b) { return a.second->fitness > b.second->fitness; });
    const std::size_t grow_count = std::min<std::size_t>(by_fitness.size(), r.options.max_elites);
    json ranges = json::array();
    for (const DescriptorRange& range : archive.ranges())
        ranges.push_back({{"name", range.name}, {"min", range.min}, {"max", range.max}, {"bins", range.bins}});
    json cells = json::array();
    std::map<std::uint64_t, std::size_t> index;  // cell -> its entry in cells
    for (const auto& [cell, elite] : archive.elites()) {
        index[cell] = cells.size();
        json c = {{"cell", cell}, {"id", elite.id}, {"fitness", elite.fitness}, {"descriptors", elite.descriptors},
                  {"script", nullptr}};
        if (archive.kind() == ArchiveKind::grid) c["bins"] = archive.bins_of(elite.descriptors);
        cells.push_back(std::move(c));
    }
    const GrowthProblem* p = grow_count > 0 ? growth() : nullptr;
    std::size_t grown = 0;
    for (std::size_t i = 0; p && i < grow_count; ++i) {
        const auto [cell, elite] = by_fitness[i];
        const std::string key = "cell_" + four_digits(cell);
        const GrowthState elite_grown = p->grow(elite->params);
        write_out(r.out / "elites" / (key + ".js"),
                  mesh_script(key, encode_mesh(elite_grown.mesh.view(), MeshFormat::glb)));
        cells[index.at(cell)]["script"] = "elites/" + key + ".js";
        cells[index.at(cell)]["key"] = key;
        ++grown;
    }
    r.summary.elites = grown;
    if (grown < by_fitness.size())
        r.note("the viewer holds the " + std::to_string(grown) + " fittest of " + std::to_string(by_fitness.size()) +
               " elites (report --elites N for more)");
    return {{"kind", archive.kind() == ArchiveKind::grid ? "grid" : "cvt"},
            {"descriptors", std::move(ranges)},
            {"cells", std::move(cells)},
            {"total_cells", archive.cells()},
            {"grown", grown}};
}

// three.js (Debian libjs-three) copied into lib/, so the report works
// offline; false (and a note) where it is not installed.
bool copy_three(Reporter& r, const fs::path& lib) {
    const char* elsewhere = std::getenv("MORPHOGEN_THREE_DIR");  // another copy of three.js r111
    const fs::path three = elsewhere && *elsewhere ? elsewhere : MORPHOGEN_THREE_DIR;
    const std::vector<std::pair<fs::path, std::string>> files = {
        {three / "three.min.js", "three.min.js"},
        {three / "examples/js/loaders/GLTFLoader.js", "GLTFLoader.js"},
        {three / "examples/js/controls/OrbitControls.js", "OrbitControls.js"}};
    for (const auto& [from, name] : files) {
        if (!fs::is_regular_file(from)) {
            r.note("no 3-D viewer: " + from.string() + " is missing (install Debian's libjs-three)");
            return false;
        }
        std::error_code ec;
        fs::copy_file(from, lib / name, fs::copy_options::overwrite_existing, ec);
        if (ec) throw IoError((lib / name).string() + ": cannot write: " + ec.message());
    }
    return true;
}

// data.js, the page and its script and style sheet.
void write_page(Reporter& r, bool three) {
    write_out(r.out / "data.js", "window.MORPHOGEN_REPORT = " + r.data.dump() + ";\n");
    write_out(r.out / "report.js", report_asset_js());
    write_out(r.out / "report.css", report_asset_css());
    std::string html(report_asset_html());
    const std::string marker = "<!--three-->";
    const std::string scripts = three ? "<script src=\"lib/three.min.js\"></script>\n"
                                        "<script src=\"lib/GLTFLoader.js\"></script>\n"
                                        "<script src=\"lib/OrbitControls.js\"></script>"
                                      : "";
    if (const auto at = html.find(marker); at != std::string::npos) html.replace(at, marker.size(), scripts);
    r.summary.index = r.out / "index.html";
    write_out(r.summary.index, html);
}

}  // namespace

std::string base64(std::string_view bytes) {
    static constexpr char alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    std::size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        const unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) | (static_cast<unsigned char>(bytes[i + 1]) << 8) |
                           static_cast<unsigned char>(bytes[i + 2]);
        for (int s = 18; s >= 0; s -= 6) out += alphabet[(v >> s) & 63];
    }
    if (i < bytes.size()) {
        const bool two = i + 1 < bytes.size();
        const unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) |
                           (two ? static_cast<unsigned char>(bytes[i + 1]) << 8 : 0u);
        out += alphabet[(v >> 18) & 63];
        out += alphabet[(v >> 12) & 63];
        out += two ? alphabet[(v >> 6) & 63] : '=';
        out += '=';
    }
    return out;
}

ReportSummary write_report(const fs::path& run_dir, const fs::path& out_dir, const ReportOptions& options) {
    Reporter r{run_paths(run_dir), out_dir, options, {}, {}};
    const RunPaths& paths = r.paths;
    const std::string dir = run_dir.string();
    if (!fs::is_directory(run_dir)) throw IoError("run directory " + dir + " does not exist");
    if (!fs::exists(paths.history) && !fs::exists(paths.checkpoint) && !fs::exists(paths.config))
        throw IoError(dir + " is not a run directory: it has no history.csv, checkpoint.json or config.json");
    if (!fs::exists(paths.history)) throw IoError(dir + ": damaged run directory: history.csv is missing");
    if (!fs::exists(paths.checkpoint))
        throw CheckpointError(dir + ": damaged run directory: checkpoint.json is missing");
    if (!fs::exists(paths.lineage)) throw IoError(dir + ": damaged run directory: lineage.csv is missing");

    // Everything is read before anything is written.
    const RunState state = load_checkpoint(paths.checkpoint);
    const ExperimentConfig config = read_experiment_config(state.config, paths.checkpoint.string());
    const NumericCsv history = read_numeric_csv(paths.history, history_columns);
    const Lineage lineage = read_lineage(paths.lineage);
    const std::map<std::uint64_t, fs::path> meshes = exported_meshes(paths.best);

    std::vector<std::uint64_t> births;  // per history row, for generation_of
    for (const auto& b : history.columns.at("births"))  // (a hostile cell becomes 0, not undefined behaviour)
        births.push_back(b && *b >= 0 && *b < 9.2e18 ? static_cast<std::uint64_t>(*b) : 0);
    const auto& best_column = history.columns.at("best");

    make_dir(r.out);
    for (const char* sub : {"meshes", "thumbs", "elites", "lib"}) make_dir(r.out / sub);
    remove_old_files(r.out / "meshes", "gen_", ".js");
    remove_old_files(r.out / "thumbs", "gen_", ".png");
    remove_old_files(r.out / "elites", "cell_", ".js");
    for (const char* name : {"best.js", "growth.js", "growth.glb", "contact.png"}) {
        std::error_code ec;
        fs::remove(r.out / name, ec);  // written again below if there is one
    }

    json& d = r.data;
    const bool qd = config.algorithm == Algorithm::map_elites;
    d["name"] = config.run.name;
    d["run_dir"] = fs::absolute(run_dir).lexically_normal().string();
    d["algorithm"] = qd ? "map_elites" : "steady_state";
    d["seed"] = state.seed;
    d["config"] = state.config;
    d["births"] = std::max<std::uint64_t>(lineage.size(), state.births());
    d["checkpoint_births"] = state.births();
    d["generations"] = history.rows > 0 ? json(history.rows - 1) : json();
    d["target_generations"] = config.run.generations;
    d["elapsed_s"] = history.rows > 0 ? optional_number(history.columns.at("elapsed_s").back()) : json(state.elapsed_s);
    d["population"] = config.evolution.population;

    // history, column by column
    json columns = json::object();
    for (const std::string& name : history.names) {
        json values = json::array();
        for (const auto& v : history.columns.at(name)) values.push_back(optional_number(v));
        columns[name] = std::move(values);
    }
    d["history"] = {{"names", history.names}, {"columns", std::move(columns)}};

    // the viewer's meshes: every exported generation
    json mesh_list = json::array();
    std::vector<std::uint64_t> exported;
    for (const auto& [generation, path] : meshes) {
        const std::string key = "gen_" + four_digits(generation);
        std::string bytes;
        try {
            bytes = read_file_bytes(path);
        } catch (const std::exception& e) {
            r.note(std::string("skipped ") + e.what());
            continue;
        }
        write_out(r.out / "meshes" / (key + ".js"), mesh_script(key, bytes));
        exported.push_back(generation);
        mesh_list.push_back({{"generation", generation},
                             {"key", key},
                             {"script", "meshes/" + key + ".js"},
                             {"fitness", generation < history.rows ? optional_number(best_column[generation]) : json()}});
    }
    r.summary.meshes = exported.size();
    d["meshes"] = std::move(mesh_list);
    if (exported.empty())
        r.note(config.run.export_every == 0 ? "no meshes: this run exports none (run.export_every is 0)"
                                            : "no meshes: best/ holds no gen_NNNN.glb yet");

    // pictures: thumbnails of the generations the ancestry and the sheet show
    // (from the .obj beside each .glb: the mesh readers do not read GLB)
    std::map<std::uint64_t, std::optional<MeshArrays>> loaded;
    auto load = [&](std::uint64_t generation) -> const MeshArrays* {
        if (auto it = loaded.find(generation); it != loaded.end()) return it->second ? &*it->second : nullptr;
        std::optional<MeshArrays>& mesh = loaded[generation];
        try {
            mesh = read_mesh(fs::path(meshes.at(generation)).replace_extension(".obj").string());
        } catch (const std::exception& e) {
            r.note(std::string("no picture of generation ") + std::to_string(generation) + ": " + e.what());
        }
        return mesh ? &*mesh : nullptr;
    };
    std::set<std::uint64_t> thumbs;
    auto thumb = [&](std::uint64_t generation) -> json {
        if (!std::binary_search(exported.begin(), exported.end(), generation)) return json();
        const std::string name = "thumbs/gen_" + four_digits(generation) + ".png";
        if (thumbs.count(generation)) return name;
        const MeshArrays* mesh = load(generation);
        if (!mesh) return json();
        RenderOptions render;
        render.size = r.options.thumb_size;
        write_png(render_mesh(mesh->view(), render), (r.out / name).string());
        thumbs.insert(generation);
        return name;
    };

    // the best so far and its ancestry
    const std::optional<Individual>& best = qd ? state.elites->best : state.ga.best;
    std::optional<GrowthProblem> problem;
    auto growth = [&]() -> const GrowthProblem* {
        if (!problem) try {
                problem.emplace(config);
            } catch (const std::exception& e) {
                r.note(std::string("cannot grow genomes (their seed mesh): ") + e.what());
                return nullptr;
            }
        return &*problem;
    };
    d["best"] = nullptr;
    d["ancestry"] = json::array();
    d["animation"] = nullptr;
    if (!best) {
        r.note("no valid individual yet: no best, no ancestry");
    } else {
        json b = {{"id", best->id},
                  {"fitness", best->fitness},
                  {"generation", generation_of(best->id, births)},
                  {"parent1", optional_id(best->parent1)},
                  {"parent2", optional_id(best->parent2)},
                  {"vertices", best->size},
                  {"script", nullptr}};
        if (const GrowthProblem* p = growth()) {
            const GrowthState grown = p->grow(best->params);
            write_out(r.out / "best.js", mesh_script("best", encode_mesh(grown.mesh.view(), MeshFormat::glb)));
            b["script"] = "best.js";
        }
        d["best"] = std::move(b);
        if (best->id < lineage.size()) {
            for (std::uint64_t id : ancestry(lineage, best->id, paths.lineage)) {
                const std::uint64_t generation = generation_of(id, births);
                d["ancestry"].push_back({{"id", id},
                                         {"generation", generation},
                                         {"fitness", optional_number(lineage.fitness[id])},
                                         {"parent1", optional_id(lineage.parent1[id])},
                                         {"parent2", optional_id(lineage.parent2[id])},
                                         {"thumb", thumb(generation)}});
            }
            r.summary.ancestors = d["ancestry"].size();
        } else {
            r.note("lineage.csv does not reach the best (id " + std::to_string(best->id) + "): no ancestry");
        }
        // the growth animation of the best genome
        if (r.options.animation_frames > 0 && growth()) {
            int frames = r.options.animation_frames;
            std::string why;
            if (const auto glb = report_animation_glb(config, Genome{config.network.layers(), best->params}, frames, why)) {
                write_out(r.out / "growth.glb", *glb);
                write_out(r.out / "growth.js", mesh_script("growth", *glb));
                d["animation"] = {{"script", "growth.js"}, {"file", "growth.glb"}, {"frames", frames}};
                r.summary.animation = true;
            } else {
                r.note(why);
            }
        }
    }

    // the contact sheet
    d["sheet"] = nullptr;
    if (!exported.empty() && r.options.sheet_count > 0) {
        std::vector<MeshArrays> sheet_meshes;
        std::vector<std::string> captions;
        json generations = json::array();
        for (std::uint64_t g : spread(exported, static_cast<std::size_t>(r.options.sheet_count))) {
            const MeshArrays* mesh = load(g);
            if (!mesh) continue;
            sheet_meshes.push_back(*mesh);
            char caption[64];
            const auto& f = g < history.rows ? best_column[g] : std::optional<double>();
            std::snprintf(caption, sizeof caption, f ? "gen %llu  %.4g" : "gen %llu",
                          static_cast<unsigned long long>(g), f ? *f : 0.0);
            captions.emplace_back(caption);
            generations.push_back(g);
        }
        if (!sheet_meshes.empty()) {
            RenderOptions render;
            render.size = 160;
            render.columns = 6;
            render_contact_sheet(sheet_meshes, captions, (r.out / "contact.png").string(), render);
            d["sheet"] = {{"image", "contact.png"}, {"generations", std::move(generations)}};
        }
    }

    d["elites"] = qd ? elites_json(r, state.elites->archive, growth) : json();

    const bool have_three = copy_three(r, r.out / "lib");
    d["three"] = have_three;
    d["notes"] = r.summary.notes;
    write_page(r, have_three);
    return r.summary;
}

bool report_at_end_of_run(const fs::path& run_dir) {
    try {
        const ReportSummary summary = write_report(run_dir, run_dir / "report", ReportOptions{});
        std::cerr << "report: " << summary.index.string() << '\n';
        return true;
    } catch (const std::exception& e) {
        std::cerr << "morphogen: the run is complete but its report failed: " << e.what()
                  << "; write it with: morphogen report " << run_dir.string() << '\n';
        return false;
    }
}

}  // namespace morphogen
