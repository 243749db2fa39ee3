#include "tests/breed/breed_test_support.hpp"

#include "core/base/json_text.hpp"
#include "tests/support/temp_dir.hpp"

#include <algorithm>

namespace morphogen::testing {

ExperimentConfig tiny_breed_config(std::uint64_t seed) {
    ConfigOverrides overrides;
    overrides.seed = seed;
    return read_experiment_config(read_json_object(kTinyBreedConfig), "tiny breed config", overrides);
}

std::vector<std::string> session_files(const std::filesystem::path& dir) {
    std::vector<std::string> files;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(dir))
        if (entry.is_regular_file() && entry.path().extension() != ".tmp")
            files.push_back(entry.path().lexically_relative(dir).string());
    std::sort(files.begin(), files.end());
    return files;
}

std::string session_difference(const std::filesystem::path& a, const std::filesystem::path& b) {
    const std::vector<std::string> fa = session_files(a), fb = session_files(b);
    if (fa != fb) return "the file lists differ (" + std::to_string(fa.size()) + " and " + std::to_string(fb.size()) + " files)";
    for (const std::string& f : fa)
        if (read_text(a / f) != read_text(b / f)) return f + " differs";
    return "";
}

}  // namespace morphogen::testing
