// Fuzz target: catenary files (io::read_catenary_file, docs/model-format.md#catenary-files). The
// loader takes a path: the input is written to <scratch>/models/fuzz-input.yaml (next to the
// repository's models, so a relative `file:` resolves). read_catenary_file checks everything and
// makes lumped and wire-profile catenaries, but not a finite-element one (its form-finding and
// factorisation take ≈ 0.1 s on the bundled 10 spans). A finite-element file of at most 2 spans and
// 1 000 elements a wire is also built (form-finding with its stitch wires and irregularities, the
// matrices, the static state: a few ms), so that what the reader accepts is built too.
// Overrides as in fuzz_model.cpp: a line "#@overrides", then "section.key=value" lines.
#include <exception>
#include <string>
#include <vector>

#include "fuzz_common.hpp"
#include "inerta/catenary/fe_catenary.hpp"
#include "inerta/io/catenary_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto& scratch = inerta::fuzz::Scratch::get();
  std::vector<std::string> overrides;
  const std::string text = inerta::fuzz::split_overrides(inerta::fuzz::as_text(data, size), overrides);
  const std::string path = scratch.write("models", text);
  try {
    const inerta::io::CatenaryFile f = inerta::io::read_catenary_file(path, overrides);
    if (f.fe && f.fe->spans <= 2 && f.fe->span / f.fe->element_length <= 500) (void)inerta::catenary::FeLine(*f.fe);
  } catch (const std::exception&) {
  }
  return 0;
}
