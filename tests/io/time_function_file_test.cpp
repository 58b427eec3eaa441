// Time functions in model files (src/io/model_time_functions.cpp, docs/model-format.md#time-functions):
// what each new type reads, and an error-path test for every key — "file:line: 'key': ..." at the
// line marked "# <-- here" — plus the angle and assembly warnings (model.notes).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "inerta/error.hpp"
#include "inerta/io/model_file.hpp"
#include "support/temp.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_io_time_function_file {

namespace {

using inerta::ModelError;
using inerta::io::parse_model;
using TF = inerta::mbs::TimeFunction;

constexpr const char* kSource = "tf.yaml";
constexpr const char* kMark = "# <-- here";

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

int marked_line(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  int n = 0, found = 0, count = 0;
  while (std::getline(in, line)) {
    ++n;
    if (contains(line, kMark)) found = n, ++count;
  }
  return count == 1 ? found : 0;
}

std::string model_error(const std::string& text, const std::string& source = kSource) {
  try {
    parse_model(text, source);
  } catch (const ModelError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected inerta::ModelError, got: " << e.what();
    return {};
  }
  ADD_FAILURE() << "expected inerta::ModelError, but the model loaded";
  return {};
}

void expect_error(const std::string& text, const std::string& key, const std::string& expected,
                  const std::string& source = kSource) {
  const int line = marked_line(text);
  ASSERT_GT(line, 0) << "test bug: mark exactly one line with '" << kMark << "'";
  const std::string msg = model_error(text, source);
  const std::string prefix = source + ":" + std::to_string(line) + ": '" + key + "': ";
  EXPECT_TRUE(contains(msg, prefix)) << "message: " << msg << "\nwanted:  " << prefix;
  EXPECT_TRUE(contains(msg, expected)) << "message: " << msg << "\nwanted:  " << expected;
}

// A slider on a vertical rail driven in y by `motion` (indented block text).
std::string driven(const std::string& motion) {
  return R"(name: tf
options: {gravity: false}
ground:
  markers: {P: [0, 0]}
bodies:
  - {name: s, mass: 1, inertia: 0.1, position: [0, 0]}
joints:
  - {name: rail, type: prismatic, markers: [ground.P, s.cm], axis: [0, 1]}
  - name: drive
    type: driving
    marker: s.cm
    coordinate: y
    motion:
)" + motion;
}

TF motion_of(const std::string& motion, const std::string& source = kSource) {
  return parse_model(driven(motion), source).joints[1].motion;
}

// What the types read ----------------------------------------------------------------------------

TEST(TimeFunctionFile, EachTypeReadsItsKeys) {
  TF f = motion_of("      {type: ramp, slope: 0.5, offset: 0.1}\n");
  EXPECT_EQ(f.kind, TF::Kind::Ramp);
  EXPECT_DOUBLE_EQ(f.value(2), 1.1);
  f = motion_of("      {type: step, height: 0.2, rise: 0.5, start: 1}\n");
  EXPECT_DOUBLE_EQ(f.value(1.25), 0.1);
  f = motion_of("      {type: chirp, amplitude: 0.01, f0: 1, f1: 10, duration: 5, sweep: logarithmic}\n");
  EXPECT_EQ(f.sweep, TF::Sweep::Logarithmic);
  f = motion_of("      {type: sum_of_sines, amplitudes: [1, 2], frequencies: [1, 2], phases_deg: [90, 0]}\n");
  EXPECT_NEAR(f.value(0), 1.0, 1e-15);
  f = motion_of("      {type: polynomial, coefficients: [0, 1, 3], t0: 1}\n");
  EXPECT_DOUBLE_EQ(f.value(2), 4);
  f = motion_of("      {type: road, class: C, speed: 20, seed: 4, duration: 10, n_min: 0.05, n_max: 1, delay: 0.1}\n");
  EXPECT_EQ(f.road_profile.road_class, 'C');
  EXPECT_DOUBLE_EQ(f.road_profile.length, 200);
  EXPECT_EQ(f.road_profile.seed, 4u);
  f = motion_of("      {type: table, interpolation: linear, accept_linear: true, points: [[0, 0], [1, 1]]}\n");
  EXPECT_EQ(f.interpolation, TF::Interpolation::Linear);
}

TEST(TimeFunctionFile, TableFromCsvRelativeToTheModelFile) {
  const auto dir = inerta::testing::temp_dir() / "tf_csv";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "road.csv") << "# measured\ntime,z,other\n0,0,9\n0.5,0.01,9\n1,0.03,9\n";
  const std::string model = (dir / "m.yaml").string();
  TF f = motion_of("      {type: table, file: road.csv, columns: [time, z]}\n", model);
  EXPECT_EQ(f.interpolation, TF::Interpolation::Spline);
  EXPECT_DOUBLE_EQ(f.value(0.5), 0.01);
  f = motion_of("      {type: table, file: road.csv, columns: [0, 1]}\n", model);  // 0-based positions
  EXPECT_DOUBLE_EQ(f.value(1), 0.03);
  // A CSV cell that is not a number: the CSV file, its line and the column.
  std::ofstream(dir / "bad.csv") << "t,z\n0,0\n1,abc\n";
  std::string msg = model_error(driven("      {type: table, file: bad.csv, columns: [t, z]}\n"), model);
  EXPECT_TRUE(contains(msg, (dir / "bad.csv").string() + ":3: column 'z': 'abc' is not a finite number")) << msg;
  std::ofstream(dir / "back.csv") << "t,z\n0,0\n1,0\n0.5,0\n";
  msg = model_error(driven("      {type: table, file: back.csv, columns: [t, z]}\n"), model);
  EXPECT_TRUE(contains(msg, (dir / "back.csv").string() + ":4: column 't': times must be strictly increasing")) << msg;
  expect_error(driven("      type: table\n      file: road.csv\n      columns: [t, height]   # <-- here\n"), "columns",
               "has no column 't'", model);
  expect_error(driven("      type: table\n      file: nothere.csv   # <-- here\n      columns: [t, z]\n"), "file",
               "cannot open", model);
}

// Refusals for driving joints ----------------------------------------------------------------

TEST(TimeFunctionFile, LinearTableRefusedForADrivingJoint) {
  expect_error(driven("      type: table\n      interpolation: linear   # <-- here\n      points: [[0, 0], [1, 1]]\n"),
               "interpolation", "f'' = 0");
  // A linear table is fine for a force (no second derivative needed).
  EXPECT_NO_THROW(parse_model(driven("      {type: table, points: [[0, 0], [1, 1]]}\nforces:\n  - {name: F, type: "
                                     "point_force, marker: s.cm, direction: [1, 0], value: {type: table, "
                                     "interpolation: linear, points: [[0, 0], [1, 1]]}}\n"),
                              kSource));
}

TEST(TimeFunctionFile, RampWithACornerInTheRunRefusedForADrivingJoint) {
  expect_error(driven("      type: ramp\n      slope: 1\n      start: 0.5   # <-- here\n"), "start", "corner at t = 0.5 s");
  expect_error(driven("      type: ramp\n      slope: 1\n      end: 2   # <-- here\n"), "end", "accept_linear: true");
  EXPECT_NO_THROW(motion_of("      {type: ramp, slope: 1, end: 2, accept_linear: true}\n"));
}

// Error paths, one per key ------------------------------------------------------------------------

struct Case {
  const char* block;  // the motion mapping, with the marked line
  const char* key;
  const char* expected;
};

TEST(TimeFunctionFile, EveryKeyHasAnErrorPath) {
  const Case cases[] = {
      {"      type: wave   # <-- here\n", "type", "unknown function type 'wave'"},
      {"      type: ramp\n      slope: 1\n      slop: 2   # <-- here\n", "slop", "unknown key in motion (ramp)"},
      {"      type: ramp\n      slope: fast   # <-- here\n", "slope", "expected a number"},
      {"      type: ramp   # <-- here\n", "slope", "missing in motion"},
      {"      type: ramp\n      slope: 1\n      start: 1\n      end: 0.5   # <-- here\n      accept_linear: true\n",
       "end", "must be after start"},
      {"      type: ramp\n      slope: 1\n      offset: .nan   # <-- here\n", "offset", "finite"},
      {"      type: ramp\n      slope: 1\n      end: 3\n      accept_linear: maybe   # <-- here\n", "accept_linear",
       "expected true or false"},
      {"      type: step\n      height: 1\n      rise: 0   # <-- here\n", "rise", "must be > 0 (s), got 0"},
      {"      type: step   # <-- here\n      rise: 1\n", "height", "missing"},
      {"      type: step\n      height: 1\n      rise: 1\n      start: x   # <-- here\n", "start", "expected a number"},
      {"      type: step\n      height: 1\n      rise: 1\n      amplitude: 1   # <-- here\n", "amplitude",
       "unknown key in motion (step)"},
      {"      type: chirp\n      amplitude: 1\n      f0: 0   # <-- here\n      f1: 2\n      duration: 1\n      sweep: "
       "logarithmic\n",
       "f0", "must be > 0 (Hz)"},
      {"      type: chirp\n      amplitude: 1\n      f0: 1\n      f1: -2   # <-- here\n      duration: 1\n", "f1",
       "must be >= 0 (Hz)"},
      {"      type: chirp\n      amplitude: 1\n      f0: 1\n      f1: 2\n      duration: -1   # <-- here\n", "duration",
       "must be > 0 (s)"},
      {"      type: chirp\n      amplitude: 1\n      f0: 1\n      f1: 2\n      duration: 1\n      sweep: log   # <-- "
       "here\n",
       "sweep", "expected linear (the default) or logarithmic"},
      {"      type: chirp\n      amplitude: .inf   # <-- here\n      f0: 1\n      f1: 2\n      duration: 1\n", "amplitude",
       "finite"},
      {"      type: sum_of_sines\n      amplitudes: 1   # <-- here\n      frequencies: [1]\n", "amplitudes",
       "expected a list of numbers"},
      {"      type: sum_of_sines\n      amplitudes: [1, 2]\n      frequencies: [1]   # <-- here\n", "frequencies",
       "has 1 frequencies for 2 amplitudes"},
      {"      type: sum_of_sines\n      amplitudes: [1]\n      frequencies: [1]\n      phases: [0, 1]   # <-- here\n",
       "phases", "has 2 phases for 1 amplitudes"},
      {"      type: sum_of_sines\n      amplitudes: [1]\n      frequencies: [1]\n      phases: [0]\n      phases_deg: [0] "
       "  # <-- here\n",
       "phases_deg", "not both"},
      {"      type: sum_of_sines\n      amplitudes: [1, 1]\n      frequencies:\n        - 1\n        - -3   # <-- here\n",
       "frequencies", "must be >= 0 (Hz), got -3"},
      {"      type: polynomial\n      coefficients: []   # <-- here\n", "coefficients", "at least one coefficient"},
      {"      type: polynomial\n      coefficients: [1]\n      t0: abc   # <-- here\n", "t0", "expected a number"},
      {"      type: table\n      points: [[0, 0], [1, 1]]\n      interpolation: cubic   # <-- here\n", "interpolation",
       "expected spline (the default, C²) or linear"},
      {"      type: table   # <-- here\n", "motion", "give either points"},
      {"      type: table\n      points: [[0, 0], [1, 1]]\n      columns: [t, z]   # <-- here\n", "columns",
       "belongs to a table read from a file"},
      {"      type: table\n      file: x.csv\n      columns: [t]   # <-- here\n", "columns",
       "expected two columns [time, value]"},
      {"      type: road\n      class: J   # <-- here\n      speed: 20\n      length: 1000\n", "class",
       "expected an ISO 8608 class A to H"},
      {"      type: road\n      class: AB   # <-- here\n      speed: 20\n      length: 1000\n", "class",
       "expected an ISO 8608 class A to H"},
      {"      type: road\n      class: C\n      speed: 0   # <-- here\n      length: 1000\n", "speed",
       "must be > 0 (m/s), got 0"},
      {"      type: road\n      class: C\n      speed: 20\n      length: 1000\n      seed: 1.5   # <-- here\n", "seed",
       "expected a whole number >= 0"},
      {"      type: road\n      class: C\n      speed: 20\n      length: 1000\n      n_min: -1   # <-- here\n", "n_min",
       "must be > 0 (cycles/m)"},
      {"      type: road\n      class: C\n      speed: 20\n      length: 1000\n      n_max: 0.005   # <-- here\n",
       "n_max", "must be > n_min"},
      {"      type: road\n      class: C\n      speed: 20\n      length: 10   # <-- here\n", "length",
       "at least the longest wavelength"},
      {"      type: road\n      class: C\n      speed: 20\n      duration: -1   # <-- here\n", "duration",
       "must be > 0 (s)"},
      {"      type: road   # <-- here\n      class: C\n      speed: 20\n", "motion", "give either length"},
      {"      type: road\n      class: C\n      speed: 20\n      length: 1000\n      delay: -0.1   # <-- here\n", "delay",
       "must be >= 0 (s)"},
      {"      type: road\n      class: C\n      speed: 20\n      length: 1000\n      offset: x   # <-- here\n", "offset",
       "expected a number"},
      {"      type: road\n      class: C\n      speed: 20\n      length: 1000\n      wavelength: 2   # <-- here\n",
       "wavelength", "unknown key in motion (road)"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.block);
    expect_error(driven(c.block), c.key, c.expected);
  }
}

// Warnings ----------------------------------------------------------------------------------------

const std::string kPendulum = R"(name: p
options: {gravity: false}
ground:
  markers: {O: [0, 0]}
bodies:
  - name: bar
    mass: 1
    inertia: 0.1
    position: [0.5, 0]
    angle: ANGLE
    markers: {a: [-0.5, 0], b: [0.5, 0]}
joints:
  - {name: pin, type: revolute, markers: [ground.O, bar.a]}
)";

std::string with_angle(const std::string& a) {
  std::string t = kPendulum;
  t.replace(t.find("ANGLE"), 5, a);
  return t;
}

bool has_note(const inerta::mbs::Model& m, const std::string& part) {
  for (const auto& n : m.notes)
    if (contains(n, part)) return true;
  return false;
}

TEST(TimeFunctionFile, AngleAboveTwoPiInRadiansIsAWarning) {
  const auto m = parse_model(with_angle("60"), kSource);
  EXPECT_TRUE(has_note(m, "warning: tf.yaml:10: 'angle': 60 rad is more than 2π in magnitude")) << m.notes.size();
  EXPECT_TRUE(has_note(m, "angle_deg: 60"));
  EXPECT_FALSE(has_note(parse_model(with_angle("1.5"), kSource), "'angle'"));
}

TEST(TimeFunctionFile, LargeAssemblyCorrectionIsAWarningNamingTheBody) {
  // The bar is tabulated 0.5 m off its pin: assembly moves it by ≈ 0.5 m in a model 1.1 m in size.
  std::string t = with_angle("0");
  t.replace(t.find("position: [0.5, 0]"), 18, "position: [0.5, 0.5]");
  const auto m = parse_model(t, kSource);
  EXPECT_TRUE(has_note(m, "warning: tf.yaml:6: assembly moved body 'bar' by")) << (m.notes.empty() ? "" : m.notes[0]);
  EXPECT_TRUE(has_note(m, "more than 10 % of the model's size"));
  // A small correction (1 mm) is not.
  t = with_angle("0");
  t.replace(t.find("position: [0.5, 0]"), 18, "position: [0.5, 0.001]");
  EXPECT_TRUE(parse_model(t, kSource).notes.empty());
}

}  // namespace
}  // namespace test_io_time_function_file
