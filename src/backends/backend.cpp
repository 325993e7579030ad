#include "backends/backend.h"

#include <stdexcept>

#include "backends/mesa/mesa_backend.h"

namespace ffc::backends {

std::unique_ptr<Backend> make(const std::string& name) {
  if (name == "mesa") return std::make_unique<MesaBackend>();
  throw std::invalid_argument("unknown backend '" + name + "' (available: mesa)");
}

}  // namespace ffc::backends
