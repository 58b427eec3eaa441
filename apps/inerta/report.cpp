// Reports in the CLI: --report and `inerta verify-report` (docs/cli.md "Reports").
#include "report.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "inerta/error.hpp"
#include "inerta/network/layouts.hpp"
#include "inerta/io/files.hpp"
#include "inerta/report/record.hpp"

extern char** environ;

namespace inerta::cli {

namespace fs = std::filesystem;

namespace {
std::vector<std::string> argv_;
struct VerifyArgs {
  std::string file;
  double rtol = 0;
  bool keep = false;
} verify_args;
CLI::App* verify_cmd = nullptr;
}  // namespace

void set_command_line(int argc, char** argv) { argv_.assign(argv, argv + argc); }
const std::vector<std::string>& command_line() { return argv_; }

void add_report_option(CLI::App* app, std::string& report) {
  app->add_option("--report", report,
                  "Write a self-contained HTML report: the verdict first (with --acceptance), tables, figures, and the "
                  "provenance that `inerta verify-report` re-runs")
      ->check(CLI::Validator(
          [](std::string& s) { return s.empty() ? std::string("an empty file name: give FILE.html") : std::string(); },
          "FILE.html"));
}

report::Provenance run_provenance(std::vector<std::pair<std::string, std::string>> settings) {
  report::Provenance p = report::current_provenance(argv_);
  p.settings = std::move(settings);
  return p;
}

report::RunContext line_run_context(const std::string& model, const CatenaryArgs& cat, const catenary::Catenary& line,
                                    const analysis::AcceptanceCriteria* criteria,
                                    const std::vector<analysis::VerdictRow>& verdict,
                                    std::vector<std::pair<std::string, std::string>> settings) {
  settings.emplace_back("overrides", cat.sets.empty() ? "none" : fmt::format("{}", fmt::join(cat.sets, "; ")));
  settings.emplace_back("suspension", cat.suspension.empty() ? "from the model" : cat.suspension);
  settings.emplace_back("criteria", criteria ? criteria->name + " (" + criteria->source + ")" : "none");
  report::RunContext ctx;
  ctx.provenance = run_provenance(std::move(settings));
  ctx.model = model + (cat.suspension.empty() ? "" : ", suspension " + cat.suspension);
  if (!cat.suspension.empty()) ctx.suspension = network::resolve(cat.suspension, parse_params(cat.params));
  ctx.line = line.describe();
  ctx.kmh = cat.unit == "kmh";
  if (criteria) ctx.criteria = criteria, ctx.verdict = verdict;
  return ctx;
}

void write_report(const std::string& path, const std::string& html) {
  io::OutputFile f(path);
  std::fputs(html.c_str(), f.get());
  f.commit();
  fmt::print("wrote {} (the report; `inerta verify-report {}` re-runs it)\n", path, path);
}

CLI::App* add_verify_report_command(CLI::App& app) {
  VerifyArgs& a = verify_args;
  verify_cmd = app.add_subcommand("verify-report",
                                  "Re-run the command of a report (--report) and say whether every reported number is reproduced");
  verify_cmd->add_option("report", a.file, "The report (HTML) to verify")->required();
  verify_cmd->add_option("--rtol", a.rtol, "Numbers equal within this relative difference (default 0: exactly)")
      ->check(CLI::Validator(
          [](std::string& s) {
            double x = NAN;
            return CLI::detail::lexical_cast(s, x) && x >= 0 && x <= 1 ? std::string()
                                                                        : "a relative difference in [0, 1], got '" + s + "'";
          },
          "X in [0, 1]"));
  verify_cmd->add_flag("--keep", a.keep, "Keep the re-run's folder (its report, CSV and log) and print where it is");
  return verify_cmd;
}

namespace {
// The options whose value is an output the re-run must write elsewhere.
bool output_option(const std::string& a) { return a == "--out" || a == "--report" || a == "--table"; }

std::string tail(const std::string& path, std::size_t lines) {
  std::ifstream in(path);
  std::vector<std::string> all;
  for (std::string l; std::getline(in, l);) all.push_back(l);
  std::string out;
  for (std::size_t i = all.size() > lines ? all.size() - lines : 0; i < all.size(); ++i) out += "  " + all[i] + "\n";
  return out;
}
}  // namespace

int run_verify_report() {
  const VerifyArgs& a = verify_args;
  const std::string text = io::read_input_text(a.file, "report");
  const report::Record reported = report::read_record(text, a.file);
  const report::Provenance& p = reported.provenance;
  const report::BuildInfo& now = report::build_info();
  fmt::print("report: {} — {} of {}, {} numbers{}\n", a.file, reported.command, p.date, reported.numbers.size(),
             reported.verdict.empty() ? "" : ", verdict " + reported.verdict);
  fmt::print("  written by inerta {} (commit {}{}); this is inerta {} (commit {}{})\n", p.build.version, p.build.commit,
             p.build.modified ? ", modified" : "", now.version, now.commit, now.modified ? ", modified" : "");
  std::error_code ec;
  if (!fs::is_directory(p.cwd, ec))
    throw ModelError(fmt::format("{}: the report ran in '{}', which does not exist here", a.file, p.cwd));
  const fs::path report_abs = fs::absolute(a.file);
  fs::current_path(p.cwd);
  // the inputs as they are now
  int changed = 0;
  for (const auto& f : p.inputs) {
    std::string sha;
    try {
      sha = report::sha256_hex(io::read_input_text(f.path, f.what));
    } catch (const std::exception&) {
      fmt::print("  input {} ({}): missing now\n", f.path, f.what), ++changed;
      continue;
    }
    if (sha != f.sha256) fmt::print("  input {} ({}): changed since the report (SHA-256 {} → {})\n", f.path, f.what, f.sha256.substr(0, 12), sha.substr(0, 12)), ++changed;
  }
  if (changed == 0) fmt::print("  {} input file(s) unchanged (SHA-256)\n", p.inputs.size());
  // re-run in a folder of its own
  const fs::path dir = fs::temp_directory_path() / fmt::format("inerta_verify_{}_{}", ::getpid(), std::rand());
  fs::create_directories(dir);
  std::vector<std::string> args = p.argv;
  std::string new_report;
  for (std::size_t i = 1; i < args.size(); ++i) {
    std::string& x = args[i];
    for (const char* opt : {"--out", "--report", "--table"}) {
      const std::string eq = std::string(opt) + "=";
      if (x.starts_with(eq)) {
        const std::string name = (dir / (std::string(opt + 2) + fs::path(x.substr(eq.size())).extension().string())).string();
        x = eq + name;
        if (std::string(opt) == "--report") new_report = name;
      }
    }
    if (output_option(x) && i + 1 < args.size()) {
      const std::string opt = x.substr(2);
      std::string& v = args[i + 1];
      const std::string name = (dir / (opt + (reported.command == "optimise" ? std::string() : fs::path(v).extension().string()))).string();
      if (opt == "report") new_report = name;
      v = name;
      ++i;
    }
  }
  if (reported.command == "optimise") {  // a study's report is DIR/report.html of its --out DIR
    for (std::size_t i = 1; i + 1 < args.size(); ++i)
      if (args[i] == "--out") new_report = (fs::path(args[i + 1]) / "report.html").string();
  }
  if (new_report.empty()) throw ModelError(fmt::format("{}: its command line has no --report: cannot re-run it", a.file));
  args[0] = "/proc/self/exe";
  std::vector<char*> cargv;
  for (auto& s : args) cargv.push_back(s.data());
  cargv.push_back(nullptr);
  const std::string log = (dir / "rerun.log").string();
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&fa, 1, 2);
  char self[4096];
  const ssize_t n = ::readlink("/proc/self/exe", self, sizeof self - 1);
  if (n <= 0) throw std::runtime_error("cannot find this program (/proc/self/exe)");
  self[n] = 0;
  cargv[0] = self;
  fmt::print("  re-running: {}\n", report::shell_quoted(p.argv));
  std::fflush(stdout);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, self, &fa, nullptr, cargv.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  if (rc != 0) throw std::runtime_error(fmt::format("cannot start {}: {}", self, std::strerror(rc)));
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  if (!fs::exists(new_report)) {
    fmt::print(stderr, "error: the re-run (exit {}) wrote no report; its last lines:\n{}", code, tail(log, 15));
    if (!a.keep) fs::remove_all(dir, ec);
    return 1;
  }
  const report::Record again = report::read_record(io::read_input_text(new_report, "re-run's report"), new_report);
  const auto diff = report::compare(reported, again, a.rtol);
  if (a.keep) fmt::print("  the re-run's files: {}\n", dir.string());
  else fs::remove_all(dir, ec);
  if (diff.empty() && reported.verdict == again.verdict) {
    fmt::print("reproduced: all {} numbers equal{}{}\n", reported.numbers.size(),
               a.rtol > 0 ? fmt::format(" (within {:g} relative)", a.rtol) : std::string(" (exactly)"),
               reported.verdict.empty() ? "" : ", verdict " + again.verdict);
    return 0;
  }
  fmt::print("NOT reproduced: {} of {} numbers differ{}\n", diff.size(), reported.numbers.size(),
             reported.verdict == again.verdict ? "" : fmt::format("; verdict {} → {}", reported.verdict, again.verdict));
  std::size_t shown = 0;
  for (const auto& d : diff) {
    if (shown++ == 30) {
      fmt::print("  … and {} more\n", diff.size() - 30);
      break;
    }
    if (!d.missing.empty())
      fmt::print("  {}: {}\n", d.key, d.missing);
    else
      fmt::print("  {}: reported {:.17g}, now {:.17g} (difference {:.3g}, {:.3g} relative)\n", d.key, d.reported, d.now,
                 d.now - d.reported, std::abs(d.now - d.reported) / std::max(std::abs(d.reported), 1e-300));
  }
  (void)report_abs;
  return 7;
}

}  // namespace inerta::cli
