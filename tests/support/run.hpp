#pragma once
// Test helper: simulate a model and collect its outputs.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "inerta/error.hpp"
#include "inerta/io/model_file.hpp"
#include "inerta/io/study_file.hpp"
#include "inerta/mbs/assembly.hpp"
#include "inerta/mbs/dynamics.hpp"
#include "inerta/solve/integrator.hpp"
#include "temp.hpp"

namespace inerta::testing {

inline std::string model_path(const std::string& name) { return std::string(INERTA_SOURCE_DIR) + "/models/" + name; }

/// Writes `text` to the file `name` in the system temp directory; returns its path.
inline std::string write_study(const std::string& name, const std::string& text) {
  const auto p = inerta::testing::temp_dir() / name;
  std::ofstream(p) << text;
  return p.string();
}

/// The ModelError message of loading the study `text` (written to the file `name`), or "" if it loads.
inline std::string study_error(const std::string& name, const std::string& text) {
  try {
    io::load_study(write_study(name, text), false);
  } catch (const ModelError& e) {
    return e.what();
  }
  return "";
}

struct Series {
  std::vector<double> t;
  std::vector<std::vector<double>> out;  ///< out[k] = values of output k
  solve::RunStats stats;
  const std::vector<double>& operator[](std::size_t k) const { return out[k]; }
};

inline Series run(const mbs::Model& model, double t_end, double dt, const solve::IntegratorOptions& opt = {}) {
  Series s;
  s.out.resize(model.outputs.size());
  mbs::State x = mbs::assemble(model, 0.0);
  s.stats =
      solve::integrate(model, x, 0.0, t_end, dt, opt, [&](double t, const mbs::State& xs, const mbs::Workspace& ws) {
        s.t.push_back(t);
        for (std::size_t k = 0; k < model.outputs.size(); ++k)
          s.out[k].push_back(mbs::evaluate_output(model.outputs[k], model, t, xs, ws));
      });
  return s;
}

/// Peak-to-peak and mean of v over the samples with t >= t_from.
struct Window {
  double ptp, mean;
};
inline Window window(const std::vector<double>& t, const std::vector<double>& v, double t_from) {
  double lo = 1e300, hi = -1e300, sum = 0;
  long n = 0;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] >= t_from - 1e-12) lo = std::min(lo, v[i]), hi = std::max(hi, v[i]), sum += v[i], ++n;
  return {hi - lo, sum / static_cast<double>(n)};
}

}  // namespace inerta::testing
