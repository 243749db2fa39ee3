#include "run/limits/resource_estimate.hpp"

#include "core/base/errors.hpp"
#include "evolution/emitters/cma/cma_emitter.hpp"
#include "evolution/execution/pipeline.hpp"
#include "fitness/canopy.hpp"
#include "fitness/light.hpp"
#include "fitness/plant_fitness.hpp"
#include "fitness/tree_fitness.hpp"
#include "core/growth/network/network.hpp"
#include "evolution/execution/worker_threads.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

namespace morphogen {

namespace {

using nlohmann::json;

// Bytes, measured on this build (peak RSS of runs that stress one part; see
// docs/limits.md) and rounded up.
constexpr double base_bytes = 64.0 * (1 << 20);     // the executable, its libraries, the heap's own use
constexpr double genome_overhead = 96;              // an Individual besides its parameters
constexpr double checkpoint_bytes_per_param = 8;    // format 2: genomes as raw doubles after the header
constexpr double checkpoint_text_per_genome = 200;  // id, parents, fitness, size, genome index, brackets
constexpr double checkpoint_tree_per_genome = 800;
constexpr double checkpoint_text_per_row = 300;     // a history row
constexpr double checkpoint_tree_per_row = 1200;
constexpr double checkpoint_fixed = 64 * 1024;      // config, lineage, envelope
constexpr double history_row_bytes = 128;           // a HistoryRow kept in the run state
// While a checkpoint is written (and read back by resume) its genomes exist
// once as bytes (the binary part, or the file read), its JSON header as two
// texts (the content's dump and the header line) and two JSON trees.
constexpr double checkpoint_texts_alive = 2, checkpoint_trees_alive = 2;
// A vertex of a growing mesh: position, direction, faces, half-edges,
// valence, outgoing edge (144 bytes) and 16 bytes per output (outputs and the
// next step's); vectors grow by doubling, so up to twice that.
constexpr double vertex_fixed_bytes = 144, vertex_bytes_per_output = 16, vector_slack = 2;
// A grown mesh written to a file: OBJ text (~125 bytes a vertex) or GLB
// (positions, normals, indices, copied about three times); the larger.
constexpr double export_bytes_per_vertex = 160;
constexpr double kept_mesh_bytes_per_vertex = 48;  // positions and faces (gallery)
// Fitness memory per face of the final mesh.
constexpr double light_tree_bytes_per_face = 200;      // CGAL AABB tree of the triangles
constexpr double canopy_bytes_per_face = 72;           // triangles above the height
constexpr double self_intersection_bytes_per_face = 250;
constexpr double measure_bytes_per_face = 48;

// Seconds of one core (development VM), rounded up from `morphogen bench`
// and timed `grow`/`score` runs on meshes of 2 000 to 400 000 vertices.
constexpr double second_per_mac = 0.1e-9;         // network multiply-add (fused kernel)
constexpr double second_per_output = 5e-9;        // gather, per output of a vertex
// Move, split test, flip, neighbour lists: ~100 ns a vertex on meshes that
// fit the caches, ~1 us on 400 000 vertices (cache misses); the larger.
constexpr double second_per_vertex_step = 1e-6;
constexpr double second_per_split = 1e-6;         // a new vertex
constexpr double second_per_param_build = 2e-9;   // building the network from a genome
constexpr double light_tree_second_per_face = 1.5e-6;
constexpr double light_ray_second = 0.5e-6, light_ray_second_per_level = 0.1e-6;  // + log2(faces) levels
constexpr double canopy_second_per_cell = 100e-9, canopy_second_per_face = 200e-9;
constexpr double self_intersection_second_per_face = 3e-6;
constexpr double measure_second_per_face = 50e-9;

const json& at_or_null(const json& object, const char* key) {
    static const json null;
    return object.is_object() && object.contains(key) ? object[key] : null;
}

std::string group(double n) {
    char text[64];
    if (n != std::floor(n) || !(n < 1e15)) {
        std::snprintf(text, sizeof text, "%.3g", n);
        return text;
    }
    std::snprintf(text, sizeof text, "%.0f", n);
    std::string digits = text, out;
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
        out += digits[i];
    }
    return out;
}

std::string seconds_text(double s) {
    char text[64];
    if (!(s < 1e7)) std::snprintf(text, sizeof text, "%.3g s", s);
    else if (s >= 3600) std::snprintf(text, sizeof text, "%.1f h", s / 3600);
    else if (s >= 60) std::snprintf(text, sizeof text, "%.1f min", s / 60);
    else std::snprintf(text, sizeof text, "%.3g s", s);
    return text;
}

// The box a plant stays in: the seed's, grown by the farthest a vertex can
// move (docs/algorithm.md §5.2: k * drive <= min(speed, budget / total) * drive,
// drive <= 0.5 and drive <= total), clamped at the ground.
struct Reach {
    Vec3 lo, hi;
    double width() const { return (hi - lo).norm(); }
};

Reach plant_reach(const SeedExtent& seed, const GrowthParams& g) {
    const double step = std::min(0.5 * g.speed, g.budget);
    const double d = step * static_cast<double>(g.steps);
    Reach r{seed.lo.array() - d, seed.hi.array() + d};
    if (g.ground) {
        r.lo.z() = std::max(r.lo.z(), std::min(0.0, seed.lo.z()));
        r.hi.z() = std::max(r.hi.z(), 0.0);
    }
    return r;
}

const std::vector<std::string> reach_keys{"growth.steps", "growth.speed", "growth.budget", "growth.seed_radius"};

std::vector<std::string> with(std::vector<std::string> first, const std::vector<std::string>& more) {
    first.insert(first.end(), more.begin(), more.end());
    return first;
}

// Memory and time of scoring one mesh with a resolved fitness section.
struct FitnessCost {
    double bytes = 0;  // the most any term needs at once (terms run one after another)
    std::vector<EstimatePart> work;
    std::vector<HardCap> caps;
};

void add_self_intersection(FitnessCost& cost, double faces, const std::string& why_key) {
    cost.bytes = std::max(cost.bytes, faces * self_intersection_bytes_per_face);
    cost.work.push_back({"self-intersection test of " + group(faces) + " faces", {why_key, "growth.max_vertices"},
                         faces * self_intersection_second_per_face});
}

void add_canopy(FitnessCost& cost, double cell, const std::string& path, double faces, const Reach& reach) {
    const double cells =
        ((reach.hi.x() - reach.lo.x()) / cell + 3) * ((reach.hi.y() - reach.lo.y()) / cell + 3);
    const std::vector<std::string> keys = with({path + ".cell"}, reach_keys);
    cost.bytes = std::max(cost.bytes, cells + faces * canopy_bytes_per_face);
    cost.work.push_back({"canopy grid of up to " + group(cells) + " cells (" + path + ")", keys,
                         cells * canopy_second_per_cell + faces * canopy_second_per_face});
    cost.caps.push_back({"canopy grid cells (" + path + ".cell over a plant up to " +
                             group(std::ceil(std::max(reach.hi.x() - reach.lo.x(), reach.hi.y() - reach.lo.y()))) +
                             " wide)",
                         keys, cells, static_cast<double>(canopy_max_cells)});
}

void add_fitness(FitnessCost& cost, const json& section, const std::string& path, double faces, const Reach& reach) {
    const std::string type = at_or_null(section, "type").is_string() ? section["type"].get<std::string>() : "canopy";
    if (type == "sum") {
        const json& terms = at_or_null(section, "terms");
        for (std::size_t i = 0; i < terms.size(); ++i)
            add_fitness(cost, terms[i], path + ".terms[" + std::to_string(i) + "]", faces, reach);
    } else if (type == "canopy") {
        const json& cell = at_or_null(section, "cell");
        add_canopy(cost, cell.is_number() ? cell.get<double>() : CanopyParams{}.cell, path, faces, reach);
    } else if (type == "light" || type == "tree" || type == "plant") {
        // A tree or plant casts the rays of its light (its own defaults) and
        // takes sections and the volume, or the skeleton and the moment, as
        // cheap as a measure.
        LightParams p = type == "tree" ? TreeFitnessParams{}.light : type == "plant" ? PlantFitnessParams{}.light : LightParams{};
        if (type != "light") {
            cost.bytes = std::max(cost.bytes, faces * measure_bytes_per_face);
            cost.work.push_back({type == "tree" ? "tree sections and volume" : "plant skeleton and moment", {path + ".type"},
                                 2 * faces * measure_second_per_face});
        }
        if (const json& e = at_or_null(section, "elevations_deg"); e.is_array()) p.elevations_deg = e.get<std::vector<double>>();
        if (const json& a = at_or_null(section, "azimuths_deg"); a.is_array()) p.azimuths_deg = a.get<std::vector<double>>();
        if (const json& s = at_or_null(section, "spacing"); s.is_number()) p.spacing = s.get<double>();
        // In a stand the rays meet a tree of the plant and its eight copies.
        const json& stand = at_or_null(section, "stand_spacing");
        const double scene_faces = stand.is_number() && stand.get<double>() > 0.0 ? 9 * faces : faces;
        double suns = 0;
        for (double e : p.elevations_deg) suns += e == 90.0 ? 1.0 : static_cast<double>(p.azimuths_deg.size());
        // Rays per sun: the lattice covers the projected box of the mesh, whose
        // sides are at most the box's diagonal; light.cpp adds at most 3 per side.
        const double side = reach.width() / p.spacing + 3;
        const double rays = side * side;
        const std::vector<std::string> keys = with({path + ".spacing"}, reach_keys);
        cost.bytes = std::max(cost.bytes, scene_faces * light_tree_bytes_per_face);
        const double per_ray = light_ray_second + light_ray_second_per_level * std::log2(scene_faces + 2);
        cost.work.push_back({"light: " + group(suns) + " suns x up to " + group(rays) + " rays (" + path + ")",
                             with(keys, {path + ".elevations_deg", path + ".azimuths_deg"}),
                             suns * rays * per_ray + scene_faces * light_tree_second_per_face});
        cost.caps.push_back({"light rays per sun (" + path + ".spacing " + group(p.spacing) +
                                 " over a plant up to " + group(std::ceil(reach.width())) + " wide)",
                             keys, rays, light_max_rays_per_sun});
    } else if (type == "self_intersecting") {
        add_self_intersection(cost, faces, path + ".type");
    } else {  // height, footprint, area, volume, vertices, faces
        cost.bytes = std::max(cost.bytes, faces * measure_bytes_per_face);
        cost.work.push_back({type + " of the mesh", {path + ".type"}, faces * measure_second_per_face});
    }
}

const std::vector<std::string> network_keys{"network.hidden", "network.outputs"};

}  // namespace

double physical_memory_bytes() {
    const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
    return pages > 0 && page > 0 ? static_cast<double>(pages) * static_cast<double>(page) : 0.0;
}

ResourceLimits default_resource_limits() {
    const double physical = physical_memory_bytes();
    ResourceLimits limits;
    limits.max_memory_bytes = physical > 0 ? default_memory_fraction * physical : 16.0 * (1ull << 30);
    limits.max_eval_seconds = default_max_eval_seconds;
    return limits;
}

std::optional<double> parse_byte_size(const std::string& text) {
    std::size_t used = 0;
    double value = 0;
    try {
        value = std::stod(text, &used);
    } catch (const std::exception&) {
        return std::nullopt;
    }
    // Plain decimal only (stod would also take hex, "inf", leading blanks).
    if (text.substr(0, used).find_first_not_of("0123456789.eE+-") != std::string::npos) return std::nullopt;
    std::string unit = text.substr(used);
    double scale = 1;
    if (!unit.empty()) {
        const std::string letters = "KMGT";
        const auto at = letters.find(static_cast<char>(std::toupper(static_cast<unsigned char>(unit[0]))));
        if (at != std::string::npos) {
            scale = std::pow(1024.0, static_cast<double>(at + 1));
            unit.erase(0, 1);
            if (unit == "iB" || unit == "ib") unit.clear();
        }
        if (unit == "B" || unit == "b") unit.clear();
    }
    if (!unit.empty() || !std::isfinite(value) || !(value > 0)) return std::nullopt;
    return value * scale;
}

std::string format_bytes(double bytes) {
    static const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
    int u = 0;
    while (u < 6 && bytes >= 1024) bytes /= 1024, ++u;
    char text[64];
    if (u == 0) std::snprintf(text, sizeof text, "%.0f B", bytes);
    else if (!(bytes < 1e6)) std::snprintf(text, sizeof text, "%.3g %s", bytes, units[u]);
    else std::snprintf(text, sizeof text, bytes < 10 ? "%.2f %s" : bytes < 100 ? "%.1f %s" : "%.0f %s", bytes, units[u]);
    return text;
}

SeedExtent seed_extent(const Seed& seed) {
    SeedExtent e;
    const auto& positions = seed.mesh.positions();
    e.vertices = static_cast<double>(positions.size());
    if (positions.empty()) return e;
    e.lo = e.hi = positions.front();
    for (const Vec3& p : positions) e.lo = e.lo.cwiseMin(p), e.hi = e.hi.cwiseMax(p);
    return e;
}

double ResourceEstimate::memory_bytes() const {
    return std::accumulate(memory.begin(), memory.end(), 0.0, [](double s, const EstimatePart& p) { return s + p.amount; });
}

double ResourceEstimate::eval_seconds() const {
    return std::accumulate(work.begin(), work.end(), 0.0, [](double s, const EstimatePart& p) { return s + p.amount; });
}

namespace {
// The most births in flight at once (docs/algorithm.md §8.4): a batch, or
// the pipeline's lag (all of generation 0 at the start).
double births_in_flight(const GaParams& p) {
    if (p.schedule == ScheduleKind::batch) return std::min(p.batch, p.population);
    return std::max(p.lag, p.population);
}
std::string in_flight_key(const GaParams& p) {
    return p.schedule == ScheduleKind::batch ? "evolution.batch" : "evolution.lag";
}
}  // namespace

Workload evolution_workload(const ExperimentConfig& config) {
    Workload w;
    w.evolution = true;
    // Threads beyond the births in flight get no child and never grow a workspace.
    w.threads = std::min<int>(resolve_threads(config.run.threads),
                              static_cast<int>(births_in_flight(config.evolution)));
    w.writers = config.run.export_every > 0 ? 1 : 0;
    return w;
}

SearchGenomes search_genomes(const ExperimentConfig& config) {
    const double P = config.evolution.population;
    const double flight = births_in_flight(config.evolution);
    // A checkpoint keeps the pipeline's births conceived from earlier states (lag - 1).
    const double pending = config.evolution.schedule == ScheduleKind::pipeline ? config.evolution.lag - 1 : 0.0;
    if (config.algorithm == Algorithm::map_elites) {
        // Every cell full (generation 0's P births enter the archive too), its
        // copy in the run state saved at each checkpoint, the births in flight
        // and their copy in that state, the best.
        const double cells = static_cast<double>(config.qd.cells());
        return {2 * cells + 2 * flight + pending + 3, cells + pending + 1};
    }
    // The population, its copy in the run state saved at each checkpoint, the
    // births in flight, their copy in the evaluator's queue and in that
    // state, and the best so far (in both states and one export).
    return {2 * P + 2 * flight + pending + 3, P + pending + 1};
}

namespace {

// The memory of a search: its genomes (population or archive, births in
// flight, best), files kept for export, CMA's covariance matrices, and a
// checkpoint written or read. Sets e.genomes and e.checkpoint_bytes.
void add_search_memory(ResourceEstimate& e, const ExperimentConfig& config, double D, double v) {
    // Genome memory is population x parameters: name first whichever is
    // further above its default.
    const double default_parameters = static_cast<double>(parameter_count(NetworkParams{}.layers()));
    const bool elites = config.algorithm == Algorithm::map_elites;
    const double genomes = elites ? static_cast<double>(config.qd.cells()) : config.evolution.population;
    const bool population_first = genomes / double(GaParams{}.population) >= D / default_parameters;
    const auto genome_keys = [&](const std::vector<std::string>& search_keys) {
        return population_first ? with(search_keys, network_keys) : with(network_keys, search_keys);
    };
    // A MAP-Elites archive's size is set by its cells: the bins of a grid, archive.cells of a CVT.
    const std::string cells_key = config.qd.archive == ArchiveKind::cvt ? "archive.cells" : "descriptors";
    e.genomes = search_genomes(config);
    e.memory.push_back({group(e.genomes.held) +
                            (elites ? " genomes (a full archive of " + group(genomes) +
                                          " cells twice, births in flight, best) x "
                                    : std::string(" genomes (population, births in flight, best) x ")) +
                            group(D) + " parameters",
                        genome_keys(elites ? std::vector<std::string>{cells_key, in_flight_key(config.evolution)}
                                           : std::vector<std::string>{"evolution.population",
                                                                      in_flight_key(config.evolution)}),
                        e.genomes.held * (8 * D + genome_overhead)});
    // Births that could become the exported best keep their export files
    // until they are inserted: at most kMaxKeepingBirths in flight.
    if (config.run.export_every > 0) {
        const double kept =
            std::min(births_in_flight(config.evolution), static_cast<double>(kMaxKeepingBirths));
        e.memory.push_back({group(kept) + " births in flight keeping the files of a mesh of up to " + group(v) +
                                " vertices to export",
                            {"growth.max_vertices", "run.export_every"}, kept * v * export_bytes_per_vertex});
    }
    // CMA emitters with a full covariance: C, its eigenvectors, the
    // eigensolver's copy and the update's new C, n x n doubles each; C goes
    // into every checkpoint too.
    double full_matrices = 0;
    if (elites)
        for (const EmitterSpec& emitter : config.qd.emitters)
            full_matrices += static_cast<double>(emitter.emitter->square_matrices());
    if (full_matrices > 0)
        e.memory.push_back({group(full_matrices) + " full covariance matrices of " + group(D) + " x " + group(D) +
                                " (C, its eigenvectors, the solver's and the update's copies)",
                            with({"emitters"}, network_keys), full_matrices * 4 * 8 * D * D});
    const double kept = e.genomes.checkpointed;
    const double rows = static_cast<double>(config.run.generations) + 1;
    const double header = kept * checkpoint_text_per_genome + rows * checkpoint_text_per_row + checkpoint_fixed;
    e.checkpoint_bytes = (kept + full_matrices * D) * D * checkpoint_bytes_per_param + header;
    const double tree = kept * checkpoint_tree_per_genome + rows * checkpoint_tree_per_row + checkpoint_fixed;
    e.memory.push_back({"writing or reading a checkpoint of up to " + format_bytes(e.checkpoint_bytes) + " (" +
                            group(kept) + " genomes, " + group(rows) + " history rows)",
                        genome_keys(elites ? std::vector<std::string>{cells_key, "run.generations"}
                                           : std::vector<std::string>{"evolution.population", "run.generations"}),
                        e.checkpoint_bytes + checkpoint_texts_alive * header + checkpoint_trees_alive * tree +
                            rows * history_row_bytes});
}

}  // namespace

ResourceEstimate estimate_resources(const ExperimentConfig& config, const SeedExtent& seed, const Workload& w) {
    ResourceEstimate e;
    const std::vector<int> layers = config.network.layers();
    e.parameters = parameter_count(layers);
    const double D = static_cast<double>(e.parameters);
    const double N = config.network.outputs;
    const GrowthParams& g = config.growth;
    const double threads = std::max(1, w.threads);

    // Vertices: at most 3V - 4 after a step (one split per face), never past
    // max_vertices by splitting (a seed may start above it).
    const double cap = std::max(seed.vertices, static_cast<double>(g.max_vertices));
    double v = seed.vertices;
    int t = 0;
    for (; t < g.steps && v < cap; ++t) {
        e.vertex_steps += v;
        v = std::min(cap, 3 * v - 4);
    }
    e.vertex_steps += v * static_cast<double>(g.steps - t);
    e.max_vertices = v;
    const double faces = std::max(0.0, 2 * v - 4);
    const Reach reach = plant_reach(seed, g);
    e.max_width = reach.width();

    // Work of one evaluation.
    const double per_vertex_step = D * second_per_mac + N * second_per_output + second_per_vertex_step;
    const std::vector<std::string> growth_keys{"growth.max_vertices", "growth.split_area", "growth.steps"};
    e.work.push_back({"growth: up to " + group(e.vertex_steps) + " vertex-steps (" + std::to_string(g.steps) +
                          " steps, up to " + group(v) + " vertices) x " + group(D) + " network parameters",
                      D * second_per_mac > second_per_vertex_step ? with(network_keys, growth_keys)
                                                                  : with(growth_keys, network_keys),
                      D * second_per_param_build + e.vertex_steps * per_vertex_step +
                          (v - seed.vertices) * second_per_split});
    FitnessCost fitness;
    const json& reject = at_or_null(at_or_null(config.resolved, "fitness"), "reject_self_intersecting");
    if (w.scores) add_fitness(fitness, at_or_null(config.resolved, "fitness"), "fitness", faces, reach);
    if (w.scores && reject.is_boolean() && reject.get<bool>())
        add_self_intersection(fitness, faces, "fitness.reject_self_intersecting");
    if (w.metrics) {  // score's report: every measure, self-intersection, canopy
        add_self_intersection(fitness, faces, "growth.max_vertices");
        const CanopyParams c = canopy_params_of(at_or_null(config.resolved, "fitness"));
        FitnessCost metrics;
        add_canopy(metrics, c.cell, "fitness", faces, reach);
        fitness.bytes = std::max(fitness.bytes, metrics.bytes);
        fitness.work.push_back(metrics.work.front());
    }
    e.work.insert(e.work.end(), fitness.work.begin(), fitness.work.end());
    e.caps = fitness.caps;

    // Memory at the peak.
    const std::vector<std::string> thread_keys{"run.threads"};
    e.memory.push_back({"the program itself", {}, base_bytes});
    const double vertex_bytes = vector_slack * (vertex_fixed_bytes + vertex_bytes_per_output * N);
    e.memory.push_back({group(threads) + " growth workspace(s) of up to " + group(v) + " vertices x " +
                            format_bytes(vertex_bytes),
                        with({"growth.max_vertices", "growth.split_area", "growth.steps", "network.outputs"}, thread_keys),
                        threads * v * vertex_bytes});
    e.memory.push_back({group(threads) + " network(s) of " + group(D) + " parameters",
                        with(network_keys, thread_keys), threads * 3 * 8 * D});
    if (fitness.bytes > 0)
        e.memory.push_back({group(threads) + " fitness evaluation(s) of up to " + group(faces) + " faces",
                            with({"growth.max_vertices", "fitness.type"}, thread_keys), threads * fitness.bytes});
    if (w.writers > 0)  // evolve grows the best again to export it
        e.memory.push_back({group(w.writers) + " mesh file(s) of up to " + group(v) + " vertices being written",
                            {"growth.max_vertices", "growth.split_area"},
                            w.writers * v * (export_bytes_per_vertex + (w.evolution ? vertex_bytes : 0))});
    if (w.kept_meshes > 0)
        e.memory.push_back({group(w.kept_meshes) + " meshes of up to " + group(v) + " vertices kept for the sheet",
                            {"growth.max_vertices"}, w.kept_meshes * v * kept_mesh_bytes_per_vertex});
    if (w.evolution) add_search_memory(e, config, D, v);
    return e;
}

std::vector<ConfigIssue> resource_issues(const ResourceEstimate& e, const ResourceLimits& limits) {
    std::vector<ConfigIssue> issues;
    if (!limits.enabled) return issues;
    // The keys of the largest parts that make up most of a total, and a
    // breakdown of those parts.
    auto blame = [](std::vector<EstimatePart> parts, double total, std::string (*show)(double)) {
        std::sort(parts.begin(), parts.end(), [](const auto& a, const auto& b) { return a.amount > b.amount; });
        std::vector<std::string> keys;
        std::string detail;
        double covered = 0;
        for (const EstimatePart& p : parts) {
            if (covered >= 0.9 * total || p.amount <= 0) break;
            covered += p.amount;
            for (const std::string& k : p.keys)
                if (std::find(keys.begin(), keys.end(), k) == keys.end()) keys.push_back(k);
            detail += (detail.empty() ? "" : "; ") + p.what + ": " + show(p.amount);
        }
        std::string path;
        for (const std::string& k : keys) path += (path.empty() ? "" : ", ") + k;
        return std::pair{path, detail};
    };
    const double bytes = e.memory_bytes();
    if (!(bytes <= limits.max_memory_bytes)) {
        auto [path, detail] = blame(e.memory, bytes, format_bytes);
        issues.push_back({path, "needs up to " + format_bytes(bytes) + " of memory (" + detail +
                                    "), more than the limit " + format_bytes(limits.max_memory_bytes) +
                                    " (--max-memory SIZE; the default is half of this machine's memory; "
                                    "--no-limits lifts every limit)"});
    }
    const double seconds = e.eval_seconds();
    if (!(seconds <= limits.max_eval_seconds)) {
        auto [path, detail] = blame(e.work, seconds, seconds_text);
        issues.push_back({path, "one evaluation may take up to " + seconds_text(seconds) + " of one core (" + detail +
                                    "), more than the limit " + seconds_text(limits.max_eval_seconds) +
                                    " (--max-eval-time SECONDS; --no-limits lifts every limit)"});
    }
    for (const HardCap& cap : e.caps) {
        if (cap.needed <= cap.cap) continue;
        std::string path;
        for (const std::string& k : cap.keys) path += (path.empty() ? "" : ", ") + k;
        issues.push_back({path, cap.what + ": up to " + group(cap.needed) + ", more than the " + group(cap.cap) +
                                    " that scoring allows (larger plants would score invalid; --no-limits "
                                    "skips this check)"});
    }
    return issues;
}

void check_resource_limits(const ExperimentConfig& config, const Workload& workload, const ResourceLimits& limits,
                           const std::string& source) {
    if (!limits.enabled) return;
    check_resource_limits(config, make_seed(config.growth), workload, limits,
                          source);
}

ResourceEstimate check_resource_limits(const ExperimentConfig& config, const Seed& seed, const Workload& workload,
                                       const ResourceLimits& limits, const std::string& source) {
    const ResourceEstimate estimate = estimate_resources(config, seed_extent(seed), workload);
    ConfigIssues issues;
    for (ConfigIssue& issue : resource_issues(estimate, limits)) issues.add(std::move(issue.path), std::move(issue.message));
    issues.throw_if_any(source);
    return estimate;
}

std::string resource_summary(const ResourceEstimate& e, const ResourceLimits& limits) {
    std::string text = "estimated at most " + format_bytes(e.memory_bytes()) + " of memory and " +
                       seconds_text(e.eval_seconds()) + " of one core per evaluation";
    if (e.checkpoint_bytes > 0) text += ", checkpoints up to " + format_bytes(e.checkpoint_bytes);
    if (!limits.enabled) return text + "; no limits";
    return text + "; limits " + format_bytes(limits.max_memory_bytes) + " and " + seconds_text(limits.max_eval_seconds);
}

}  // namespace morphogen
