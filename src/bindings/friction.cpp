// Python bindings of gecko/friction (see python/gecko/friction.py for the public wrappers).
#include "bindings.hpp"

namespace gecko {
namespace bindings {

void bind_friction(py::module_& m) { (void)m; }

}  // namespace bindings
}  // namespace gecko
