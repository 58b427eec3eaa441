#pragma once
// Where this program runs from (issue 51, docs/install.md): an installed <prefix>/bin/inerta reads its data in
// <prefix>/share/inerta and runs the Python package installed under <prefix>; a build tree's, the source
// tree's and the build tree's.
#include <string>

namespace inerta::cli {

/// At start: io::set_data_dir(<bin>/../share/inerta) when this program is an installed copy.
void find_installed_data();
/// The folder to put on PYTHONPATH for the Dask driver (python/inerta/distributed.py).
std::string python_package_dir();

}  // namespace inerta::cli
