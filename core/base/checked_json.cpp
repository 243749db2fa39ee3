#include "core/base/checked_json.hpp"

#include <cmath>
#include <stdexcept>

namespace morphogen::checked_json {

void fail(const std::string& path, const std::string& what) { throw std::invalid_argument(path + ": " + what); }

const nlohmann::json& member(const nlohmann::json& object, const char* key, const std::string& path) {
    if (!object.is_object()) fail(path, "expected an object");
    auto it = object.find(key);
    if (it == object.end()) fail(path, std::string("missing \"") + key + "\"");
    return *it;
}

std::uint64_t read_u64(const nlohmann::json& value, const std::string& path) {
    if (!value.is_number_unsigned()) fail(path, "expected a non-negative integer");
    return value.get<std::uint64_t>();
}

double read_finite(const nlohmann::json& value, const std::string& path) {
    if (!value.is_number()) fail(path, "expected a number");
    const double v = value.get<double>();
    if (!std::isfinite(v)) fail(path, "not finite");
    return v;
}

std::vector<double> read_finite_array(const nlohmann::json& value, const std::string& path) {
    if (!value.is_array()) fail(path, "expected an array");
    std::vector<double> out;
    out.reserve(value.size());
    for (std::size_t i = 0; i < value.size(); ++i) out.push_back(read_finite(value[i], path + "[" + std::to_string(i) + "]"));
    return out;
}

}  // namespace morphogen::checked_json
