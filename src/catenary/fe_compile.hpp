#pragma once
// Compiling a line's data (FeCatenaryData, what the file gives) into an FeLine, pass by pass; FeLine's
// constructor is the pipeline (src/catenary/fe_line.cpp, docs/architecture.md "A line feature").
// Each pass reads the data and the earlier passes' results and writes its own:
//   mesh           fe_mesh.cpp           the marks (masts, droppers, stitch clamps), stations and DOFs
//   wires          fe_wires.cpp          each wire's element properties, matrices and weight; supports,
//                                        registrations and anchors
//   stitch_wires   fe_stitch_wires.cpp   the stitch wires and their clamps
//   droppers       fe_droppers.cpp       the droppers in line order with their data and pre-sags
//   form_find      fe_form_finding.cpp   the static state of the designed line (spec/05 §5.3)
//   irregularities fe_irregularities.cpp dropper-length errors and point masses on the form-found line
//   assemble       fe_assembly.cpp       the whole line's K, K_static, M, gravity and static state
// Tension sections and overlaps are placed before (link_sections, fe_sections.cpp: FeLinkedSection each):
// each section is compiled by this pipeline as a line of its own.
#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <array>
#include <functional>
#include <vector>

#include "inerta/catenary/fe_line.hpp"

namespace inerta::catenary::compile {

using Triplets = std::vector<Eigen::Triplet<double>>;

void add_block(Triplets& t, const std::array<int, 4>& d, const Eigen::Matrix4d& k);

/// A station that the mesh must have: a mast, a dropper, a stitch wire's clamp.
struct Mark {
  enum class Kind { Mast, SpanDropper, StitchDropper, StitchEnd } kind;
  double x;        ///< m along the line
  int index;       ///< its position in droppers.x / stitch.droppers.x; a stitch end: 0 ahead of a mast, 1 behind
  bool on_stitch;  ///< a stitch dropper hanging from the stitch wire
};

/// Pass 1: stations at the marks, each interval in equal elements <= mesh.element_length; the DOFs
/// interleaved by station [w_m θ_m w_c θ_c (w_s θ_s)] (a narrow band), w fixed at pinned anchors.
struct Mesh {
  std::vector<double> x;         ///< stations, m
  std::vector<Mark> marks;       ///< in line order (the line's end not included)
  std::vector<int> mark_node;    ///< the station of each mark, then the line's end
  std::vector<int> mast_nodes;   ///< interior masts
  std::vector<int> end_nodes;    ///< anchors on a tensioning device (their w free); none if pinned
  std::vector<char> on_stitch;   ///< per station: 0 no stitch wire, 1 inside one, 2 at its clamp
  std::vector<int> dof;          ///< [node][wire][c] → free DOF or −1
  int n_dofs = 0;
  int at(int wire, int node, int c) const { return dof[static_cast<std::size_t>((node * FeLine::kWires + wire) * 2 + c)]; }
};
Mesh mesh(const FeCatenaryData& d);

/// Pass 2: the wires. Messenger (0) and contact wire (1) apart (the form-finding needs them apart);
/// per element its properties (what wear changes), then matrices and consistent gravity loads.
struct Wires {
  std::vector<double> EI[2], mass_per_length[2];  ///< per element of the messenger and the contact wire
  Triplets k[2], m[2];
  Eigen::VectorXd fg[2];
};
Wires wires(const FeCatenaryData& d, const Mesh& mesh);
/// Pass 3: the stitch wires (with the messenger: the upper structure) and their clamp masses.
void stitch_wires(const FeCatenaryData& d, const Mesh& mesh, Wires& w);

/// Pass 4: the droppers in line order (geometry and data; lengths and tensions from the form-finding)
/// and each one's contact-wire pre-sag (m).
std::vector<FeLine::Dropper> droppers(const FeCatenaryData& d, const Mesh& mesh, std::vector<double>& presag);

/// Pass 5: the form-finding (header of fe_line.hpp). Sets each dropper's tension, length and
/// stiffness; returns the static heights and what the assembly needs.
struct FormFound {
  std::vector<double> stretched;      ///< each dropper's stretched length, m
  std::vector<double> design_length;  ///< unstretched, the form-finding without height errors, m
  Eigen::VectorXd wc, wm;             ///< contact wire and upper structure (w relative to g)
  bool heights = false;               ///< the section has mast heights or a profile (g below)
  double g_a = 0, g_slope = 0;        ///< the straight line g between the anchors' heights
  Eigen::VectorXd g_dofs, g_anchor_force;  ///< FeLine's (empty without heights)
};
FormFound form_find(const FeCatenaryData& d, const Mesh& mesh, const Wires& w, const std::vector<double>& presag,
                    std::vector<FeLine::Dropper>& droppers);

/// Pass 6: irregularities on the form-found line (FeIrregularity): each dropper's length error δ
/// (its length, tension and static stiffness changed), their loads and the point masses' loads and mass.
struct Irregular {
  std::vector<double> delta;  ///< per dropper, m
  Eigen::VectorXd f;          ///< loads that move the line to its reference state
  Triplets point_mass;        ///< the point masses' consistent mass
  bool any = false;
};
Irregular irregularities(const FeCatenaryData& d, int n_dofs, const std::vector<double>& stretched,
                         const std::function<FeLine::Shape(double)>& contact_shape, std::vector<FeLine::Dropper>& droppers);

}  // namespace inerta::catenary::compile
