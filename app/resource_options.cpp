#include "app/resource_options.hpp"

namespace morphogen {

ResourceLimits ResourceOptions::limits() const {
    ResourceLimits limits = default_resource_limits();
    if (!max_memory.empty()) limits.max_memory_bytes = *parse_byte_size(max_memory);  // checked by the option
    limits.max_eval_seconds = max_eval_seconds;
    limits.enabled = !no_limits;
    return limits;
}

void add_resource_options(CLI::App* command, ResourceOptions& options) {
    const CLI::Validator size(
        [](std::string& text) {
            return parse_byte_size(text) ? std::string()
                                         : "expected a size such as 8G, 512M or 1.5T (K, M, G, T = powers of 1024)";
        },
        "SIZE");
    command
        ->add_option("--max-memory", options.max_memory,
                     "Refuse a config estimated to need more memory than this (default: half of this machine's, " +
                         format_bytes(default_resource_limits().max_memory_bytes) + ")")
        ->check(size)
        ->group("Resource limits");
    command
        ->add_option("--max-eval-time", options.max_eval_seconds,
                     "Refuse a config whose worst genome is estimated to take longer than this many seconds of one "
                     "core to grow and score")
        ->check(CLI::PositiveNumber)
        ->default_val(default_max_eval_seconds)
        ->group("Resource limits");
    command->add_flag("--no-limits", options.no_limits, "Refuse nothing for its size (docs/limits.md)")
        ->group("Resource limits");
}

}  // namespace morphogen
