#pragma once
// Reading one JSON config object with every problem collected, not just the
// first. Each read names its key path ("growth.split_area"), checks type and
// range, records the value actually used (defaults filled in) in `resolved()`,
// and `finish()` reports keys nobody read as unknown, suggesting the nearest
// known key. Modules (growth, network, fitness, evolution, run) each read their
// own section with one of these; the caller throws once with all issues.
#include "core/base/atomic_file.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace morphogen {

struct ConfigIssue {
    std::string path;     // JSON path, e.g. "growth.split_area" ("" = the document)
    std::string message;  // what is wrong, naming the bad value
};

// Accumulates issues across readers; throw_if_any() raises one ConfigError.
class ConfigIssues {
public:
    void add(std::string path, std::string message);
    bool empty() const { return issues_.empty(); }
    const std::vector<ConfigIssue>& list() const { return issues_; }
    // One line per issue: "<source>: <path>: <message>".
    std::string format(const std::string& source) const;
    void throw_if_any(const std::string& source) const;

private:
    std::vector<ConfigIssue> issues_;
};

// Levenshtein distance, used to suggest the nearest known key.
std::size_t edit_distance(const std::string& a, const std::string& b);
// The candidate nearest to `word`, if it is near enough to be a plausible typo.
std::optional<std::string> nearest(const std::string& word, const std::vector<std::string>& candidates);

class ObjectReader {
public:
    // `object` may be null/absent (treated as {}); a non-object is an issue.
    ObjectReader(const nlohmann::json* object, std::string path, ConfigIssues& issues);

    double number(const std::string& key, double fallback, double min, double max,
                  bool min_exclusive = false);
    long long integer(const std::string& key, long long fallback, long long min, long long max);
    bool boolean(const std::string& key, bool fallback);
    std::string string(const std::string& key, const std::string& fallback);
    // String that must be one of `allowed`.
    std::string choice(const std::string& key, const std::string& fallback,
                       const std::vector<std::string>& allowed);
    std::vector<long long> integer_list(const std::string& key, const std::vector<long long>& fallback,
                                        long long min, long long max);
    std::vector<double> number_list(const std::string& key, const std::vector<double>& fallback,
                                    double min, double max);
    // Raw access for nested structures (e.g. fitness terms); marks the key known.
    // Returns null if absent. The caller must set resolved(key) itself.
    const nlohmann::json* raw(const std::string& key);
    void set_resolved(const std::string& key, nlohmann::json value);
    // Leaves `key` out of the resolved object (a key that does not apply).
    void drop_resolved(const std::string& key) { resolved_.erase(key); }

    // Report unknown keys (with a suggestion). Call after all reads.
    void finish();

    std::string path_of(const std::string& key) const;
    const nlohmann::json& resolved() const { return resolved_; }
    ConfigIssues& issues() { return issues_; }

private:
    const nlohmann::json* find(const std::string& key);

    const nlohmann::json* object_;
    std::string path_;
    ConfigIssues& issues_;
    std::vector<std::string> known_;
    nlohmann::json resolved_ = nlohmann::json::object();
};

// Parse JSON text with the strict reader (json_text.hpp): anything but one
// well-formed JSON object within its limits is a ConfigError naming source,
// line, column and key path.
nlohmann::json parse_json_text(const std::string& text, const std::string& source);
// A file's bytes, at most `bound`; IoError (with the system's reason) if it
// cannot be read, is not a regular file or is larger (read_file_bytes).
std::string read_document_file(const std::string& path, FileBound bound);
// The most a config file may hold: far beyond any config the limits let run
// (the largest, with every key and 8 emitters, is a few kilobytes).
inline constexpr FileBound config_bound{std::uint64_t{16} << 20, "config files"};
// Read and parse a config file, at most config_bound (IoError if unreadable,
// ConfigError if malformed).
nlohmann::json load_json_file(const std::string& path);

}  // namespace morphogen
