#include "fuzz/fuzz_target.hpp"

#include <cxxabi.h>

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <typeinfo>

namespace morphogen::fuzz {

void finding(const std::string& what) {
    std::fprintf(stderr, "fuzz finding: %s\n", what.c_str());
    std::fflush(stderr);
    std::abort();
}

void report_exception(const std::exception& e) {
    const char* mangled = typeid(e).name();
    int status = 0;
    const std::unique_ptr<char, decltype(&std::free)> name(abi::__cxa_demangle(mangled, nullptr, nullptr, &status),
                                                           &std::free);
    finding(std::string("undocumented exception ") + (status == 0 && name ? name.get() : mangled) + ": " +
            e.what());
}

void report_unknown_exception() { finding("an exception that is not a std::exception"); }

}  // namespace morphogen::fuzz
