// Fuzz target: catenary files (io::read_catenary_file, docs/model-format.md#catenary-files). The
// loader takes a path: the input is written to <scratch>/models/fuzz-input.yaml (next to the
// repository's models, so a relative `file:` resolves). read_catenary_file checks everything and
// makes lumped and wire-profile catenaries, but not a finite-element one (its form-finding and
// factorisation take seconds, not a parser's job): that is the one part of load_catenary not fuzzed.
// Overrides as in fuzz_model.cpp: a line "#@overrides", then "section.key=value" lines.
#include <exception>
#include <string>
#include <vector>

#include "fuzz_common.hpp"
#include "inerta/io/catenary_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto& scratch = inerta::fuzz::Scratch::get();
  std::vector<std::string> overrides;
  const std::string text = inerta::fuzz::split_overrides(inerta::fuzz::as_text(data, size), overrides);
  const std::string path = scratch.write("models", text);
  try {
    (void)inerta::io::read_catenary_file(path, overrides);
  } catch (const std::exception&) {
  }
  return 0;
}
