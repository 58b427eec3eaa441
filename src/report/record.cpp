// The numbers record of a report (report/record.hpp).
#include "inerta/report/record.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <map>
#include <nlohmann/json.hpp>

#include "inerta/error.hpp"

namespace inerta::report {

namespace {
using nlohmann::json;

json number(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  return v;
}
double number(const json& j) {
  if (j.is_number()) return j.get<double>();
  if (j.is_string()) {
    const std::string s = j.get<std::string>();
    if (s == "nan") return NAN;
    if (s == "inf") return INFINITY;
    if (s == "-inf") return -INFINITY;
  }
  throw std::runtime_error("a number");
}
constexpr const char* kOpen = "<script type=\"application/json\" id=\"inerta-record\">";
constexpr const char* kFormat = "inerta-report 1";
}  // namespace

std::string record_json(const Record& r) {
  json j;
  j["format"] = kFormat;
  j["command"] = r.command;
  j["verdict"] = r.verdict;
  const Provenance& p = r.provenance;
  j["program"] = {{"version", p.build.version}, {"commit", p.build.commit}, {"modified", p.build.modified}};
  j["argv"] = p.argv;
  j["cwd"] = p.cwd;
  j["date"] = p.date;
  json in = json::array();
  for (const auto& f : p.inputs) in.push_back({{"path", f.path}, {"what", f.what}, {"sha256", f.sha256}, {"bytes", f.bytes}});
  j["inputs"] = in;
  json s = json::array();
  for (const auto& [k, v] : p.settings) s.push_back({k, v});
  j["settings"] = s;
  json n = json::array();
  for (const auto& [k, v] : r.numbers) n.push_back({k, number(v)});
  j["numbers"] = n;
  std::string text = j.dump(1);  // doubles round-trip (nlohmann writes 17 significant digits where needed)
  for (std::size_t at = 0; (at = text.find("</", at)) != std::string::npos; at += 3) text.replace(at, 2, "<\\/");
  return text;
}

Record read_record(const std::string& html, const std::string& file) {
  const auto open = html.find(kOpen);
  if (open == std::string::npos)
    throw ModelError(fmt::format("{}: not an Inerta report (no inerta-record block; reports are written by --report)", file));
  const auto from = open + std::string(kOpen).size();
  const auto close = html.find("</script>", from);
  if (close == std::string::npos) throw ModelError(fmt::format("{}: the inerta-record block is not closed: a damaged report", file));
  Record r;
  try {
    const json j = json::parse(html.substr(from, close - from));
    if (j.at("format") != kFormat)
      throw ModelError(fmt::format("{}: report format '{}', this program reads '{}'", file, j.at("format").dump(), kFormat));
    r.command = j.at("command").get<std::string>();
    r.verdict = j.at("verdict").get<std::string>();
    Provenance& p = r.provenance;
    p.build.version = j.at("program").at("version").get<std::string>();
    p.build.commit = j.at("program").at("commit").get<std::string>();
    p.build.modified = j.at("program").at("modified").get<bool>();
    p.argv = j.at("argv").get<std::vector<std::string>>();
    p.cwd = j.at("cwd").get<std::string>();
    p.date = j.at("date").get<std::string>();
    for (const auto& f : j.at("inputs"))
      p.inputs.push_back({f.at("path").get<std::string>(), f.at("what").get<std::string>(), f.at("sha256").get<std::string>(),
                          f.at("bytes").get<std::size_t>()});
    for (const auto& s : j.at("settings")) p.settings.emplace_back(s.at(0).get<std::string>(), s.at(1).get<std::string>());
    for (const auto& n : j.at("numbers")) r.numbers.emplace_back(n.at(0).get<std::string>(), number(n.at(1)));
  } catch (const ModelError&) {
    throw;
  } catch (const std::exception& e) {
    throw ModelError(fmt::format("{}: the inerta-record block is damaged ({})", file, e.what()));
  }
  if (r.provenance.argv.size() < 2) throw ModelError(fmt::format("{}: the record holds no command line", file));
  return r;
}

std::vector<Difference> compare(const Record& a, const Record& b, double rtol) {
  std::map<std::string, double> now;
  for (const auto& [k, v] : b.numbers) now.emplace(k, v);
  std::vector<Difference> out;
  std::map<std::string, bool> seen;
  for (const auto& [k, v] : a.numbers) {
    seen[k] = true;
    const auto it = now.find(k);
    if (it == now.end()) {
      out.push_back({k, v, NAN, "not in the re-run"});
      continue;
    }
    const double w = it->second;
    const bool same = (std::isnan(v) && std::isnan(w)) || v == w ||
                      (std::isfinite(v) && std::isfinite(w) && std::abs(v - w) <= rtol * std::max(std::abs(v), std::abs(w)));
    if (!same) out.push_back({k, v, w, ""});
  }
  for (const auto& [k, w] : b.numbers)
    if (!seen.count(k)) out.push_back({k, NAN, w, "not in the report"});
  return out;
}

}  // namespace inerta::report
