#pragma once
// Writing a whole text file at once (the CSV and JSON writers of io).
#include <string>

namespace inerta::io {

/// Writes `text` to `path` (created or replaced). Throws std::runtime_error "cannot write 'path'"
/// if the file cannot be opened or written.
void write_text_file(const std::string& path, const std::string& text);

}  // namespace inerta::io
