#pragma once
// Looking for one problem among those a config reader collected.
#include "core/base/config_reader.hpp"

#include <string>

namespace morphogen::testing {

// True if `issues` has one at `path` whose message contains `fragment`.
inline bool has_issue(const ConfigIssues& issues, const std::string& path, const std::string& fragment) {
    for (const ConfigIssue& issue : issues.list())
        if (issue.path == path && issue.message.find(fragment) != std::string::npos) return true;
    return false;
}

}  // namespace morphogen::testing
