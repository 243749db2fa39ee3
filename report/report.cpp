#include "report/report.hpp"

#include "core/base/atomic_file.hpp"
#include "core/base/config_reader.hpp"
#include "core/base/errors.hpp"
#include "fitness/architecture/architecture_json.hpp"
#include "core/growth/genome_grower.hpp"
#include "core/io/mesh_io.hpp"
#include "report/render.hpp"
#include "report/report_animation.hpp"
#include "report/report_assets.hpp"
#include "report/report_data.hpp"
#include "report/report_plants.hpp"
#include "run/persistence/checkpoint.hpp"
#include "run/searches/elites_search.hpp"
#include "run/config/experiment_config.hpp"
#include "run/persistence/run_directory.hpp"

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

// best/gen_NNNN.glb by generation.
std::map<std::uint64_t, fs::path> exported_meshes(const fs::path& best_dir) {
    std::map<std::uint64_t, fs::path> found;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(best_dir, ec))
        if (const auto generation = export_generation(entry.path().filename().string(), ".glb"))
            found[*generation] = entry.path();
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

std::string four_digits(std::uint64_t n) {
    char text[32];
    std::snprintf(text, sizeof text, "%04llu", static_cast<unsigned long long>(n));
    return text;
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
// into elites/cell_NNNN.js for the viewer (engine-ready: wind and levels).
template <typename Growth>
json elites_json(Reporter& r, const ExperimentConfig& config, const Archive& archive, Growth& growth) {
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
    const GenomeGrower* p = grow_count > 0 ? growth() : nullptr;
    std::size_t grown = 0;
    for (std::size_t i = 0; p && i < grow_count; ++i) {
        const auto [cell, elite] = by_fitness[i];
        const std::string key = "cell_" + four_digits(cell);
        const ReportPlant plant = grow_report_plant(config, *p, *elite, cell, r.options.colour);
        if (plant.why_plain) r.note("elite of cell " + std::to_string(cell) + ": no wind or levels: " + *plant.why_plain);
        write_out(r.out / "elites" / (key + ".js"), mesh_script(key, plant.glb));
        cells[index.at(cell)]["script"] = "elites/" + key + ".js";
        cells[index.at(cell)]["key"] = key;
        cells[index.at(cell)]["lods"] = plant.lods;
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
        // Read and written, not fs::copy_file: its copy_file_range reports a
        // file-size limit (EFBIG) as "Input/output error".
        write_out(lib / name, read_file_bytes(from, {std::uint64_t{64} << 20, "page assets"}));
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

// What a report shows, read (and checked) before anything is written.
struct RunInputs {
    RunState state;
    ExperimentConfig config;
    NumericCsv history;
    Lineage lineage;
    std::map<std::uint64_t, fs::path> meshes;  // best/gen_NNNN.glb by generation
    std::vector<std::uint64_t> births;          // per history row, for generation_of
};

RunInputs read_run(const fs::path& run_dir, const RunPaths& paths) {
    const std::string dir = run_dir.string();
    if (!fs::is_directory(run_dir)) throw IoError("run directory " + dir + " does not exist");
    if (!fs::exists(paths.history) && !fs::exists(paths.checkpoint) && !fs::exists(paths.config))
        throw IoError(dir + " is not a run directory: it has no history.csv, checkpoint.json or config.json");
    if (!fs::exists(paths.history)) throw IoError(dir + ": damaged run directory: history.csv is missing");
    if (!fs::exists(paths.checkpoint))
        throw CheckpointError(dir + ": damaged run directory: checkpoint.json is missing");
    if (!fs::exists(paths.lineage)) throw IoError(dir + ": damaged run directory: lineage.csv is missing");

    RunState state = load_checkpoint(paths.checkpoint);
    ExperimentConfig config = read_experiment_config(state.config, paths.checkpoint.string());
    RunInputs in{std::move(state), std::move(config), read_numeric_csv(paths.history, history_columns),
                 read_lineage(paths.lineage), exported_meshes(paths.best), {}};
    for (const auto& b : in.history.columns.at("births"))  // (a hostile cell becomes 0, not undefined behaviour)
        in.births.push_back(b && *b >= 0 && *b < 9.2e18 ? static_cast<std::uint64_t>(*b) : 0);
    return in;
}

// The run at a glance and its history, column by column.
void summary_json(json& d, const fs::path& run_dir, const RunInputs& in) {
    d["name"] = in.config.run.name;
    d["run_dir"] = fs::absolute(run_dir).lexically_normal().string();
    d["algorithm"] = algorithm_name(in.config.algorithm);
    d["seed"] = in.state.seed;
    d["config"] = in.state.config;
    d["births"] = std::max<std::uint64_t>(in.lineage.size(), in.state.births());
    d["checkpoint_births"] = in.state.births();
    d["generations"] = in.history.rows > 0 ? json(in.history.rows - 1) : json();
    d["target_generations"] = in.config.run.generations;
    d["elapsed_s"] = in.history.rows > 0 ? optional_number(in.history.columns.at("elapsed_s").back())
                                         : json(in.state.elapsed_s);
    d["population"] = in.config.evolution.population;
    json columns = json::object();
    for (const std::string& name : in.history.names) {
        json values = json::array();
        for (const auto& v : in.history.columns.at(name)) values.push_back(optional_number(v));
        columns[name] = std::move(values);
    }
    d["history"] = {{"names", in.history.names}, {"columns", std::move(columns)}};
}

// The viewer's meshes: every exported generation. Returns the generations
// written, in order.
std::vector<std::uint64_t> viewer_meshes(Reporter& r, const RunInputs& in) {
    const auto& best_column = in.history.columns.at("best");
    json mesh_list = json::array();
    std::vector<std::uint64_t> exported;
    for (const auto& [generation, path] : in.meshes) {
        const std::string key = export_name(generation);
        std::string bytes;
        try {
            bytes = read_file_bytes(path, {kMaxMeshFileBytes, "mesh files"});
        } catch (const std::exception& e) {
            r.note(std::string("skipped ") + e.what());
            continue;
        }
        write_out(r.out / "meshes" / (key + ".js"), mesh_script(key, bytes));
        exported.push_back(generation);
        mesh_list.push_back({{"generation", generation},
                             {"key", key},
                             {"script", "meshes/" + key + ".js"},
                             {"fitness", generation < in.history.rows ? optional_number(best_column[generation]) : json()}});
    }
    r.summary.meshes = exported.size();
    r.data["meshes"] = std::move(mesh_list);
    if (exported.empty())
        r.note(in.config.run.export_every == 0 ? "no meshes: this run exports none (run.export_every is 0)"
                                               : "no meshes: best/ holds no gen_NNNN.glb yet");
    return exported;
}

// The growth of the run's config, made once when first needed; nullptr
// (and a note) where its seed mesh cannot be made.
class LazyGrowth {
public:
    LazyGrowth(Reporter& r, const ExperimentConfig& config) : r_(r), config_(config) {}
    const GenomeGrower* operator()() {
        if (!grower_) try {
                grower_.emplace(config_.network, config_.growth);
            } catch (const std::exception& e) {
                r_.note(std::string("cannot grow genomes (their seed mesh): ") + e.what());
                return nullptr;
            }
        return &*grower_;
    }

private:
    Reporter& r_;
    const ExperimentConfig& config_;
    std::optional<GenomeGrower> grower_;
};

// Pictures of exported generations, from the .obj beside each .glb (its exact
// coordinates; the GLB holds floats) in colours from growth history (its
// .genome.json grown again) unless --no-colour: each mesh read and coloured
// once, each thumbnail drawn once.
class Pictures {
public:
    Pictures(Reporter& r, const RunInputs& in, std::vector<std::uint64_t> exported, LazyGrowth& growth)
        : r_(r), in_(in), exported_(std::move(exported)), growth_(growth) {}

    const std::vector<std::uint64_t>& exported() const { return exported_; }

    // The mesh of an exported generation; nullptr (and a note) if it cannot be read.
    const MeshArrays* mesh(std::uint64_t generation) {
        if (auto it = loaded_.find(generation); it != loaded_.end()) return it->second ? &*it->second : nullptr;
        std::optional<MeshArrays>& mesh = loaded_[generation];
        try {
            mesh = read_mesh(fs::path(in_.meshes.at(generation)).replace_extension(".obj").string());
        } catch (const std::exception& e) {
            r_.note(std::string("no picture of generation ") + std::to_string(generation) + ": " + e.what());
        }
        return mesh ? &*mesh : nullptr;
    }

    // The colours of an exported generation's mesh; empty (the plain green)
    // with --no-colour, or with a note where its genome cannot be grown.
    const std::vector<float>& colours(std::uint64_t generation) {
        auto [it, fresh] = colours_.try_emplace(generation);
        const MeshArrays* m = fresh && r_.options.colour ? mesh(generation) : nullptr;
        const GenomeGrower* grower = m ? growth_() : nullptr;
        if (grower) try {
                const fs::path genome = fs::path(in_.meshes.at(generation)).replace_extension(".genome.json");
                it->second = export_colours(*grower, genome, m->positions.size());
            } catch (const std::exception& e) {
                r_.note("generation " + std::to_string(generation) + " drawn in plain green: " + e.what());
            }
        return it->second;
    }

    // thumbs/gen_NNNN.png of an exported generation, or null.
    json thumb(std::uint64_t generation) {
        if (!std::binary_search(exported_.begin(), exported_.end(), generation)) return json();
        const std::string name = "thumbs/" + export_name(generation) + ".png";
        if (thumbs_.count(generation)) return name;
        const MeshArrays* m = mesh(generation);
        if (!m) return json();
        RenderOptions render;
        render.size = r_.options.thumb_size;
        write_png(render_mesh(m->view(), render, colours(generation)), (r_.out / name).string());
        thumbs_.insert(generation);
        return name;
    }

private:
    Reporter& r_;
    const RunInputs& in_;
    std::vector<std::uint64_t> exported_;
    std::map<std::uint64_t, std::optional<MeshArrays>> loaded_;
    std::set<std::uint64_t> thumbs_;
    std::map<std::uint64_t, std::vector<float>> colours_;
    LazyGrowth& growth_;
};

// The best genome's growth animation into growth.glb and growth.js.
void animation_json(Reporter& r, const ExperimentConfig& config, const Individual& best) {
    int frames = r.options.animation_frames;
    std::string why;
    if (const auto glb = report_animation_glb(config, Genome{config.network.layers(), best.params}, frames, why, r.options.colour)) {
        write_out(r.out / "growth.glb", *glb);
        write_out(r.out / "growth.js", mesh_script("growth", *glb));
        r.data["animation"] = {{"script", "growth.js"}, {"file", "growth.glb"}, {"frames", frames}};
        r.summary.animation = true;
    } else {
        r.note(why);
    }
}

// The best so far, its mesh, its ancestry and its growth animation.
void best_json(Reporter& r, const RunInputs& in, Pictures& pictures, LazyGrowth& growth) {
    const std::optional<Individual>& best = in.state.search->best();
    json& d = r.data;
    d["best"] = nullptr;
    d["ancestry"] = json::array();
    d["animation"] = nullptr;
    if (!best) {
        r.note("no valid individual yet: no best, no ancestry");
        return;
    }
    json b = {{"id", best->id},
              {"fitness", best->fitness},
              {"generation", generation_of(best->id, in.births)},
              {"parent1", optional_id(best->parent1)},
              {"parent2", optional_id(best->parent2)},
              {"vertices", best->size},
              {"script", nullptr},
              {"architecture", nullptr}};
    if (const GenomeGrower* p = growth()) {
        const ReportPlant plant = grow_report_plant(in.config, *p, *best, std::nullopt, r.options.colour);
        if (plant.why_plain) r.note("the final best has no wind or levels: " + *plant.why_plain);
        write_out(r.out / "best.js", mesh_script("best", plant.glb));
        b["script"] = "best.js";
        b["lods"] = plant.lods;
        b["architecture"] = architecture_json(measure_architecture(plant.grown.mesh.view()));
    }
    d["best"] = std::move(b);
    if (best->id < in.lineage.size()) {
        for (std::uint64_t id : ancestry(in.lineage, best->id, r.paths.lineage)) {
            const std::uint64_t generation = generation_of(id, in.births);
            d["ancestry"].push_back({{"id", id},
                                     {"generation", generation},
                                     {"fitness", optional_number(in.lineage.fitness[id])},
                                     {"parent1", optional_id(in.lineage.parent1[id])},
                                     {"parent2", optional_id(in.lineage.parent2[id])},
                                     {"thumb", pictures.thumb(generation)}});
        }
        r.summary.ancestors = d["ancestry"].size();
    } else {
        r.note("lineage.csv does not reach the best (id " + std::to_string(best->id) + "): no ancestry");
    }
    if (r.options.animation_frames > 0 && growth()) animation_json(r, in.config, *best);
}

// The contact sheet of up to options.sheet_count exported generations.
void sheet_json(Reporter& r, const RunInputs& in, Pictures& pictures) {
    r.data["sheet"] = nullptr;
    if (pictures.exported().empty() || r.options.sheet_count <= 0) return;
    const auto& best_column = in.history.columns.at("best");
    std::vector<MeshArrays> sheet_meshes;
    std::vector<std::vector<float>> sheet_colours;
    std::vector<std::string> captions;
    json generations = json::array();
    for (std::uint64_t g : spread(pictures.exported(), static_cast<std::size_t>(r.options.sheet_count))) {
        const MeshArrays* mesh = pictures.mesh(g);
        if (!mesh) continue;
        sheet_meshes.push_back(*mesh);
        sheet_colours.push_back(pictures.colours(g));
        char caption[64];
        const auto& f = g < in.history.rows ? best_column[g] : std::optional<double>();
        std::snprintf(caption, sizeof caption, f ? "gen %llu  %.4g" : "gen %llu", static_cast<unsigned long long>(g),
                      f ? *f : 0.0);
        captions.emplace_back(caption);
        generations.push_back(g);
    }
    if (sheet_meshes.empty()) return;
    RenderOptions render;
    render.size = 160;
    render.columns = 6;
    render_contact_sheet(sheet_meshes, captions, (r.out / "contact.png").string(), render, sheet_colours);
    r.data["sheet"] = {{"image", "contact.png"}, {"generations", std::move(generations)}};
}

// Every file of the report into `staging` (a fresh folder); index.html last.
void write_report_files(Reporter& r, const fs::path& run_dir, const RunInputs& in) {
    for (const char* sub : {"meshes", "thumbs", "elites", "lib"}) make_dir(r.out / sub);
    summary_json(r.data, run_dir, in);
    LazyGrowth growth(r, in.config);
    Pictures pictures(r, in, viewer_meshes(r, in), growth);
    best_json(r, in, pictures, growth);
    sheet_json(r, in, pictures);
    const MapElitesState* elites = elites_state(*in.state.search);
    r.data["elites"] = elites != nullptr ? elites_json(r, in.config, elites->archive, growth) : json();
    const bool have_three = copy_three(r, r.out / "lib");
    r.data["three"] = have_three;
    r.data["notes"] = r.summary.notes;
    write_page(r, have_three);
}

void rename_into(const fs::path& from, const fs::path& to) {
    std::error_code ec;
    fs::rename(from, to, ec);
    if (ec) throw IoError(to.string() + ": cannot write: " + ec.message());
}

// Moves a complete report from `staging` into `out` (renames only: no disk
// space needed): index.html is removed first and put back last, so an
// index.html is always a whole report; files of an earlier report that this
// one does not have (stale generations after a resume cut them) are removed,
// and nothing else in `out` is touched.
void publish(const fs::path& staging, const fs::path& out) {
    make_dir(out);
    std::error_code ec;
    fs::remove(out / "index.html", ec);
    for (const char* sub : {"meshes", "thumbs", "elites", "lib"}) make_dir(out / sub);
    remove_old_files(out / "meshes", "gen_", ".js");
    remove_old_files(out / "thumbs", "gen_", ".png");
    remove_old_files(out / "elites", "cell_", ".js");
    for (const char* name : {"best.js", "growth.js", "growth.glb", "contact.png"}) fs::remove(out / name, ec);
    for (const char* sub : {"meshes", "thumbs", "elites", "lib"})
        for (const auto& entry : fs::directory_iterator(staging / sub)) rename_into(entry.path(), out / sub / entry.path().filename());
    for (const auto& entry : fs::directory_iterator(staging))
        if (entry.is_regular_file() && entry.path().filename() != "index.html")
            rename_into(entry.path(), out / entry.path().filename());
    rename_into(staging / "index.html", out / "index.html");
}

// Removes a folder tree on every way out of a scope.
struct RemoveOnExit {
    fs::path dir;
    ~RemoveOnExit() {
        std::error_code ec;
        fs::remove_all(dir, ec);
    }
};

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
    const RunPaths paths = run_paths(run_dir);
    const RunInputs in = read_run(run_dir, paths);  // everything is read before anything is written
    // The report is built beside OUT_DIR and moved in whole: a failure (a
    // full disk) leaves OUT_DIR as it was, with no half-written file.
    const fs::path out = out_dir.lexically_normal().has_filename() ? out_dir.lexically_normal()
                                                                   : out_dir.lexically_normal().parent_path();
    std::string staging_name = ".";
    staging_name += out.filename().string();
    staging_name += ".partial";
    const fs::path staging = out.parent_path() / staging_name;
    std::error_code ec;
    fs::remove_all(staging, ec);
    RemoveOnExit cleanup{staging};
    make_dir(staging);
    Reporter r{paths, staging, options, {}, {}};
    write_report_files(r, run_dir, in);
    publish(staging, out);
    r.summary.index = out / "index.html";
    return r.summary;
}

}  // namespace morphogen
