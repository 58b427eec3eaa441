// `inerta admittance LAYOUT` (docs/cli.md): Y(jω) of a network.
#include "checks.hpp"
#include "commands.hpp"
#include "common.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <unistd.h>
#include <CLI/CLI.hpp>
#include <cctype>
#include <charconv>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <memory>
#include <numbers>
#include <optional>
#include <sstream>

#include "inerta/analysis/acceptance.hpp"
#include "inerta/analysis/catenary_response.hpp"
#include "inerta/analysis/contact_statistics.hpp"
#include "inerta/analysis/cost_guard.hpp"
#include "inerta/analysis/frf.hpp"
#include "inerta/io/model_study_file.hpp"
#include "inerta/analysis/periodic.hpp"
#include "inerta/analysis/modal.hpp"
#include "inerta/analysis/simulate.hpp"
#include "inerta/catenary/fe_catenary.hpp"
#include "inerta/catenary/lumped.hpp"
#include "inerta/error.hpp"
#include "inerta/io/acceptance_file.hpp"
#include "inerta/io/catenary_file.hpp"
#include "inerta/io/lumped_fit_file.hpp"
#include "inerta/io/file_kind.hpp"
#include "inerta/io/linear_model_file.hpp"
#include "inerta/io/model_file.hpp"
#include "inerta/io/study_file.hpp"
#include "inerta/io/structure_results.hpp"
#include "inerta/io/study_report.hpp"
#include "inerta/io/study_results.hpp"
#include "inerta/io/files.hpp"
#include "inerta/mbs/assembly.hpp"
#include "inerta/mbs/dynamics.hpp"
#include "inerta/mbs/linearisation.hpp"
#include "inerta/network/layouts.hpp"
#include "inerta/network/realisation.hpp"
#include "inerta/optim/report.hpp"
#include "inerta/optim/study.hpp"
#include "inerta/pantograph/suspension.hpp"
#include "inerta/solve/integrator.hpp"

namespace inerta::cli {

namespace admittance_command {
namespace {

struct AdmittanceArgs {
  std::string layout, freq, out;
  std::vector<std::string> params;
};

int cmd_admittance(const AdmittanceArgs& a) {
  io::check_output_path(a.out);
  network::Params params = parse_params(a.params);
  network::Network net;
  try {
    net = network::resolve(a.layout, params);
  } catch (const network::NetworkError& e) {
    std::string where = e.column > 0 ? fmt::format("\n  {}\n  {:>{}}", a.layout, "^", e.column) : "";
    throw ModelError(fmt::format("network '{}': {}{}", a.layout, e.what(), where));
  }
  const std::vector<double> f = frequency_range(a.freq);
  network::Network s = network::simplify(net);
  std::FILE* info = a.out.empty() ? stderr : stdout;
  fmt::print(info, "network: {}  →  {}\n", network::to_string(net, true), network::to_string(s, true));
  if (s.kind == network::Network::Kind::Rigid)
    throw ModelError(fmt::format("network '{}' is rigid with these values: its admittance is infinite", a.layout));
  if (s.kind != network::Network::Kind::Open) {
    network::Rational y = network::rational_admittance(s);
    auto poly = [](const network::Poly& p) {
      std::string t;
      for (std::size_t i = 0; i < p.size(); ++i)
        if (p[i] != 0)
          t += fmt::format("{}{:g}{}", t.empty() ? "" : " + ", p[i],
                           i == 0   ? ""
                           : i == 1 ? " s"
                                    : fmt::format(" s^{}", i));
      return t.empty() ? std::string("0") : t;
    };
    fmt::print(info, "Y(s) = F/v = ({}) / ({})\n", poly(y.num), poly(y.den));
  } else {
    fmt::print(info, "the network is open with these values: Y = 0\n");
  }
  for (double fk : f)
    if (!std::isfinite(std::abs(network::admittance(s, {0.0, 2 * std::numbers::pi * fk}))))
      throw ModelError(
          fmt::format("network '{}': Y is infinite at f = {:g} Hz (a spring path gives a static "
                      "stiffness); start --freq above 0",
                      a.layout, fk));
  OutputFile file(a.out);
  std::FILE* out = file.get();
  fmt::print(out, "f_hz,mag,phase_deg,re,im\n");
  for (double fk : f) {
    std::complex<double> y = network::admittance(s, {0.0, 2 * std::numbers::pi * fk});
    fmt::print(out, "{:.10g},{:.10g},{:.10g},{:.10g},{:.10g}\n", fk, std::abs(y), std::arg(y) * 180 / std::numbers::pi,
               y.real(), y.imag());
  }
  file.commit();
  if (!a.out.empty()) fmt::print(info, "wrote {} ({} frequencies)\n", a.out, f.size());
  return 0;
}

AdmittanceArgs aa;

}  // namespace
}  // namespace admittance_command

Command add_admittance_command(CLI::App& app) {
  using namespace admittance_command;
  auto* adm = app.add_subcommand("admittance", "Admittance Y = force / relative velocity of a network (CSV)");
  adm->add_option("layout", aa.layout, "Named layout (S2-default, S1-3, ...) or expression such as \"b-(k|c)\"")
      ->required();
  adm->add_option("--param", aa.params, "Element value NAME=VALUE (SI; 0 = open, inf = rigid); repeatable");
  adm->add_option("--freq", aa.freq, "Frequencies F0:DF:F1 in Hz")->required();
  adm->add_option("--out", aa.out, "CSV file (default: standard output)");
  return {adm, [] { return cmd_admittance(aa); }};
}

}  // namespace inerta::cli
