#include "core/growth/growth_params.hpp"

#include "core/growth/network/network.hpp"

#include <limits>

namespace morphogen {

std::vector<int> NetworkParams::layers() const { return layer_sizes(outputs, hidden); }

NetworkParams read_network_params(ObjectReader& reader) {
    NetworkParams p;
    p.outputs = static_cast<int>(reader.integer("outputs", p.outputs, 3, 1000));
    const auto hidden = reader.integer_list("hidden", {p.hidden.begin(), p.hidden.end()}, 1, 10000);
    p.hidden.assign(hidden.begin(), hidden.end());
    reader.finish();
    return p;
}

namespace {

// The keys of the branching mode, all refused in the paper's mode.
constexpr const char* kBranchingKeys[] = {"turn_rate",           "exposure",         "exposure_cell", "exposure_depth",
                                          "exposure_full_shade", "signal_diffusion", "signal_rate"};

// Refuses `key` when given: it means nothing unless `condition` holds.
void refuse_unless(ObjectReader& reader, const char* key, const char* condition) {
    if (reader.raw(key) != nullptr) reader.issues().add(reader.path_of(key), std::string("is used only with ") + condition);
}

// The signals of docs/algorithm.md §5.9. Both switches are always resolved;
// a signal's own keys only when it is on. (Format-2 configs written before
// the switches were resolved when off get them by migration,
// run/config/config_migration.hpp.)
void read_signal_params(ObjectReader& reader, GrowthParams& p) {
    p.exposure = reader.boolean("exposure", p.exposure);
    if (p.exposure) {
        p.exposure_cell = reader.number("exposure_cell", p.exposure_cell, 1e-6, 1e6);
        p.exposure_depth = static_cast<int>(reader.integer("exposure_depth", p.exposure_depth, 0, 16));
        p.exposure_full_shade =
            reader.number("exposure_full_shade", p.exposure_full_shade, 0.0, 1e6, /*min_exclusive=*/true);
    } else {
        for (const char* key : {"exposure_cell", "exposure_depth", "exposure_full_shade"})
            refuse_unless(reader, key, "growth.exposure true");
    }
    p.signal_diffusion = static_cast<int>(reader.integer("signal_diffusion", p.signal_diffusion, 0, 64));
    if (p.signal_diffusion > 0) {
        p.signal_rate = reader.number("signal_rate", p.signal_rate, 0.0, 1.0, /*min_exclusive=*/true);
    } else {
        refuse_unless(reader, "signal_rate", "growth.signal_diffusion > 0");
    }
}

}  // namespace

GrowthParams read_growth_params(ObjectReader& reader) {
    constexpr double big = std::numeric_limits<double>::max();
    GrowthParams p;
    p.steps = static_cast<int>(reader.integer("steps", p.steps, 0, 1'000'000));
    p.speed = reader.number("speed", p.speed, 0.0, big);
    p.budget = reader.number("budget", p.budget, 0.0, big);
    p.ground = reader.boolean("ground", p.ground);
    p.split_area = reader.number("split_area", p.split_area, 0.0, big, /*min_exclusive=*/true);
    p.max_vertices = static_cast<int>(reader.integer("max_vertices", p.max_vertices, 4, 10'000'000));
    p.flip_every = static_cast<int>(reader.integer("flip_every", p.flip_every, 1, 1'000'000));
    p.flip_max_angle_deg = reader.number("flip_max_angle_deg", p.flip_max_angle_deg, 0.0, 180.0);
    p.min_valence = static_cast<int>(reader.integer("min_valence", p.min_valence, 3, 1000));
    p.height_scale = reader.number("height_scale", p.height_scale, 0.0, big, /*min_exclusive=*/true);
    p.seed_mesh = reader.string("seed_mesh", p.seed_mesh);
    // Beyond these the seed's area-weighted normals (products of two
    // coordinates) overflow or vanish; the mesh files' own bound is 1e9.
    p.seed_radius = reader.number("seed_radius", p.seed_radius, kMinSeedRadius, kMaxSeedRadius);
    const std::string collisions = reader.choice("collisions", "allow", {"allow", "prevent", "touch"});
    p.collisions = collisions == "prevent" ? Collisions::prevent
                   : collisions == "touch" ? Collisions::touch
                                           : Collisions::allow;
    if (p.collisions != Collisions::touch) {
        if (reader.raw("contact_distance") != nullptr)
            reader.issues().add(reader.path_of("contact_distance"), "is used only with growth.collisions \"touch\"");
    } else {
        p.contact_distance = reader.number("contact_distance", p.contact_distance, 0.0, 1e6,
                                           /*min_exclusive=*/true);
    }
    p.mode = reader.choice("mode", "paper", {"paper", "branching"}) == "branching" ? GrowthMode::branching
                                                                               : GrowthMode::paper;
    if (p.mode == GrowthMode::paper) {
        // The branching mode's keys mean nothing to the paper's model: one given is a mistake.
        for (const char* key : kBranchingKeys) refuse_unless(reader, key, "growth.mode \"branching\"");
    } else {
        p.turn_rate = reader.number("turn_rate", p.turn_rate, 0.0, 1e6);
        read_signal_params(reader, p);
    }
    if (p.seed_mesh.empty()) reader.issues().add(reader.path_of("seed_mesh"), "must name a built-in seed or a mesh file");
    reader.finish();
    return p;
}

}  // namespace morphogen
