#pragma once
// Where the program's data are read at run time (issue 51): the criteria presets (criteria/), the default
// models (models/) and the plotting scripts (scripts/). In order: $INERTA_DATA_DIR; else the folder the
// host set (the CLI: <bin>/../share/inerta of an installed program; the Python module: the share/inerta
// beside its installed package); else the source tree the build came from. docs/install.md.
#include <filesystem>

namespace inerta::io {

std::filesystem::path data_dir();
/// Sets the host's data folder if it holds criteria/ (an installed copy); returns whether it did.
bool set_data_dir(const std::filesystem::path& dir);
/// The source tree the build came from (the last resort of data_dir()).
std::filesystem::path source_tree();

}  // namespace inerta::io
