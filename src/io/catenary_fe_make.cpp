// The finite-element catenary object (catenary_fe_make.hpp).
//
// TEMPORARY (branch helper-a): FeCatenary is declared in catenary/fe_catenary.hpp but its
// implementation is not on this branch yet, so the call below cannot link here. At the merge,
// replace the body by
//     return std::make_shared<catenary::FeCatenary>(d);
#include "catenary_fe_make.hpp"

#include <fmt/format.h>

#include "inerta/error.hpp"

namespace inerta::io::detail {

std::shared_ptr<const catenary::Catenary> make_fe(const catenary::FeCatenaryData& d) {
  throw ModelError(fmt::format("the finite-element catenary ({} spans of {:g} m) is not built into this version of "
                               "Inerta yet; `inerta check` reads the file",
                               d.spans, d.span));
}

}  // namespace inerta::io::detail
