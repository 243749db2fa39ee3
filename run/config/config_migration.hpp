#pragma once
// The format of a resolved config (config.json, the config in a checkpoint;
// docs/config.md "Format versions"), and the migration of an earlier one.
//
// Format 2 (written): the top-level key "format_version": 2 and every key
// that applies, defaults included. Until 2026-11-29 a branching config left
// growth.exposure and growth.signal_diffusion out when they were off; such a
// config is read with them written out as off (false, 0).
// Format 1 (read): morphogen 0.1.0 and earlier. No "format_version", and
// some defaults left out: growth.collisions ("allow"), growth.mode
// ("paper"), evolution.algorithm ("steady_state"), evolution.schedule
// ("batch" where `batch` is given), fitness trunk_power of a tree (1), an
// emitter's covariance ("diagonal"), and a MAP-Elites run's `emitters` (one
// gaussian emitter of uniform selection).
//
// A config a user writes carries no version and is read in the current
// format; only the files of a run directory are migrated (a run directory
// made by 0.1.0 has an unversioned config.json and a checkpoint of version 1
// or 2).
#include <nlohmann/json.hpp>

namespace morphogen {

inline constexpr int config_format_version = 2;
inline constexpr const char* config_format_key = "format_version";

// A stored config in the current format: one with "format_version" 2 gets
// the signal switches format 2 left out at first (above), any other version
// is returned as it is (the reader refuses a later format); one without is
// format 1, returned with format_version 2 and the defaults format 1 left out
// written out as 0.1.0 applied them, so a later change of a default never
// changes what an old run continues with. Only adds keys; never throws (a
// document that is not a config is returned for the reader to refuse).
nlohmann::json migrate_config(nlohmann::json stored);

// Whether `whole` holds everything `part` holds: every key of every object,
// with the same value (arrays element by element, of the same length). What a
// migrated config read again must satisfy against the stored one.
bool holds_all_of(const nlohmann::json& whole, const nlohmann::json& part);

}  // namespace morphogen
