#include "backends/backend.h"

#include <map>
#include <stdexcept>

#include "backends/soft/soft_backend.h"

namespace ffc::backends {

namespace {

// Function-local, so that registrations from other libraries' static initializers find it made.
std::map<std::string, Factory>& registry() {
  static std::map<std::string, Factory> r;
  return r;
}

const char* const kOurs[] = {"soft", "soft-double", "soft-spec", "soft-double-spec"};

}  // namespace

bool register_backend(const std::string& name, Factory factory) {
  registry()[name] = factory;
  return true;
}

std::vector<std::string> names() {
  std::vector<std::string> out(std::begin(kOurs), std::end(kOurs));
  for (const auto& entry : registry()) out.push_back(entry.first);
  return out;
}

std::unique_ptr<Backend> make(const std::string& name) {
  if (auto it = registry().find(name); it != registry().end()) return it->second();
  if (name == "soft") return std::make_unique<SoftBackend>(state::Precision::Float);
  if (name == "soft-double") return std::make_unique<SoftBackend>(state::Precision::Double);
  // The spec mode of each: GL 2.1 to the letter where Mesa departs from it.
  if (name == "soft-spec") return std::make_unique<SoftBackend>(state::Precision::Float, true);
  if (name == "soft-double-spec") return std::make_unique<SoftBackend>(state::Precision::Double, true);
  if (name == "mesa")
    throw std::invalid_argument(
        "backend 'mesa' is not built: neither OSMesa nor EGL was found at configure time (or both "
        "FFCOMPAT_WITH_OSMESA and FFCOMPAT_WITH_EGL were OFF, or the program does not link ffcompat_mesa)");
  throw std::invalid_argument("unknown backend '" + name + "' (mesa, soft, soft-double, soft-spec or soft-double-spec)");
}

}  // namespace ffc::backends
