#include "inerta/catenary/catenary.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "inerta/error.hpp"

namespace inerta::catenary {

std::unique_ptr<Coupled> Catenary::couple(const std::vector<PantographOnLine>& pantographs, double speed) const {
  return make_coupled(running(pantographs, speed), speed);
}

std::vector<PantographOnLine> Catenary::running(const std::vector<PantographOnLine>& pantographs, double speed) const {
  if (pantographs.empty()) throw InvalidArgument("couple: no pantograph given");
  if (!(speed > 0) || !std::isfinite(speed))
    throw InvalidArgument(fmt::format("couple: the speed must be a positive number of m/s, got {}", speed));
  if (static_cast<int>(pantographs.size()) > max_pantographs())
    throw ModelError(fmt::format("the {} carries at most {} pantograph(s), {} were given{}", describe(), max_pantographs(),
                                 pantographs.size(),
                                 max_pantographs() == 1 ? " (a point model has no distance between pantographs)" : ""));
  for (std::size_t k = 0; k < pantographs.size(); ++k) {
    const PantographOnLine& p = pantographs[k];
    const mbs::Model& m = p.pantograph.model;
    if (p.pantograph.contact_marker < 0 || p.pantograph.contact_marker >= static_cast<int>(m.markers.size()))
      throw ModelError(fmt::format("{}: pantograph {} has no contact point (pantograph: contact) to couple", m.source,
                                   k + 1));
    if (m.spatial()) throw ModelError(fmt::format("{}: the pantograph-catenary analyses are planar", m.source));
    if (!std::isfinite(p.x0)) throw InvalidArgument(fmt::format("pantograph {}: position x0 = {}", k + 1, p.x0));
    for (std::size_t j = 0; j < k; ++j)  // two heads on one point of the wire: not a train (issue 52)
      if (pantographs[j].x0 == p.x0)
        throw InvalidArgument(fmt::format("pantographs {} and {} are both at x0 = {:g} m; give each its own position", j + 1,
                                          k + 1, p.x0));
    p.contact.validate();
  }
  std::vector<PantographOnLine> running = pantographs;  // with each one's aerodynamic uplift at this speed
  for (PantographOnLine& p : running) p.pantograph = pantograph::at_speed(p.pantograph, speed);
  return running;
}

std::unique_ptr<CoupledLanes> Catenary::couple_lanes(const std::vector<std::vector<PantographOnLine>>& trains,
                                                     double speed) const {
  if (trains.empty()) throw InvalidArgument("couple_lanes: no train given");
  std::vector<std::vector<PantographOnLine>> run;
  for (std::size_t i = 0; i < trains.size(); ++i) {
    run.push_back(running(trains[i], speed));  // couple's checks first (a NaN x0 is named as such)
    if (trains[i].size() != trains.front().size())
      throw InvalidArgument(fmt::format("couple_lanes: train {} has {} pantograph(s), train 1 has {}", i + 1,
                                        trains[i].size(), trains.front().size()));
    for (std::size_t k = 0; k < trains[i].size(); ++k)
      if (trains[i][k].x0 != trains.front()[k].x0)
        throw InvalidArgument(fmt::format("couple_lanes: pantograph {} of train {} is at x0 = {:g} m, of train 1 at {:g} m; "
                                          "lanes run at the same positions",
                                          k + 1, i + 1, trains[i][k].x0, trains.front()[k].x0));
  }
  return make_lanes(run, speed);
}

std::unique_ptr<CoupledLanes> Catenary::make_lanes(const std::vector<std::vector<PantographOnLine>>& trains,
                                                   double speed) const {
  std::vector<std::unique_ptr<Coupled>> lanes;
  for (const auto& t : trains) lanes.push_back(make_coupled(t, speed));
  return std::make_unique<CoupledLanes>(std::move(lanes));
}

CoupledLanes::CoupledLanes(std::vector<std::unique_ptr<Coupled>> lanes)
    : lanes_(std::move(lanes)), errors_(lanes_.size()) {}

Coupled& CoupledLanes::lane(int i) {
  if (i < 0 || i >= lanes()) throw InvalidArgument(fmt::format("lane {} does not exist: there are {}", i, lanes()));
  return *lanes_[static_cast<std::size_t>(i)];
}
const Coupled& CoupledLanes::lane(int i) const { return const_cast<CoupledLanes*>(this)->lane(i); }

void CoupledLanes::fail(int i, std::exception_ptr e) {
  lane(i);
  errors_[static_cast<std::size_t>(i)] = std::move(e);
}

std::exception_ptr CoupledLanes::error(int i) const {
  lane(i);
  return errors_[static_cast<std::size_t>(i)];
}

void CoupledLanes::advance(double t_end, double dt, const solve::IntegratorOptions& options, const LaneObserver& observer,
                           bool accelerations) {
  for (int i = 0; i < lanes(); ++i) {
    if (!running(i)) continue;
    try {
      lane(i).advance(t_end, dt, options, [&](const Sample& s) { observer(i, s); }, accelerations);
    } catch (...) {
      fail(i, std::current_exception());
    }
  }
}

double Catenary::estimated_seconds(const std::vector<PantographOnLine>& pantographs, double speed, double t_end) const {
  if (!(speed > 0)) return 0;
  const double t = t_end > 0 ? t_end : kSweepSpans * span() / speed;
  return 1e-3 * t * static_cast<double>(std::max<std::size_t>(pantographs.size(), 1));
}

std::unique_ptr<Coupled> Catenary::couple(const pantograph::Pantograph& p, const Contact& contact, double speed) const {
  return couple(std::vector<PantographOnLine>{{p, 0.0, contact}}, speed);
}

}  // namespace inerta::catenary

namespace inerta::catenary {

std::vector<std::string> Coupled::support_names() const {
  std::vector<std::string> names;
  for (double x : support_x()) names.push_back(fmt::format("uplift@{:g}", x));
  return names;
}

}  // namespace inerta::catenary
