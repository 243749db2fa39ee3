#pragma once
// What a breeding request can get wrong, each with the HTTP status the
// server answers (docs/breed-api.md, "Errors"): the session throws these, the
// server turns them into {"error": message}.
#include <nlohmann/json.hpp>

#include <stdexcept>
#include <string>

namespace morphogen {

struct BreedRequestError : std::runtime_error {
    BreedRequestError(int status, const std::string& message)
        : std::runtime_error(message), status(status), message(message) {}
    int status;           // 400 bad arguments, 404 unknown id, 409 not now (nothing to undo, a search running)
    std::string message;  // whole: what() ends at a NUL byte a request put in it
};

inline BreedRequestError bad_request(const std::string& message) { return {400, message}; }
inline BreedRequestError not_found(const std::string& message) { return {404, message}; }
inline BreedRequestError conflict(const std::string& message) { return {409, message}; }

// A request's text (an id, a key) in a message: in double quotes, with JSON's
// escapes for quotes, control characters and NUL, and invalid UTF-8 as U+FFFD.
inline std::string quoted(const std::string& text) {
    return nlohmann::json(text).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace morphogen
