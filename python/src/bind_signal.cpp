// Signal processing for contact-force outputs (numerics/signal.hpp): Butterworth low-pass,
// zero-phase filtering, Welch PSD; and the EN 50317 contact quality built on them
// (analysis/contact_quality.hpp).
#include <fmt/format.h>

#include "common.hpp"
#include "inerta/analysis/contact_quality.hpp"
#include "inerta/numerics/signal.hpp"

namespace inerta::python {

void bind_signal(py::module_& m) {
  py::class_<numerics::Biquad>(m, "Biquad", "One second-order section (a0 = 1), transposed direct form II.")
      .def(py::init([](double b0, double b1, double b2, double a1, double a2) {
             return numerics::Biquad{b0, b1, b2, a1, a2};
           }),
           py::arg("b0") = 1.0, py::arg("b1") = 0.0, py::arg("b2") = 0.0, py::arg("a1") = 0.0, py::arg("a2") = 0.0)
      .def_readwrite("b0", &numerics::Biquad::b0)
      .def_readwrite("b1", &numerics::Biquad::b1)
      .def_readwrite("b2", &numerics::Biquad::b2)
      .def_readwrite("a1", &numerics::Biquad::a1)
      .def_readwrite("a2", &numerics::Biquad::a2);
  py::class_<numerics::SosFilter>(m, "SosFilter", "A cascade of second-order sections designed for a sample rate (Hz).")
      .def_readwrite("sections", &numerics::SosFilter::sections)
      .def_readwrite("sample_rate", &numerics::SosFilter::sample_rate, "Hz")
      .def_readwrite("order", &numerics::SosFilter::order)
      .def("magnitude", [](const numerics::SosFilter& f, double freq) {
        double phase = 0;
        const double mag = f.magnitude(freq, &phase);
        return py::make_tuple(mag, phase);
      }, py::arg("f"), "(|H|, arg H in rad) at f (Hz)")
      .def("dc_gain", &numerics::SosFilter::dc_gain);
  m.def("butterworth_lowpass", &numerics::butterworth_lowpass, py::arg("cutoff"), py::arg("sample_rate"),
        py::arg("order") = 4, "Butterworth low-pass (bilinear transform, pre-warped), cutoff and rate in Hz.");
  m.def("filter", [](const numerics::SosFilter& f, const py::object& x) {
    const std::vector<double> v = doubles(x);
    py::gil_scoped_release nogil;
    return numerics::filter(f, v);
  }, py::arg("filter"), py::arg("x"), "Causal filtering from rest.");
  m.def("filtfilt", [](const numerics::SosFilter& f, const py::object& x) {
    const std::vector<double> v = doubles(x);
    py::gil_scoped_release nogil;
    return numerics::filtfilt(f, v);
  }, py::arg("filter"), py::arg("x"), "Zero-phase forward–backward filtering (magnitude |H|², odd-reflection ends).");
  m.def("filtfilt_padding", &numerics::filtfilt_padding, py::arg("filter"), "samples of the end extension, 3(order + 1)");
  m.def("uniform_sample_rate", [](const py::object& t, double tol) { return numerics::uniform_sample_rate(doubles(t), tol); },
        py::arg("t"), py::arg("rel_tol") = 1e-6, "1/Δt of uniformly sampled times (s → Hz); InvalidArgument otherwise");
  py::class_<numerics::Spectrum>(m, "Spectrum", "One-sided power spectral density S (units²/Hz) at f (Hz).")
      .def_property_readonly("f", [](const numerics::Spectrum& s) { return copy(s.f); }, "Hz")
      .def_property_readonly("S", [](const numerics::Spectrum& s) { return copy(s.S); }, "units²/Hz")
      .def_readonly("resolution", &numerics::Spectrum::resolution, "Hz")
      .def_readonly("segments", &numerics::Spectrum::segments)
      .def("integral", [](const numerics::Spectrum& s, const py::object& lo, const py::object& hi) {
        if (lo.is_none() && hi.is_none()) return s.integral();
        return s.integral(lo.is_none() ? 0.0 : lo.cast<double>(), hi.is_none() ? INFINITY : hi.cast<double>());
      }, py::arg("f_lo") = py::none(), py::arg("f_hi") = py::none(), "∫ S df (over [f_lo, f_hi] Hz): the variance");
  py::enum_<numerics::Window>(m, "Window")
      .value("hann", numerics::Window::Hann)
      .value("rectangular", numerics::Window::Rectangular);
  py::class_<numerics::WelchOptions>(m, "WelchOptions", "Welch PSD: segment (samples, 0 automatic), overlap, window.")
      .def(py::init([](std::size_t segment, double overlap, numerics::Window w) {
             return numerics::WelchOptions{segment, overlap, w};
           }),
           py::arg("segment") = 0, py::arg("overlap") = 0.5, py::arg("window") = numerics::Window::Hann)
      .def_readwrite("segment", &numerics::WelchOptions::segment)
      .def_readwrite("overlap", &numerics::WelchOptions::overlap)
      .def_readwrite("window", &numerics::WelchOptions::window);
  m.def("welch", [](const py::object& x, double fs, const py::object& o) {
    const std::vector<double> v = doubles(x);
    const numerics::WelchOptions opt = o.is_none() ? numerics::WelchOptions{} : o.cast<numerics::WelchOptions>();
    py::gil_scoped_release nogil;
    return numerics::welch(v, fs, opt);
  }, py::arg("x"), py::arg("sample_rate"), py::arg("options") = py::none(), "Welch's PSD of x sampled at sample_rate (Hz).");
  m.def("periodogram", [](const py::object& x, double fs, numerics::Window w) {
    return numerics::periodogram(doubles(x), fs, w);
  }, py::arg("x"), py::arg("sample_rate"), py::arg("window") = numerics::Window::Rectangular,
        "The whole record as one segment, mean removed.");

  // ---- EN 50317 contact quality -----------------------------------------------------------------------
  py::class_<analysis::ContactQualityOptions>(m, "ContactQualityOptions",
                                              "Low-pass cutoff (Hz, 20), Butterworth order (4), PSD segment (samples).")
      .def(py::init([](double cutoff, int order, std::size_t psd_segment, double tol) {
             return analysis::ContactQualityOptions{cutoff, order, psd_segment, tol};
           }),
           py::arg("cutoff") = 20.0, py::arg("order") = 4, py::arg("psd_segment") = 0, py::arg("uniform_tolerance") = 1e-6)
      .def_readwrite("cutoff", &analysis::ContactQualityOptions::cutoff, "Hz")
      .def_readwrite("order", &analysis::ContactQualityOptions::order)
      .def_readwrite("psd_segment", &analysis::ContactQualityOptions::psd_segment)
      .def_readwrite("uniform_tolerance", &analysis::ContactQualityOptions::uniform_tolerance);
  py::class_<analysis::ContactQuality>(m, "ContactQuality",
                                       "EN 50317 statistics of one pantograph over a section: raw and 20 Hz filtered, "
                                       "contact loss (%), PSD of the contact force (N²/Hz).")
      .def_readonly("x_from", &analysis::ContactQuality::x_from, "m")
      .def_readonly("x_to", &analysis::ContactQuality::x_to, "m")
      .def_readonly("t_from", &analysis::ContactQuality::t_from, "s")
      .def_readonly("t_to", &analysis::ContactQuality::t_to, "s")
      .def_readonly("first", &analysis::ContactQuality::first)
      .def_readonly("sample_rate", &analysis::ContactQuality::sample_rate, "Hz")
      .def_readonly("cutoff", &analysis::ContactQuality::cutoff, "Hz")
      .def_readonly("order", &analysis::ContactQuality::order)
      .def_readonly("raw", &analysis::ContactQuality::raw)
      .def_readonly("filtered", &analysis::ContactQuality::filtered)
      .def_readonly("loss_pct", &analysis::ContactQuality::loss_pct, "%")
      .def_readonly("psd", &analysis::ContactQuality::psd);
  m.def("contact_quality", [](const py::object& t, const py::object& x, const py::object& F, const py::object& a,
                              const py::object& b, const py::object& options) {
    const std::vector<double> tv = doubles(t), xv = doubles(x), Fv = doubles(F);
    const analysis::ContactQualityOptions o =
        options.is_none() ? analysis::ContactQualityOptions{} : options.cast<analysis::ContactQualityOptions>();
    catenary::Section s;
    if (py::isinstance<catenary::Section>(a)) {
      s = a.cast<catenary::Section>();
    } else {
      s.from = a.cast<double>();
      s.to = b.cast<double>();
    }
    py::gil_scoped_release nogil;
    return analysis::contact_quality(tv, xv, Fv, s.from, s.to, o);
  }, py::arg("t"), py::arg("x_contact"), py::arg("F"), py::arg("x_from"), py::arg("x_to") = py::none(),
        py::arg("options") = py::none(),
        "EN 50317 contact quality of one pantograph's uniformly sampled history t (s), x_contact (m), F (N) over "
        "[x_from, x_to] (m; or a Section as x_from).");
  py::class_<analysis::PartStatistics>(m, "PartStatistics", "Raw and low-passed statistics over parts of a section.")
      .def_readonly("raw", &analysis::PartStatistics::raw)
      .def_readonly("filtered", &analysis::PartStatistics::filtered);
  m.def("part_statistics", [](const py::object& t, const py::object& x, const py::object& F, const catenary::Section& section,
                              const std::vector<catenary::Section>& parts, const py::object& options) {
    const std::vector<double> tv = doubles(t), xv = doubles(x), Fv = doubles(F);
    const analysis::ContactQualityOptions o =
        options.is_none() ? analysis::ContactQualityOptions{} : options.cast<analysis::ContactQualityOptions>();
    py::gil_scoped_release nogil;
    return analysis::part_statistics(tv, xv, Fv, section, parts, o);
  }, py::arg("t"), py::arg("x_contact"), py::arg("F"), py::arg("section"), py::arg("parts"), py::arg("options") = py::none(),
        "Statistics of the samples with x in one of `parts` (Sections, m) within `section` (the overlaps of a line of "
        "tension sections), raw and after the low-pass of the whole history.");
  py::class_<analysis::SupportUplift>(m, "SupportUplift", "The largest uplift of one support over a run.")
      .def_readonly("support", &analysis::SupportUplift::support)
      .def_readonly("x", &analysis::SupportUplift::x, "m")
      .def_readonly("max_uplift", &analysis::SupportUplift::max_uplift, "m")
      .def_readonly("t_max", &analysis::SupportUplift::t_max, "s");
  m.def("support_uplift", [](const py::object& t, const py::object& support_x,
                             const std::vector<std::vector<double>>& uplift, double x_from, double x_to) {
    return analysis::support_uplift(doubles(t), doubles(support_x), uplift, x_from, x_to);
  }, py::arg("t"), py::arg("support_x"), py::arg("uplift"), py::arg("x_from"), py::arg("x_to"),
        "Max uplift (m) of each support in [x_from, x_to]; uplift[i][k]: support k at t[i].");
}

}  // namespace inerta::python
