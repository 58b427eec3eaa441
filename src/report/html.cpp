// The HTML report document (report/html.hpp).
#include "inerta/report/html.hpp"

#include <fmt/format.h>

#include <cstdlib>

namespace inerta::report {

std::string escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  return out;
}

namespace {
constexpr const char* kStyle = R"(
body { font-family: sans-serif; margin: 24px auto; max-width: 980px; color: #222; }
h1 { font-size: 22px; margin-bottom: 4px; }
h2 { font-size: 17px; margin-top: 28px; border-bottom: 1px solid #ccc; }
.verdict { font-size: 20px; padding: 12px 16px; border-radius: 6px; margin: 12px 0; }
.verdict .status { font-size: 30px; font-weight: bold; letter-spacing: 1px; }
.verdict.PASS { background: #e3f4e5; border: 2px solid #2e8b3e; }
.verdict.FAIL { background: #fbe3e3; border: 2px solid #c0392b; }
.verdict.NA { background: #f4f0de; border: 2px solid #b08d1a; }
.verdict p { font-size: 14px; margin: 4px 0; }
table { border-collapse: collapse; font-size: 13px; margin: 8px 0; }
th, td { border: 1px solid #ccc; padding: 3px 7px; text-align: right; }
th { background: #f0f0f0; }
td.text, th.text { text-align: left; }
tr.fail td { background: #fbe3e3; }
tr.na td { color: #888; }
figure { margin: 10px 0; }
figcaption { font-size: 12px; color: #555; }
code { font-size: 12px; word-break: break-all; }
)";

bool numeric(const std::string& s) {
  if (s.empty()) return false;
  char* end = nullptr;
  std::strtod(s.c_str(), &end);
  return end != s.c_str();
}
}  // namespace

Document::Document(std::string title) : title_(std::move(title)) {}

void Document::verdict(const std::string& status, const std::vector<std::string>& lines) {
  const std::string cls = status == "PASS" ? "PASS" : status == "FAIL" ? "FAIL" : "NA";
  banner_ = fmt::format("<div class=\"verdict {}\" id=\"verdict\"><span class=\"status\">{}</span>\n", cls, escape(status));
  for (const auto& l : lines) banner_ += fmt::format("<p>{}</p>\n", escape(l));
  banner_ += "</div>\n";
}

void Document::heading(const std::string& text) { body_ += fmt::format("<h2>{}</h2>\n", escape(text)); }

void Document::paragraph(const std::string& text) { body_ += fmt::format("<p>{}</p>\n", escape(text)); }

void Document::table(const Table& t) {
  body_ += t.id.empty() ? "<table>\n<tr>" : fmt::format("<table id=\"{}\">\n<tr>", escape(t.id));
  for (const auto& h : t.header) body_ += fmt::format("<th>{}</th>", escape(h));
  body_ += "</tr>\n";
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    const std::string cls = i < t.row_class.size() ? t.row_class[i] : "";
    body_ += cls.empty() ? "<tr>" : fmt::format("<tr class=\"{}\">", cls);
    for (const auto& c : t.rows[i]) body_ += numeric(c) ? "<td>" + escape(c) + "</td>" : "<td class=\"text\">" + escape(c) + "</td>";
    body_ += "</tr>\n";
  }
  body_ += "</table>\n";
}

void Document::figure(const std::string& svg, const std::string& caption) {
  body_ += fmt::format("<figure>\n{}<figcaption>{}</figcaption>\n</figure>\n", svg, escape(caption));
}

void Document::provenance(const Provenance& p) {
  heading("Provenance");
  Table t;
  t.id = "provenance";
  t.header = {"item", "value"};
  t.rows.push_back({"program", fmt::format("inerta {} (commit {}{})", p.build.version, p.build.commit,
                                           p.build.modified ? ", the source tree was modified" : "")});
  t.rows.push_back({"command", shell_quoted(p.argv)});
  t.rows.push_back({"working folder", p.cwd});
  t.rows.push_back({"date (UTC)", p.date});
  for (const auto& [k, v] : p.settings) t.rows.push_back({k, v});
  table(t);
  Table in;
  in.id = "inputs";
  in.header = {"input", "path", "bytes", "SHA-256"};
  for (const auto& f : p.inputs) in.rows.push_back({f.what, f.path, std::to_string(f.bytes), f.sha256});
  if (!p.inputs.empty()) table(in);
  paragraph("Re-run and compare every number of this report: inerta verify-report FILE.html");
}

std::string Document::html(const Record& record) const {
  std::string json = record_json(record);
  return fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>{0}</title>\n<style>{1}</style>\n"
      "</head>\n<body>\n<h1>{0}</h1>\n{2}{3}"
      "<script type=\"application/json\" id=\"inerta-record\">\n{4}\n</script>\n</body>\n</html>\n",
      escape(title_), kStyle, banner_, body_, json);
}

}  // namespace inerta::report
