#include "backends/backend.h"

#include <stdexcept>

#include "backends/mesa/mesa_backend.h"
#include "backends/soft/soft_backend.h"

namespace ffc::backends {

std::unique_ptr<Backend> make(const std::string& name) {
  if (name == "mesa") return std::make_unique<MesaBackend>();
  if (name == "soft") return std::make_unique<SoftBackend>(state::Precision::Float);
  if (name == "soft-double") return std::make_unique<SoftBackend>(state::Precision::Double);
  // The spec mode of each: GL 2.1 to the letter where Mesa departs from it.
  if (name == "soft-spec") return std::make_unique<SoftBackend>(state::Precision::Float, true);
  if (name == "soft-double-spec") return std::make_unique<SoftBackend>(state::Precision::Double, true);
  throw std::invalid_argument("unknown backend '" + name + "' (mesa, soft, soft-double, soft-spec or soft-double-spec)");
}

}  // namespace ffc::backends
