#include "breed/server.hpp"

#include "core/base/atomic_file.hpp"
#include "core/base/errors.hpp"
#include "core/base/json_text.hpp"
#include "breed/breed_assets.hpp"
#include "breed/breed_errors.hpp"
#include "breed/request_body.hpp"
#include "engine/plant_wind.hpp"

#include <httplib.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cstdio>
#include <functional>
#include <optional>
#include <random>
#include <set>
#include <string_view>
#include <vector>

namespace morphogen {

namespace fs = std::filesystem;
using nlohmann::json;

std::string new_breed_token() {
    std::random_device device;
    std::string token;
    for (int i = 0; i < 4; ++i) {
        char part[9];
        std::snprintf(part, sizeof part, "%08x", static_cast<unsigned>(device()));
        token += part;
    }
    return token;
}

namespace {

// A request's answer: status, type and body.
struct Reply {
    int status = 200;
    std::string type = "application/json";
    std::string body;
};

// Invalid UTF-8 (a request's bytes quoted in a message) becomes U+FFFD
// rather than an exception: an error must always reach the client.
std::string json_text(const json& body) { return body.dump(-1, ' ', false, json::error_handler_t::replace); }

Reply json_reply(const json& body, int status = 200) { return {status, "application/json", json_text(body)}; }

// Compares without stopping at the first difference (the token).
bool same_secret(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    unsigned char diff = 0;
    for (std::size_t i = 0; i < a.size(); ++i) diff |= static_cast<unsigned char>(a[i] ^ b[i]);
    return diff == 0;
}

std::string content_type(std::string_view name) {
    auto ends = [&](std::string_view e) { return name.size() >= e.size() && name.substr(name.size() - e.size()) == e; };
    if (ends(".html")) return "text/html; charset=utf-8";
    if (ends(".js") || ends(".mjs")) return "text/javascript; charset=utf-8";
    if (ends(".css")) return "text/css; charset=utf-8";
    if (ends(".json")) return "application/json";
    return "application/octet-stream";
}

bool ends_with(std::string_view s, std::string_view e) {
    return s.size() >= e.size() && s.substr(s.size() - e.size()) == e;
}

// The JSON object of a request body; 400 for anything else.
json body_object(const std::string& body) {
    try {
        return read_json_object(body);
    } catch (const JsonTextError& e) {
        throw bad_request(std::string("the body is not a JSON object: ") + e.what());
    }
}

void allow_only(const json& body, std::initializer_list<const char*> keys) {
    for (const auto& [key, value] : body.items()) {
        bool known = false;
        for (const char* k : keys) known = known || key == k;
        if (!known) throw bad_request("unknown field " + quoted(key));
    }
}

std::vector<std::string> parents_of(const json& body) {
    if (!body.contains("parents")) throw bad_request("missing field \"parents\" (a list of 1 or 2 plant ids)");
    const json& p = body.at("parents");
    if (!p.is_array()) throw bad_request("\"parents\" must be a list of plant ids");
    std::vector<std::string> out;
    for (const json& id : p) {
        if (!id.is_string()) throw bad_request("\"parents\" must be a list of plant ids (strings)");
        out.push_back(id.get<std::string>());
    }
    return out;
}

double number_field(const json& body, const char* key, double fallback) {
    if (!body.contains(key)) return fallback;
    if (!body.at(key).is_number()) throw bad_request(std::string("\"") + key + "\" must be a number");
    return body.at(key).get<double>();
}

int integer_field(const json& body, const char* key, int fallback, int lo, int hi) {
    if (!body.contains(key)) return fallback;
    const json& v = body.at(key);
    if (!v.is_number_integer() || v.get<long long>() < lo || v.get<long long>() > hi)
        throw bad_request(std::string("\"") + key + "\" must be an integer from " + std::to_string(lo) + " to " +
                          std::to_string(hi));
    return static_cast<int>(v.get<long long>());
}

// "wind_presets": a list of engine/plant_wind.hpp's preset names.
std::vector<WindPreset> wind_presets_field(const json& names) {
    const char* what = "\"wind_presets\" must be a list of preset names: color, uv, godot";
    if (!names.is_array()) throw bad_request(what);
    std::vector<WindPreset> presets;
    for (const json& name : names) {
        const std::optional<WindPreset> preset =
            name.is_string() ? wind_preset_named(name.get<std::string>()) : std::nullopt;
        if (!preset) throw bad_request(what);
        presets.push_back(*preset);
    }
    return presets;
}

// "p000042" from "/api/mesh/p000042.glb" (prefix and suffix given); 404 otherwise.
std::string id_in(const std::string& path, std::string_view prefix, std::string_view suffix) {
    if (!ends_with(path, suffix) || path.size() <= prefix.size() + suffix.size())
        throw not_found("no such file: " + path);
    return path.substr(prefix.size(), path.size() - prefix.size() - suffix.size());
}

}  // namespace

struct BreedServer::Impl {
    BreedSession& session;
    BreedServerOptions options;
    httplib::Server server;
    int port = 0;
    std::set<std::string> hosts;    // Host values accepted
    std::set<std::string> origins;  // Origin values accepted

    Impl(BreedSession& s, BreedServerOptions o) : session(s), options(std::move(o)) {}

    // The route of a path: the methods it answers, and what it does.
    struct Route {
        std::vector<std::string> methods;
        std::function<Reply(const std::string& body)> serve;
    };

    std::optional<Route> route(const std::string& path) {
        auto get = [](auto f) { return Route{{"GET"}, f}; };
        auto post = [](auto f) { return Route{{"POST"}, f}; };
        if (path == "/" || path == "/index.html")
            return get([](const std::string&) {
                const auto page = breed_asset("index.html");
                if (!page) throw not_found("this build has no page (breed/assets/index.html)");
                return Reply{200, "text/html; charset=utf-8", std::string(*page)};
            });
        if (path == "/api/state") return get([this](const std::string&) { return json_reply(session.state_json()); });
        if (path == "/api/lineage")
            return get([this](const std::string&) { return json_reply(session.lineage_json()); });
        if (path == "/api/breed")
            return post([this](const std::string& body_text) {
                const json body = body_object(body_text);
                allow_only(body, {"parents", "strength"});
                session.breed(parents_of(body), number_field(body, "strength", 0.5));
                return json_reply(session.state_json());
            });
        if (path == "/api/undo")
            return post([this](const std::string&) {
                session.undo();
                return json_reply(session.state_json());
            });
        if (path == "/api/redo")
            return post([this](const std::string&) {
                session.redo();
                return json_reply(session.state_json());
            });
        if (path == "/api/export")
            return post([this](const std::string& body_text) {
                const json body = body_object(body_text);
                allow_only(body, {"id", "height", "lods", "wind", "wind_presets", "colour", "leaves"});
                if (!body.contains("id") || !body.at("id").is_string())
                    throw bad_request("missing field \"id\" (a plant id)");
                PlantExportOptions o;
                if (body.contains("height")) o.height_m = number_field(body, "height", 0.0);
                o.lods = integer_field(body, "lods", 0, 0, kMaxPlantLods);
                if (body.contains("wind")) {
                    if (!body.at("wind").is_boolean()) throw bad_request("\"wind\" must be true or false");
                    o.wind = body.at("wind").get<bool>();
                }
                for (const auto& [field, flag] : {std::pair{"colour", &o.colour}, std::pair{"leaves", &o.leaves}})
                    if (body.contains(field)) {
                        if (!body.at(field).is_boolean())
                            throw bad_request(std::string("\"") + field + "\" must be true or false");
                        *flag = body.at(field).get<bool>();
                    }
                if (body.contains("wind_presets")) o.wind_presets = wind_presets_field(body.at("wind_presets"));
                const auto [genome, mesh] = session.export_plant(body.at("id").get<std::string>(), o);
                return json_reply({{"genome", genome}, {"mesh", mesh}});
            });
        if (path == "/api/explore")
            return post([this](const std::string& body_text) {
                const json body = body_object(body_text);
                allow_only(body, {"parents", "births", "along"});
                ExploreAlong along = ExploreAlong::architecture;
                if (body.contains("along")) {
                    const json& name = body.at("along");
                    const std::optional<ExploreAlong> named =
                        name.is_string() ? explore_along_from(name.get<std::string>()) : std::nullopt;
                    if (!named) throw bad_request("\"along\" must be \"architecture\" or \"descriptors\"");
                    along = *named;
                }
                session.start_explore(parents_of(body), integer_field(body, "births", 400, 1, kMaxExploreBirths), along);
                return json_reply(session.state_json(), 202);
            });
        if (path == "/api/explore/stop")
            return post([this](const std::string&) {
                session.stop_explore();
                return json_reply(session.state_json());
            });
        if (path.starts_with("/api/mesh/"))
            return get([this, path](const std::string&) {
                return Reply{200, "model/gltf-binary", session.mesh_glb(id_in(path, "/api/mesh/", ".glb"))};
            });
        if (path.starts_with("/api/thumb/"))
            return get([this, path](const std::string&) {
                return Reply{200, "image/png", session.thumb_png(id_in(path, "/api/thumb/", ".png"))};
            });
        if (path.starts_with("/assets/three/"))
            return get([this, path](const std::string&) { return three_file(path.substr(14)); });
        if (path.starts_with("/assets/"))
            return get([path](const std::string&) {
                const std::string name = path.substr(8);
                const auto text = breed_asset(name);
                if (!text) throw not_found("no such file: " + path);
                return Reply{200, content_type(name), std::string(*text)};
            });
        return std::nullopt;
    }

    // A file of Debian's libjs-three, by a plain relative path.
    Reply three_file(const std::string& relative) const {
        const bool plain = !relative.empty() && relative.find("..") == std::string::npos && relative[0] != '/' &&
                           relative.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789._/-") ==
                               std::string::npos;
        const fs::path file = options.three_dir / relative;
        std::error_code ec;
        if (!plain || !fs::is_regular_file(file, ec)) throw not_found("no such file: /assets/three/" + relative);
        return {200, content_type(relative), read_file_bytes(file, {std::uint64_t{64} << 20, "page assets"})};
    }

    // Why the request is refused before it is routed, or 0.
    std::pair<int, std::string> refusal(const httplib::Request& req) const {
        const std::string host = req.get_header_value("Host");
        if (!hosts.contains(host))
            return {403, "the Host header \"" + host + "\" is not this server's (127.0.0.1:" + std::to_string(port) + ")"};
        if (req.has_header("Origin") && !origins.contains(req.get_header_value("Origin")))
            return {403, "the Origin \"" + req.get_header_value("Origin") + "\" is not this server's page"};
        const std::string bearer = req.get_header_value("Authorization");
        const bool by_header = bearer.starts_with("Bearer ") && same_secret(bearer.substr(7), options.token);
        const bool by_query = req.has_param("token") && same_secret(req.get_param_value("token"), options.token);
        if (!by_header && !by_query)
            return {401, "this session needs its token: the token= of the printed address, as a query parameter or "
                         "an Authorization: Bearer header"};
        return {0, ""};
    }

    // Answers `req`, whose body (read within kMaxBreedBody) is `body`.
    void handle(const httplib::Request& req, const std::string& body, httplib::Response& res) {
        Reply reply;
        try {
            if (const auto [status, why] = refusal(req); status != 0) {
                reply = json_reply({{"error", why}}, status);
            } else if (std::optional<Route> r = route(req.path); !r) {
                reply = json_reply({{"error", "no such address: " + req.path}}, 404);
            } else {
                const std::string method = req.method == "HEAD" ? "GET" : req.method;
                if (std::find(r->methods.begin(), r->methods.end(), method) == r->methods.end()) {
                    reply = json_reply({{"error", req.method + " is not allowed on " + req.path + " (use " +
                                                      r->methods.front() + ")"}},
                                       405);
                    res.set_header("Allow", r->methods.front());
                } else {
                    reply = r->serve(body);
                }
            }
        } catch (const BreedRequestError& e) {
            reply = json_reply({{"error", e.message}}, e.status);
        } catch (const std::exception& e) {
            reply = json_reply({{"error", std::string("the server could not do it: ") + e.what()}}, 500);
        }
        res.status = reply.status;
        res.set_header("Cache-Control", "no-store");
        res.set_header("X-Content-Type-Options", "nosniff");
        res.set_content(reply.body, reply.type);
    }
};

BreedServer::BreedServer(BreedSession& session, BreedServerOptions options)
    : impl_(std::make_unique<Impl>(session, std::move(options))) {
    Impl& m = *impl_;
    m.server.new_task_queue = [] { return new httplib::ThreadPool(16); };
    m.server.set_payload_max_length(kMaxBreedBody);
    m.server.set_error_handler(httplib::Server::HandlerWithResponse([](const httplib::Request&, httplib::Response& res) {
        // Ours (a body, or a body provider with its type) stand; httplib's own get a sentence.
        if (!res.body.empty() || res.has_header("Content-Type")) return httplib::Server::HandlerResponse::Unhandled;
        const std::string why = res.status == 413 ? "the request body is larger than " + std::to_string(kMaxBreedBody) + " bytes"
                                                  : "the request was refused (HTTP " + std::to_string(res.status) + ")";
        res.set_content(json{{"error", why}}.dump(), "application/json");
        return httplib::Server::HandlerResponse::Handled;
    }));
    auto handler = [&m](const httplib::Request& req, httplib::Response& res) { m.handle(req, req.body, res); };
    // Methods that may carry a body read it here, within kMaxBreedBody
    // (breed/request_body.hpp); what is left unread closes the connection.
    auto with_body = [&m](const httplib::Request& req, httplib::Response& res, const httplib::ContentReader& reader) {
        const RequestBody body = read_request_body(req, reader, kMaxBreedBody);
        if (body.outcome == RequestBody::Outcome::too_large)
            answer_and_close(res, 413, json_text({{"error", "the request body is larger than " +
                                                                 std::to_string(kMaxBreedBody) + " bytes"}}));
        else if (body.outcome == RequestBody::Outcome::unreadable)
            answer_and_close(res, 400, json_text({{"error", "the request body could not be read: cut short, or framed "
                                                            "other than by Content-Length or chunked transfer encoding"}}));
        else
            m.handle(req, body.bytes, res);
    };
    m.server.Get(".*", handler);
    m.server.Post(".*", with_body);
    m.server.Put(".*", with_body);
    m.server.Patch(".*", with_body);
    m.server.Delete(".*", with_body);
    m.server.Options(".*", handler);
    if (m.options.port == 0) {
        m.port = m.server.bind_to_any_port(m.options.bind);
        if (m.port <= 0) throw IoError("cannot listen on " + m.options.bind + " (any port)");
    } else {
        if (!m.server.bind_to_port(m.options.bind, m.options.port))
            throw IoError("cannot listen on " + m.options.bind + ":" + std::to_string(m.options.port) +
                          " (in use, or not an address of this machine)");
        m.port = m.options.port;
    }
    const std::string port = std::to_string(m.port);
    std::vector<std::string> names = {"127.0.0.1", "localhost"};
    if (m.options.bind != "127.0.0.1") names.push_back(m.options.bind.find(':') != std::string::npos ? "[" + m.options.bind + "]" : m.options.bind);
    for (const std::string& name : names) {
        m.hosts.insert(name + ":" + port);
        m.origins.insert("http://" + name + ":" + port);
    }
}

BreedServer::~BreedServer() { stop(); }

int BreedServer::port() const { return impl_->port; }

std::string BreedServer::address() const {
    const std::string& bind = impl_->options.bind;
    const bool wildcard = bind == "0.0.0.0" || bind == "::" || bind == "127.0.0.1";
    const std::string host = wildcard ? "127.0.0.1" : (bind.find(':') != std::string::npos ? "[" + bind + "]" : bind);
    return "http://" + host + ":" + std::to_string(impl_->port) + "/?token=" + impl_->options.token;
}

void BreedServer::run() { impl_->server.listen_after_bind(); }

void BreedServer::stop() { impl_->server.stop(); }

}  // namespace morphogen
