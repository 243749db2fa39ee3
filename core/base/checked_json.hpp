#pragma once
// Strict readers for the JSON morphogen writes itself (the search states in a
// checkpoint): a missing key or a wrong value is a defect of the file, so each
// throws std::invalid_argument("<path>: <defect>") at the first one, and no
// default is filled in. Configs a person writes go through config_reader.hpp,
// which collects every problem and fills in defaults.
#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace morphogen::checked_json {

[[noreturn]] void fail(const std::string& path, const std::string& what);
// object[key], failing if `object` is not an object or lacks the key.
const nlohmann::json& member(const nlohmann::json& object, const char* key, const std::string& path);
std::uint64_t read_u64(const nlohmann::json& value, const std::string& path);
// A finite number ("expected a number" / "not finite" otherwise).
double read_finite(const nlohmann::json& value, const std::string& path);
// An array of finite numbers ("expected an array" otherwise; elements as read_finite).
std::vector<double> read_finite_array(const nlohmann::json& value, const std::string& path);

}  // namespace morphogen::checked_json
