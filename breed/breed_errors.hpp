#pragma once
// What a breeding request can get wrong, each with the HTTP status the
// server answers (docs/breed-api.md, "Errors"): the session throws these, the
// server turns them into {"error": what()}.
#include <stdexcept>
#include <string>

namespace morphogen {

struct BreedRequestError : std::runtime_error {
    BreedRequestError(int status, const std::string& message) : std::runtime_error(message), status(status) {}
    int status;  // 400 bad arguments, 404 unknown id, 409 not now (nothing to undo, a search running)
};

inline BreedRequestError bad_request(const std::string& message) { return {400, message}; }
inline BreedRequestError not_found(const std::string& message) { return {404, message}; }
inline BreedRequestError conflict(const std::string& message) { return {409, message}; }

}  // namespace morphogen
