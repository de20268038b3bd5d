#include "scenery.hpp"

namespace sansui::python {

void add_scenery(py::module_& module) {
  (void)module;
}

}  // namespace sansui::python
