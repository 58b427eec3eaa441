// Fuzz target: model files (io::parse_model_file, docs/model-format.md), with overrides.
// The input is the file's text, then optionally a line "#@overrides" and overrides "NAME.KEY=VALUE",
// one a line (fuzz_common.hpp).
#include <exception>
#include <string>
#include <vector>

#include "fuzz_common.hpp"
#include "inerta/io/model_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::vector<std::string> overrides;
  const std::string text = inerta::fuzz::split_overrides(inerta::fuzz::as_text(data, size), overrides);
  try {
    (void)inerta::io::parse_model_file(text, "fuzz.yaml", overrides);
  } catch (const std::exception&) {
  }
  return 0;
}
