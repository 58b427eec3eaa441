// Pass 4 of compiling a line (fe_compile.hpp): the droppers in line order.
#include "fe_compile.hpp"

namespace inerta::catenary::compile {

std::vector<FeLine::Dropper> droppers(const FeCatenaryData& d, const Mesh& mesh, std::vector<double>& presag) {
  std::vector<FeLine::Dropper> out;
  const FeStitch& st = d.stitch;
  using Dropper = FeLine::Dropper;
  for (std::size_t i = 0; i < mesh.marks.size(); ++i) {
    const Mark& it = mesh.marks[i];
    if (it.kind != Mark::Kind::SpanDropper && it.kind != Mark::Kind::StitchDropper) continue;
    const int n = mesh.mark_node[i];
    Dropper dr{mesh.x[static_cast<std::size_t>(n)], n, mesh.at(it.on_stitch ? 2 : 0, n, 0), mesh.at(1, n, 0), 0, 0, 0};
    dr.index = it.index;
    const std::size_t j = static_cast<std::size_t>(it.index);
    if (it.kind == Mark::Kind::SpanDropper) {
      dr.kind = Dropper::Kind::Span;
      dr.EA = d.dropper_EA, dr.mass_per_length = d.dropper_mass_per_length;
      dr.clamp_upper = d.clamp_mass_messenger, dr.clamp_contact = d.clamp_mass_contact;
      presag.push_back(d.presag[j]);
    } else {
      dr.kind = Dropper::Kind::Stitch;
      dr.on_stitch_wire = it.on_stitch;
      dr.EA = st.dropper_EA, dr.mass_per_length = st.dropper_mass_per_length;
      dr.clamp_upper = it.on_stitch ? st.clamp_mass_stitch : d.clamp_mass_messenger;
      dr.clamp_contact = st.clamp_mass_contact;
      presag.push_back(st.dropper_presag.empty() ? 0.0 : st.dropper_presag[j]);
    }
    out.push_back(dr);
  }
  return out;
}

}  // namespace inerta::catenary::compile
