#include "inerta/io/linear_model_file.hpp"

namespace inerta::io {

Json linear_model_json(const mbs::Model& model, const mbs::LinearModel& lin) {
  Json coords = Json::array();
  for (int k = 0; k < model.n_coords(); ++k) coords.push_back(model.coord_name(k));
  Json j;
  j["model"] = model.name;
  j["state"] = "X = [xi; xi_dot; z], q = q_e + N xi, dX/dt = A X";
  j["coordinates"] = std::move(coords);
  j["dof"] = lin.dof;
  j["internal_states"] = lin.nz;
  j["q_e"] = json_rows(lin.equilibrium.q.transpose());
  j["N"] = json_rows(lin.N);
  j["A"] = json_rows(lin.A);
  j["M"] = json_rows(lin.M);
  j["C"] = json_rows(lin.C);
  j["K"] = json_rows(lin.K);
  return j;
}

void write_linear_model(const std::string& path, const mbs::Model& model, const mbs::LinearModel& lin) {
  write_json(path, linear_model_json(model, lin));
}

}  // namespace inerta::io
