#include "backends/backend.h"

#include <stdexcept>

#include "backends/mesa/mesa_backend.h"
#include "backends/soft/soft_backend.h"

namespace ffc::backends {

std::unique_ptr<Backend> make(const std::string& name) {
  if (name == "mesa") return std::make_unique<MesaBackend>();
  if (name == "soft") return std::make_unique<SoftBackend>(state::Precision::Float);
  if (name == "soft-double") return std::make_unique<SoftBackend>(state::Precision::Double);
  throw std::invalid_argument("unknown backend '" + name + "' (mesa, soft or soft-double)");
}

}  // namespace ffc::backends
