#pragma once
// Small checked readers shared by the search states' JSON (ga_state_json,
// map_elites_state_json). Each throws std::invalid_argument("<path>: <defect>").
#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>

namespace morphogen::state_json {

[[noreturn]] void fail(const std::string& path, const std::string& what);
// object[key], failing if `object` is not an object or lacks the key.
const nlohmann::json& member(const nlohmann::json& object, const char* key, const std::string& path);
std::uint64_t read_u64(const nlohmann::json& value, const std::string& path);
// A finite number ("expected a number" / "not finite" otherwise).
double read_finite(const nlohmann::json& value, const std::string& path);

}  // namespace morphogen::state_json
