// World in a build without MPI: main() never makes one (a launched process
// exits 2 first), but the code that uses it still links.
#include "cluster/world.hpp"

#include <exception>
#include <stdexcept>

namespace morphogen::cluster {

World::World(int&, char**&) { throw std::runtime_error("this morphogen was built without MPI"); }
struct World::Posted {};
World::~World() = default;
void World::send(int, int, const std::string&, const std::function<void()>&) { throw std::logic_error("no MPI"); }
Message World::receive(int, int, const std::function<void()>&) { throw std::logic_error("no MPI"); }
std::optional<Message> World::try_receive(int, int) { throw std::logic_error("no MPI"); }
void World::post(int, int, std::string) { throw std::logic_error("no MPI"); }
void World::progress() {}
void World::flush(const std::function<void()>&) {}
void World::Backoff::pause() {}
void World::abort(int) { std::terminate(); }

}  // namespace morphogen::cluster
