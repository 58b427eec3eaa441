// Fuzz target: study files, as `inerta optimise` reads them: io::is_model_study, then
// io::load_model_study (docs/studies.md) or io::load_study (pantograph J2 study). The input is
// written to <scratch>/studies/fuzz-input.yaml, so the seeds' "../models/hsx.yaml" resolves to the
// repository's models (fuzz_common.hpp). Nothing is optimised: only the loading, without the
// operating lengths (a pantograph study's static equilibria under each catenary: ≈ 1 s a seed with
// the sanitizers, which held the target at ≈ 1 exec/s — issue 38) and without a model study's
// baseline (an rms, H∞ or peak analysis of the model: a grown corpus's inputs held the target at
// ≈ 9 exec/s). Both are the library's analysis, tested in tests/optim, not the file reader's.
#include <exception>

#include "fuzz_common.hpp"
#include "inerta/io/model_study_file.hpp"
#include "inerta/io/study_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto& scratch = inerta::fuzz::Scratch::get();
  const std::string path = scratch.write("studies", inerta::fuzz::as_text(data, size));
  try {
    if (inerta::io::is_model_study(path))
      (void)inerta::io::load_model_study(path, false);
    else
      (void)inerta::io::load_study(path, false);
  } catch (const std::exception&) {
  }
  return 0;
}
