// Python bindings of gecko/seta (see python/gecko/seta.py for the public wrappers).
#include "bindings.hpp"

namespace gecko {
namespace bindings {

void bind_seta(py::module_& m) { (void)m; }

}  // namespace bindings
}  // namespace gecko
