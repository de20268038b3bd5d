#include "signatures.hpp"

namespace sansui::python {

std::string scenery_stubs() {
  return "";
}

}  // namespace sansui::python
