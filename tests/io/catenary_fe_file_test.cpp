// Finite-element catenary files (type: finite_element, docs/model-format.md#finite-element-catenary):
// the bundled benchmark-type line, overrides, and every documented error with its file:line and key.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "inerta/error.hpp"
#include "inerta/io/catenary_file.hpp"
#include "inerta/io/file_kind.hpp"
#include "support/run.hpp"
#include "support/temp.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_io_catenary_fe_file {

using namespace inerta;

namespace {

// A small valid file; the line numbers are those of the comments.
const std::string kLine =
    "type: finite_element\n"                                     // 1
    "line: {span: 50, spans: 4, encumbrance: 1.1}\n"             // 2
    "messenger: {tension: 16000, mass_per_length: 1.08}\n"       // 3
    "contact_wire:\n"                                            // 4
    "  tension: 22000\n"                                         // 5
    "  mass_per_length: 1.35\n"                                  // 6
    "  EI: 195\n"                                                // 7
    "droppers:\n"                                                // 8
    "  x: [10, 25, 40]\n"                                        // 9
    "  presag: [0.01, 0.03, 0.01]\n"                             // 10
    "  EA: 200000\n"                                             // 11
    "supports: {stiffness: 500000}\n"                            // 12
    "registration: {stiffness: 2500}\n";                         // 13

std::string write(const std::string& text) {
  const std::string path = (inerta::testing::temp_dir() / "inerta_fe_catenary.yaml").string();
  std::ofstream(path) << text;
  return path;
}

// The message of reading `text` (with overrides), or "" if it reads.
std::string error_of(const std::string& text, const std::vector<std::string>& sets = {}) {
  try {
    io::read_catenary_file(write(text), sets);
  } catch (const ModelError& e) {
    return e.what();
  }
  return "";
}

std::string replace(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

}  // namespace

TEST(FeCatenaryFile, TheBundledLineHoldsTheBenchmarkTypeData) {
  const std::string path = inerta::testing::model_path("catenary-fe.yaml");
  EXPECT_EQ(io::file_kind(path), io::FileKind::Catenary);
  const catenary::FeCatenaryData d = io::read_fe_catenary_data(path);
  EXPECT_EQ(d.span, 55);
  EXPECT_EQ(d.spans, 10);
  EXPECT_EQ(d.encumbrance, 1.2);
  EXPECT_EQ(d.dropper_x, (std::vector<double>{4.5, 10.25, 16.0, 21.75, 27.5, 33.25, 39.0, 44.75, 50.5}));
  EXPECT_EQ(d.presag, (std::vector<double>{0, 0.024, 0.041, 0.052, 0.055, 0.052, 0.041, 0.024, 0}));
  EXPECT_EQ(d.nominal_dropper_length,
            (std::vector<double>{1.017, 0.896, 0.810, 0.758, 0.741, 0.758, 0.810, 0.896, 1.017}));
  EXPECT_EQ(d.messenger.tension, 16000);
  EXPECT_EQ(d.messenger.mass_per_length, 1.08);
  EXPECT_EQ(d.messenger.EI, 131.7);
  EXPECT_EQ(d.contact_wire.tension, 22000);
  EXPECT_EQ(d.contact_wire.mass_per_length, 1.35);
  EXPECT_EQ(d.contact_wire.EI, 195);
  EXPECT_EQ(d.dropper_EA, 200000);
  EXPECT_EQ(d.dropper_mass_per_length, 0.117);
  EXPECT_EQ(d.clamp_mass_messenger, 0.195);
  EXPECT_EQ(d.clamp_mass_contact, 0.165);
  EXPECT_EQ(d.support_stiffness, 500000);
  EXPECT_EQ(d.registration_stiffness, 2673.58);
  EXPECT_EQ(d.element_length, 0.25);
  EXPECT_EQ(d.rayleigh_mass, 0.0125);
  EXPECT_EQ(d.rayleigh_stiffness, 1e-4);
  EXPECT_EQ(d.time_step, 1e-3);
  EXPECT_EQ(d.hht_alpha, 0);
  EXPECT_EQ(d.section_first, -1);  // the default section
  const io::CatenaryFile f = io::read_catenary_file(path);
  EXPECT_EQ(f.catenary, nullptr);  // not made by read_catenary_file
  EXPECT_EQ(f.contact.kind, catenary::Contact::Kind::Penalty);
  EXPECT_EQ(f.contact.stiffness, 50000);
  EXPECT_EQ(f.name, "benchmark-type simple catenary (10 spans of 55 m)");
  // Wave speeds sqrt(T/ρA): 127.7 m/s on the contact wire, 121.7 m/s on the messenger.
  EXPECT_NEAR(d.contact_wire.wave_speed(), 127.6569, 1e-4);
  EXPECT_NEAR(d.messenger.wave_speed(), 121.7161, 1e-4);
}

TEST(FeCatenaryFile, OptionalKeysTakeTheirDocumentedDefaults) {
  const catenary::FeCatenaryData d = io::read_fe_catenary_data(write(kLine));
  EXPECT_EQ(d.messenger.EI, 0);  // not given
  EXPECT_EQ(d.contact_wire.EI, 195);
  EXPECT_EQ(d.dropper_mass_per_length, 0);
  EXPECT_EQ(d.clamp_mass_messenger, 0);
  EXPECT_EQ(d.clamp_mass_contact, 0);
  EXPECT_EQ(d.support_mass, 0);
  EXPECT_EQ(d.registration_mass, 0);
  EXPECT_TRUE(d.nominal_dropper_length.empty());
  EXPECT_EQ(d.gravity, 9.81);
  EXPECT_EQ(d.element_length, 0.25);
  EXPECT_EQ(d.rayleigh_mass, 0.0125);
  EXPECT_EQ(d.rayleigh_stiffness, 1e-4);
  EXPECT_EQ(d.time_step, 1e-3);
  EXPECT_EQ(d.hht_alpha, 0);
  const io::CatenaryFile f = io::read_catenary_file(write(kLine));
  EXPECT_EQ(f.contact.kind, catenary::Contact::Kind::Penalty);  // no contact section: penalty 50 kN/m
  EXPECT_EQ(f.contact.stiffness, 50e3);
  EXPECT_EQ(f.contact.damping, 0);
  const io::CatenaryFile g = io::read_catenary_file(
      write(kLine + "contact: {stiffness: 80000, damping: 10}\nsection: {spans: [2, 3]}\nintegration: {alpha: -0.1}\n"));
  EXPECT_EQ(g.contact.kind, catenary::Contact::Kind::Penalty);
  EXPECT_EQ(g.contact.stiffness, 80000);
  EXPECT_EQ(g.contact.damping, 10);
  EXPECT_EQ(g.fe->section_first, 2);
  EXPECT_EQ(g.fe->section_last, 3);
  EXPECT_EQ(g.fe->hht_alpha, -0.1);
}

TEST(FeCatenaryFile, OverridesSetANumberBySectionAndKey) {
  const catenary::FeCatenaryData d = io::read_fe_catenary_data(
      write(kLine), {"messenger.tension=17000", "droppers.EA=1.5e5", "damping.rayleigh_mass=0",
                     "integration.time_step=2.5e-4", "mesh.element_length=0.125", "droppers.presag[1]=0.04",
                     "line.spans=6", "section.spans=2:5", "contact_wire.EI=150", "supports.mass=2"});
  EXPECT_EQ(d.messenger.tension, 17000);
  EXPECT_EQ(d.contact_wire.tension, 22000);
  EXPECT_EQ(d.dropper_EA, 1.5e5);
  EXPECT_EQ(d.rayleigh_mass, 0);
  EXPECT_EQ(d.time_step, 2.5e-4);
  EXPECT_EQ(d.element_length, 0.125);
  EXPECT_EQ(d.presag[1], 0.04);
  EXPECT_EQ(d.spans, 6);
  EXPECT_EQ(d.section_first, 2);
  EXPECT_EQ(d.section_last, 5);
  EXPECT_EQ(d.contact_wire.EI, 150);
  EXPECT_EQ(d.support_mass, 2);
  const io::CatenaryFile f = io::read_catenary_file(write(kLine), {"contact.stiffness=1e5", "contact.type=penalty"});
  EXPECT_EQ(f.contact.stiffness, 1e5);
}

TEST(FeCatenaryFile, ABadOverrideNamesItself) {
  auto expect = [](const std::vector<std::string>& sets, const std::string& part) {
    const std::string msg = error_of(kLine, sets);
    EXPECT_NE(msg.find(part), std::string::npos) << msg;
  };
  expect({"messenger.tensoin=1"}, "--set 'messenger.tensoin=1': unknown key; expected line.span, line.spans");
  expect({"catenary.kc0=5000"}, "--set 'catenary.kc0=5000': unknown key");  // a lumped key
  expect({"fe.span=50"}, "--set 'fe.span=50': unknown key");
  expect({"messenger.tension=much"}, "--set 'messenger.tension=much': 'much' is not a number");
  expect({"line.spans=2.5"}, "--set 'line.spans=2.5': expected a whole number");
  expect({"droppers.x[3]=45"}, "--set 'droppers.x[3]=45': droppers.x has 3 value(s), index 0 to 2");
  expect({"section.spans=3"}, "expected section.spans=FIRST:LAST");
  expect({"messenger.tension=-5"}, "--set 'messenger.tension=-5': finite-element catenary: messenger: tension: must be > 0 (N), got -5");
  expect({"section.spans=2:9"}, "--set 'section.spans=2:9': finite-element catenary: section: spans: must be [first, last]");
  expect({"contact.type=bilateral"}, "--set 'contact.type=bilateral': the finite-element catenary takes a penalty contact");
  expect({"messenger.tension"}, "expected section.key=value");
}

TEST(FeCatenaryFile, EveryErrorNamesTheFileLineAndKey) {
  const std::string path = write("");
  auto expect = [&](const std::string& text, const std::string& part) {
    const std::string msg = error_of(text);
    EXPECT_NE(msg.find(path + part), std::string::npos) << "message: " << msg << "\nfile:\n" << text;
  };
  EXPECT_EQ(error_of(kLine), "");
  // unknown keys: top level, in a section
  expect(kLine + "stitch_wire: {tension: 2800}\n", ":14: 'stitch_wire': unknown key in a finite-element catenary file");
  expect(replace(kLine, "  EI: 195\n", "  EJ: 195\n"),
         ":7: 'EJ': unknown key in contact_wire; expected one of: tension, mass_per_length, EI");
  expect(kLine + "mesh: {elements: 3}\n", ":14: 'elements': unknown key in mesh; expected one of: element_length");
  expect(kLine + "damping: {mass: 0.1}\n", ":14: 'mass': unknown key in damping; expected one of: rayleigh_mass, rayleigh_stiffness");
  // duplicate keys, at the top level and in a section
  expect(kLine + "supports: {stiffness: 1}\n", ":14: 'supports': duplicate key at the top level");
  expect(replace(kLine, "  EI: 195\n", "  EI: 195\n  EI: 196\n"), ":8: 'EI': duplicate key in contact_wire");
  // missing sections and keys
  expect(replace(kLine, "registration: {stiffness: 2500}\n", ""), ":1: 'registration': missing in a finite-element catenary file");
  expect(replace(kLine, "  tension: 22000\n", ""), ":5: 'tension': missing in contact_wire; expected a number (N)");
  expect(replace(kLine, "  EA: 200000\n", ""), ":9: 'EA': missing in droppers");
  expect(replace(kLine, "  presag: [0.01, 0.03, 0.01]\n", ""), ":9: 'presag': missing in droppers");
  expect(replace(kLine, "spans: 4, ", ""), ":2: 'spans': missing in line");
  // wrong types
  expect(replace(kLine, "tension: 16000", "tension: [16000]"), ":3: 'tension': expected a number");
  expect(replace(kLine, "tension: 22000", "tension: strong"), ":5: 'tension': expected a number, got 'strong'");
  expect(replace(kLine, "spans: 4", "spans: 4.5"), ":2: 'spans': expected a whole number, got 4.5");
  expect(replace(kLine, "x: [10, 25, 40]", "x: 10"), ":9: 'x': expected a list of numbers (m)");
  expect(kLine + "section: {spans: 3}\n", ":14: 'spans': expected [first, last]");
  expect(replace(kLine, "messenger: {tension: 16000, mass_per_length: 1.08}", "messenger: 16000"),
         ":3: 'messenger': expected a mapping");
  // the contact: penalty only
  expect(kLine + "contact: {type: bilateral}\n", ":14: 'type': the finite-element catenary takes a penalty contact");
  expect(kLine + "contact: {kind: penalty}\n", ":14: 'kind': unknown key in contact");
  // values FeCatenaryData::validate refuses, at the line of their key (the messenger's tension, not the contact wire's)
  expect(replace(kLine, "tension: 16000", "tension: -16000"), ":3: 'tension': must be > 0 (N), got -16000 in messenger");
  expect(replace(kLine, "tension: 22000", "tension: .nan"), ":5: 'tension': must be > 0 (N), got nan in contact_wire");
  expect(replace(kLine, "presag: [0.01, 0.03, 0.01]", "presag: [0.01, 0.03]"), ":10: 'presag': needs one value per dropper (3), got 2");
  // Issue 38: a NaN nominal length was accepted.
  expect(replace(kLine, "presag: [0.01, 0.03, 0.01]\n", "presag: [0.01, 0.03, 0.01]\n  nominal_length: [.nan, 1, 1]\n"),
         ":11: 'nominal_length[0]': must be a finite length > 0 (m), got nan");
  expect(replace(kLine, "presag: [0.01, 0.03, 0.01]", "presag: [0.01, 2, 0.01]"), ":10: 'presag[1]': must be finite and smaller than the encumbrance");
  expect(replace(kLine, "  x: [10, 25, 40]\n", "  x:\n    - 10\n    - 60\n    - 40\n"), ":11: 'x[1]': must increase strictly inside (0, span = 50 m)");
  expect(replace(kLine, "  EA: 200000\n", "  EA: 200000\n  nominal_length: [1]\n"), ":12: 'nominal_length': needs one value per dropper");
  expect(replace(kLine, "spans: 4", "spans: 0"), ":2: 'spans': must be >= 1, got 0 in line");
  expect(replace(kLine, "encumbrance: 1.1", "encumbrance: -1"), ":2: 'encumbrance': must be > 0 (m), got -1 in line");
  expect(replace(kLine, "supports: {stiffness: 500000}", "supports: {stiffness: 0}"), ":12: 'stiffness': must be > 0 (N/m), got 0 in supports");
  expect(replace(kLine, "registration: {stiffness: 2500}", "registration: {stiffness: 2500, mass: -1}"), ":13: 'mass': must be >= 0 (kg), got -1 in registration");
  expect(kLine + "damping: {rayleigh_mass: -0.1}\n", ":14: 'rayleigh_mass': must be >= 0 (1/s), got -0.1 in damping");
  expect(kLine + "damping: {rayleigh_stiffness: .inf}\n", ":14: 'rayleigh_stiffness': must be >= 0 (s), got inf in damping");
  expect(kLine + "integration: {time_step: 0.05}\n", ":14: 'time_step': must be <= 0.01 (s), got 0.05 in integration; a wire carries waves");
  expect(kLine + "integration: {alpha: -0.5}\n", ":14: 'alpha': must be >= -0.333333, got -0.5 in integration");
  expect(kLine + "mesh: {element_length: 0}\n", ":14: 'element_length': must be >= 0.001 (m), got 0 in mesh");
  expect(kLine + "section: {spans: [3, 6]}\n", ":14: 'spans': must be [first, last] with 1 <= first <= last <= 4, got [3, 6] in section");
  expect(replace(kLine, "type: finite_element", "type: finite_elements"), ":1: 'type': expected lumped");
}

TEST(FeCatenaryFile, OtherTypesKeepTheirFormatAndPointAtTheFiniteElementType) {
  const std::string lumped = inerta::testing::model_path("catenary.yaml");
  try {
    io::read_fe_catenary_data(lumped);
    FAIL();
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("not a finite-element catenary file"), std::string::npos) << e.what();
  }
  EXPECT_NE(io::read_catenary_file(lumped).catenary, nullptr);
  EXPECT_FALSE(io::read_catenary_file(lumped).fe.has_value());
  // Finite-element sections without the type.
  const std::string msg = error_of(replace(kLine, "type: finite_element\n", ""));
  EXPECT_NE(msg.find(":1: 'line': unknown key; expected name, type, catenary, contact (a finite-element catenary needs "
                     "type: finite_element)"),
            std::string::npos)
      << msg;
  const std::string dup = error_of("catenary: {span: 60, kc: [1, 0, 0, 0], mc: [1, 0, 0, 0], cc: [0, 0, 0, 0]}\n"
                                   "name: a\nname: b\n");
  EXPECT_NE(dup.find(":3: 'name': duplicate key"), std::string::npos) << dup;
}

TEST(FeCatenaryFile, SolverSectionAndItsErrors) {
  // Without `solver` the direct solve (older files keep their results); the bundled line is modal.
  EXPECT_EQ(io::read_fe_catenary_data(write(kLine)).solver, catenary::FeCatenaryData::Solver::Direct);
  const catenary::FeCatenaryData b = io::read_fe_catenary_data(inerta::testing::model_path("catenary-fe.yaml"));
  EXPECT_EQ(b.solver, catenary::FeCatenaryData::Solver::Modal);
  EXPECT_EQ(b.modal_cutoff, 100);
  EXPECT_EQ(b.window_behind, 2);
  EXPECT_EQ(b.window_ahead, 3);
  const catenary::FeCatenaryData m =
      io::read_fe_catenary_data(write(kLine + "solver: {type: modal, cutoff: 80, window_behind: -1, window_ahead: 1}\n"));
  EXPECT_EQ(m.solver, catenary::FeCatenaryData::Solver::Modal);
  EXPECT_EQ(m.modal_cutoff, 80);
  EXPECT_EQ(m.window_behind, -1);
  EXPECT_EQ(m.window_ahead, 1);
  EXPECT_EQ(io::read_fe_catenary_data(write(kLine + "solver: modal\n")).solver, catenary::FeCatenaryData::Solver::Modal);
  EXPECT_EQ(io::read_fe_catenary_data(write(kLine + "solver: modal\n"), {"solver.type=direct"}).solver,
            catenary::FeCatenaryData::Solver::Direct);
  // Errors at their line, naming the key.
  std::string e = error_of(kLine + "solver: {type: fast}\n");
  EXPECT_NE(e.find(":14:"), std::string::npos) << e;
  EXPECT_NE(e.find("expected modal or direct, got 'fast'"), std::string::npos) << e;
  e = error_of(kLine + "solver: quick\n");
  EXPECT_NE(e.find("'solver'"), std::string::npos) << e;
  e = error_of(kLine + "solver: {cutoff: 0}\n");
  EXPECT_NE(e.find("cutoff"), std::string::npos) << e;
  e = error_of(kLine + "solver: {window_ahead: 1.5}\n");
  EXPECT_NE(e.find("whole number"), std::string::npos) << e;
  e = error_of(kLine + "solver: {window_behind: -3}\n");
  EXPECT_NE(e.find("window_behind"), std::string::npos) << e;
  e = error_of(kLine + "solver: {windows: 3}\n");
  EXPECT_NE(e.find("windows"), std::string::npos) << e;
  // Override numbers are decimal and the whole text (issue 38: std::stod took 0x10 as 16 and " 5" as 5).
  for (const std::string bad : {"solver.cutoff=0x10", "messenger.tension= 17000", "messenger.tension=17000 ", "solver.cutoff=1e2x"}) {
    e = error_of(kLine + "solver: modal\n", {bad});
    EXPECT_NE(e.find("is not a number"), std::string::npos) << bad << ": " << e;
  }
  EXPECT_EQ(io::read_fe_catenary_data(write(kLine + "solver: modal\n"), {"solver.cutoff=+80"}).modal_cutoff, 80);
  // A structural step of 1e-7 s ended in the pantograph integrator's "the model is stiff" (issue 38).
  e = error_of(kLine, {"integration.time_step=1e-7"});
  EXPECT_NE(e.find("must be >= 1e-05 (s), got 1e-07"), std::string::npos) << e;
  // A solver section without its type (issue 38): not the direct solve in silence.
  e = error_of(kLine + "solver: {cutoff: 80}\n");
  EXPECT_NE(e.find(":14:"), std::string::npos) << e;
  EXPECT_NE(e.find("'type': missing in solver; expected modal or direct"), std::string::npos) << e;
  e = error_of(kLine, {"solver.type=quick"});
  EXPECT_NE(e.find("expected solver.type=modal or direct"), std::string::npos) << e;
  e = error_of(kLine, {"solver.cutoff=-5"});
  EXPECT_NE(e.find("cutoff"), std::string::npos) << e;
}
}  // namespace test_io_catenary_fe_file

namespace test_io_catenary_fe_file {

// Issue 52: what docs/model-format.md says of a line of tension sections — a section's `stitch:` key by
// key over the line's, and the file's analysis `section:` over the whole line (as --set's).
TEST(FeCatenaryFile, ASectionsStitchIsTakenKeyByKeyAndTheAnalysisSectionIsTheLines) {
  const std::string src = std::string(INERTA_SOURCE_DIR) + "/models/catenary-fe-overlap.yaml";
  std::ifstream in(src);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string second = "  - {spans: 13, anchors: pinned}";
  ASSERT_NE(text.find(second), std::string::npos);
  text.replace(text.find(second), second.size(), "  - {spans: 13, anchors: pinned, stitch: {tension: 4000, droppers: {EA: 1.0e5}}}");
  text.replace(text.find("\nline:"), 6, "\nsection: {spans: [14, 18]}\nline:");
  const catenary::FeCatenaryData d = io::read_fe_catenary_data(write(text), {});
  ASSERT_EQ(d.tension_sections.size(), 3u);
  const catenary::FeStitch &line = d.tension_sections[0].stitch, &mine = d.tension_sections[1].stitch;
  EXPECT_EQ(mine.wire.tension, 4000);
  EXPECT_EQ(mine.dropper_EA, 1.0e5);
  EXPECT_EQ(mine.length, line.length);  // the line's other keys kept
  EXPECT_EQ(mine.wire.mass_per_length, line.wire.mass_per_length);
  EXPECT_EQ(mine.dropper_x, line.dropper_x);
  EXPECT_EQ(line.wire.tension, 3500);
  EXPECT_EQ(d.section_first, 14);
  EXPECT_EQ(d.section_last, 18);
  // stitch: null leaves a section without stitch wires.
  const std::string mine_text = "stitch: {tension: 4000, droppers: {EA: 1.0e5}}";
  text.replace(text.find(mine_text), mine_text.size(), "stitch: null");
  EXPECT_FALSE(io::read_fe_catenary_data(write(text), {}).tension_sections[1].stitch.present);
}

}  // namespace test_io_catenary_fe_file
