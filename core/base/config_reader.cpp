#include "core/base/config_reader.hpp"

#include "core/base/errors.hpp"
#include "core/base/json_text.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <variant>

namespace morphogen {

using nlohmann::json;

void ConfigIssues::add(std::string path, std::string message) {
    issues_.push_back({std::move(path), std::move(message)});
}

std::string ConfigIssues::format(const std::string& source) const {
    std::string out;
    for (const auto& issue : issues_) {
        if (!out.empty()) out += '\n';
        out += source;
        out += ": ";
        if (!issue.path.empty()) out += issue.path + ": ";
        out += issue.message;
    }
    return out;
}

void ConfigIssues::throw_if_any(const std::string& source) const {
    if (!issues_.empty()) throw ConfigError(format(source));
}

std::size_t edit_distance(const std::string& a, const std::string& b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t above = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diagonal = above;
        }
    }
    return row[b.size()];
}

std::optional<std::string> nearest(const std::string& word, const std::vector<std::string>& candidates) {
    std::optional<std::string> best;
    std::size_t best_distance = std::max<std::size_t>(2, word.size() / 3) + 1;
    for (const auto& candidate : candidates) {
        const std::size_t d = edit_distance(word, candidate);
        if (d < best_distance) {
            best_distance = d;
            best = candidate;
        }
    }
    return best;
}

namespace {
std::string show(const json& value) {
    std::string text = value.dump();
    if (text.size() > 60) text = text.substr(0, 57) + "...";
    return text;
}
std::string type_name(const json& value) {
    return value.type_name();
}
// 2^53 - 1: every integer up to this is exact as a double.
constexpr double max_exact_float_integer = 9007199254740991.0;
// A key or string as JSON writes it: quoted and escaped, so it cannot split a line.
std::string quote_json(const std::string& text) {
    return json(text).dump(-1, ' ', false, json::error_handler_t::replace);
}
// An integer in [min, max], or the message saying why the value is not one.
// A whole number written in float form (9e15, 3.0) counts up to 2^53 - 1:
// beyond that a double cannot tell it from its neighbours.
std::variant<long long, std::string> whole_number(const json& value, long long min, long long max) {
    const std::string out_of_range =
        show(value) + " is out of range [" + std::to_string(min) + ", " + std::to_string(max) + "]";
    if (value.is_number_integer()) {
        if (value.is_number_unsigned() && value.get<unsigned long long>() >
                                              static_cast<unsigned long long>(std::numeric_limits<long long>::max()))
            return out_of_range;
        const auto v = value.get<long long>();
        if (v < min || v > max) return out_of_range;
        return v;
    }
    if (value.is_number_float()) {
        const double d = value.get<double>();
        if (std::isfinite(d) && std::floor(d) == d) {
            if (d < static_cast<double>(min) || d > static_cast<double>(max)) return out_of_range;
            if (std::abs(d) > max_exact_float_integer)
                return show(value) + " is too large to be exact in float form; write it as a plain integer";
            return static_cast<long long>(d);
        }
    }
    return "expected an integer, got " + type_name(value) + " " + show(value);
}
std::string show_number(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}
}  // namespace

ObjectReader::ObjectReader(const json* object, std::string path, ConfigIssues& issues)
    : object_(object), path_(std::move(path)), issues_(issues) {
    // null is refused like any other non-object: {"network": null} is a
    // mistake, not a request for the defaults (leave the key out for those).
    if (object_ != nullptr && object_->is_null()) {
        issues_.add(path_, "expected an object, got null (leave the section out to take its defaults)");
        object_ = nullptr;
    }
    if (object_ != nullptr && !object_->is_object()) {
        issues_.add(path_, "expected an object, got " + type_name(*object_) + " " + show(*object_));
        object_ = nullptr;
    }
}

std::string ObjectReader::path_of(const std::string& key) const {
    return path_.empty() ? key : path_ + "." + key;
}

const json* ObjectReader::find(const std::string& key) {
    known_.push_back(key);
    if (object_ == nullptr) return nullptr;
    auto it = object_->find(key);
    return it == object_->end() ? nullptr : &*it;
}

double ObjectReader::number(const std::string& key, double fallback, double min, double max,
                            bool min_exclusive) {
    const json* value = find(key);
    double result = fallback;
    if (value != nullptr) {
        if (!value->is_number()) {
            issues_.add(path_of(key), "expected a number, got " + type_name(*value) + " " + show(*value));
        } else {
            const double v = value->get<double>();
            const bool below = min_exclusive ? !(v > min) : !(v >= min);
            if (!std::isfinite(v) || below || v > max) {
                std::string range(min_exclusive ? "(" : "[");
                range += show_number(min) + ", " + show_number(max) + "]";
                issues_.add(path_of(key), show(*value) + " is out of range " + range);
            } else {
                result = v;
            }
        }
    }
    resolved_[key] = result;
    return result;
}

long long ObjectReader::integer(const std::string& key, long long fallback, long long min, long long max) {
    const json* value = find(key);
    long long result = fallback;
    if (value != nullptr) {
        auto read = whole_number(*value, min, max);
        if (auto* v = std::get_if<long long>(&read))
            result = *v;
        else
            issues_.add(path_of(key), std::get<std::string>(read));
    }
    resolved_[key] = result;
    return result;
}

bool ObjectReader::boolean(const std::string& key, bool fallback) {
    const json* value = find(key);
    bool result = fallback;
    if (value != nullptr) {
        if (!value->is_boolean())
            issues_.add(path_of(key), "expected true or false, got " + type_name(*value) + " " + show(*value));
        else
            result = value->get<bool>();
    }
    resolved_[key] = result;
    return result;
}

std::string ObjectReader::string(const std::string& key, const std::string& fallback) {
    const json* value = find(key);
    std::string result = fallback;
    if (value != nullptr) {
        if (!value->is_string())
            issues_.add(path_of(key), "expected a string, got " + type_name(*value) + " " + show(*value));
        else
            result = value->get<std::string>();
    }
    resolved_[key] = result;
    return result;
}

std::string ObjectReader::choice(const std::string& key, const std::string& fallback,
                                 const std::vector<std::string>& allowed) {
    const bool present = object_ != nullptr && object_->contains(key);
    std::string result = string(key, fallback);
    if (present && std::find(allowed.begin(), allowed.end(), result) == allowed.end() &&
        (*object_)[key].is_string()) {
        std::string list;
        for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + ("\"" + a + "\"");
        std::string message = quote_json(result) + " is not one of " + list;
        if (auto near = nearest(result, allowed)) message += " (did you mean \"" + *near + "\"?)";
        issues_.add(path_of(key), message);
        result = fallback;
        resolved_[key] = result;
    }
    return result;
}

std::vector<long long> ObjectReader::integer_list(const std::string& key, const std::vector<long long>& fallback,
                                                  long long min, long long max) {
    const json* value = find(key);
    std::vector<long long> result = fallback;
    if (value != nullptr) {
        if (!value->is_array()) {
            issues_.add(path_of(key), "expected a list of integers, got " + type_name(*value) + " " + show(*value));
        } else {
            std::vector<long long> items;
            bool ok = true;
            for (std::size_t i = 0; i < value->size(); ++i) {
                const json& item = (*value)[i];
                const std::string item_path = path_of(key) + "[" + std::to_string(i) + "]";
                auto read = whole_number(item, min, max);
                if (auto* v = std::get_if<long long>(&read)) {
                    items.push_back(*v);
                } else {
                    issues_.add(item_path, std::get<std::string>(read));
                    ok = false;
                }
            }
            if (ok) result = items;
        }
    }
    resolved_[key] = result;
    return result;
}

std::vector<double> ObjectReader::number_list(const std::string& key, const std::vector<double>& fallback,
                                              double min, double max) {
    const json* value = find(key);
    std::vector<double> result = fallback;
    if (value != nullptr) {
        if (!value->is_array()) {
            issues_.add(path_of(key), "expected a list of numbers, got " + type_name(*value) + " " + show(*value));
        } else {
            std::vector<double> items;
            bool ok = true;
            for (std::size_t i = 0; i < value->size(); ++i) {
                const json& item = (*value)[i];
                const std::string item_path = path_of(key) + "[" + std::to_string(i) + "]";
                if (!item.is_number()) {
                    issues_.add(item_path, "expected a number, got " + type_name(item) + " " + show(item));
                    ok = false;
                } else if (!(item.get<double>() >= min && item.get<double>() <= max)) {
                    issues_.add(item_path, show(item) + " is out of range [" + show_number(min) + ", " +
                                               show_number(max) + "]");
                    ok = false;
                } else {
                    items.push_back(item.get<double>());
                }
            }
            if (ok) result = items;
        }
    }
    resolved_[key] = result;
    return result;
}

const json* ObjectReader::raw(const std::string& key) { return find(key); }

void ObjectReader::set_resolved(const std::string& key, json value) { resolved_[key] = std::move(value); }

void ObjectReader::finish() {
    if (object_ == nullptr) return;
    for (const auto& [key, value] : object_->items()) {
        if (std::find(known_.begin(), known_.end(), key) != known_.end()) continue;
        std::string message = "unknown key " + quote_json(key);
        if (auto near = nearest(key, known_)) message += " (did you mean \"" + *near + "\"?)";
        const bool plain = std::all_of(key.begin(), key.end(), [](char c) { return c > ' ' && c != 127; });
        issues_.add(path_of(plain ? key : quote_json(key)), message);
    }
}

json parse_json_text(const std::string& text, const std::string& source) {
    try {
        return read_json_object(text);
    } catch (const JsonTextError& e) {
        throw ConfigError(source + ": invalid JSON at " + e.what());
    }
}

std::string read_document_file(const std::string& path, FileBound bound) { return read_file_bytes(path, bound); }

json load_json_file(const std::string& path) { return parse_json_text(read_document_file(path, config_bound), path); }

}  // namespace morphogen
