#pragma once
// Checks every number a command line gives, whatever the command: CLI11 2.1
// reads "-1" into an unsigned option as 2^64-1 and "nan" into a double, and
// the error then surfaces far from the option (or not at all). Each
// unsigned option refuses a sign, each floating-point one a non-finite
// value, naming the option and the value as typed (exit 2).
#include <CLI/CLI.hpp>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <string>

namespace morphogen {

inline void check_numeric_options(CLI::App& app) {
    const CLI::Validator whole_number(
        [](std::string& text) -> std::string {
            const std::size_t first = text.find_first_not_of(" \t");
            if (first != std::string::npos && (text[first] == '-' || text[first] == '+'))
                return "expected a whole number >= 0, got '" + text + "'";
            // CLI11 would read a number past 2^64-1 as 2^64-1 (ERANGE unchecked).
            errno = 0;
            char* end = nullptr;
            (void)std::strtoull(text.c_str(), &end, 10);
            if (errno == ERANGE) return "expected a whole number up to 18446744073709551615, got '" + text + "'";
            return {};
        },
        "", "whole number");
    const CLI::Validator finite_number(
        [](std::string& text) -> std::string {
            char* end = nullptr;
            const double value = std::strtod(text.c_str(), &end);
            if (end != text.c_str() && !std::isfinite(value)) return "expected a finite number, got '" + text + "'";
            return {};
        },
        "", "finite number");
    for (CLI::Option* option : app.get_options()) {
        const std::string type = option->get_type_name();
        if (type.rfind("UINT", 0) == 0) option->check(whole_number);
        else if (type.rfind("FLOAT", 0) == 0) option->check(finite_number);
    }
    for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) check_numeric_options(*sub);
}

}  // namespace morphogen
