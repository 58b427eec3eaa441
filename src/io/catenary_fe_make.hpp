#pragma once
// The finite-element catenary object from its data, in a file of its own (catenary_fe_make.cpp) so
// that the catenary-file reader does not depend on the finite-element solver's translation units.
#include <memory>

#include "inerta/catenary/fe_catenary.hpp"

namespace inerta::io::detail {

/// std::make_shared<catenary::FeCatenary>(d); InvalidArgument / ModelError from its constructor.
std::shared_ptr<const catenary::Catenary> make_fe(const catenary::FeCatenaryData& d);

}  // namespace inerta::io::detail
