#include "inerta/io/text_file.hpp"

#include <fstream>
#include <stdexcept>

namespace inerta::io {

void write_text_file(const std::string& path, const std::string& text) {
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  if (file) file << text;
  if (file) file.close();
  if (!file) throw std::runtime_error("cannot write '" + path + "'");
}

}  // namespace inerta::io
