// Fuzz target: acceptance criteria files (io::load_acceptance, docs/contact-quality.md "Acceptance
// criteria"). The loader takes a path: the input is written to <scratch>/models/fuzz-input.yaml (a
// path ending in .yaml, so never taken for a preset name). A set that loads is then judged against
// a fixed verdict input, so the criteria's numbers reach the verdict's arithmetic too.
#include <exception>
#include <string>

#include "fuzz_common.hpp"
#include "inerta/analysis/acceptance.hpp"
#include "inerta/io/acceptance_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto& scratch = inerta::fuzz::Scratch::get();
  const std::string path = scratch.write("models", inerta::fuzz::as_text(data, size));
  try {
    const auto c = inerta::io::load_acceptance(path);
    inerta::analysis::VerdictInput in;
    in.speed = 300 / 3.6;
    in.raw = inerta::analysis::statistics({100, 0, 0, 120, 80, 0, 150});
    in.filtered = in.raw, in.has_filtered = true;
    in.loss_runs = inerta::analysis::loss_runs({100, 0, 0, 120, 80, 0, 150});
    in.has_loss_runs = true, in.sample_dt = 1e-3;
    in.uplift_max = 0.05, in.uplift_limit = 0.12;
    (void)inerta::analysis::passed(inerta::analysis::assess(c, in));
    if (c.has_target) (void)c.target.at(300);
  } catch (const std::exception&) {
  }
  return 0;
}
