// The field series of a run (README "Outputs"): the water's particles, the plate's mesh with its stress, the cables
// as curves with their tension, and the tank's outline, each an HDF5 file per output time with an XDMF series
// ParaView opens. Everything is in the tank's frame (the frame the solver works in).
#include <cstdint>

#include "halfeti/app/simulation.hpp"
#include "halfeti/cable/catenary.hpp"

namespace halfeti::app {

namespace {

constexpr int kCableSegments = 32;  // points along each drawn cable, enough for the paper's slack catenaries

// Interleaves two components into (x, y, 0) triples: ParaView's vectors have three.
std::vector<double> as_vectors(std::size_t n, const double* x, const double* y) {
  std::vector<double> out(3 * n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    out[3 * i] = x[i];
    out[3 * i + 1] = y[i];
  }
  return out;
}

}  // namespace

void Simulation::write_fields(double t) {
  write_tank_outline();
  write_plate_fields(t);
  write_cable_fields(t);
  write_fluid_fields(t);
}

void Simulation::write_fluid_fields(double t) {
  if (!parts_.fluid) return;
  ScopedTimer timer(timers_, "fields");
  const sph::Fluid& f = *parts_.fluid;
  const std::size_t n = f.owned_count();
  const std::vector<double> p = f.pressure();
  const std::vector<double> velocity = as_vectors(n, f.vx().data(), f.vy().data());
  fluid_fields_->write(t, n, f.x().data(), f.y().data(),
                       {io::Field::vector("velocity", "m/s", velocity.data()),
                        io::Field::scalar("rho", "kg/m^3", f.rho().data()),
                        io::Field::scalar("p", "Pa", p.data()), io::Field::ids("gid", f.gid().data())});
}

void Simulation::write_plate_fields(double t) {
  if (!plate_fields_) return;
  ScopedTimer timer(timers_, "fields");
  std::vector<double> x, y, displacement, velocity, von_mises, energy;
  std::vector<std::int64_t> cells, element;
  std::vector<double> cell_von_mises, cell_energy;
  // Every plate rank takes part in the element fields; rank 0, which holds the replicated state, writes.
  if (const auto* plate = parts_.plate.get()) plate->element_fields(von_mises, energy);
  if (const auto* plate = rank_ == 0 ? parts_.plate.get() : nullptr) {
    const auto& mesh = plate->mesh();
    for (int n = 0; n < plate->node_count(); ++n) {
      const Eigen::Vector2d p = plate->position(n), u = plate->displacement(n), v = plate->velocity(n);
      x.push_back(p.x());
      y.push_back(p.y());
      displacement.insert(displacement.end(), {u.x(), u.y(), 0.0});
      velocity.insert(velocity.end(), {v.x(), v.y(), 0.0});
    }
    // Drawn as linear quadrilaterals (a Q9 as its four quarters, each carrying its element's values).
    const auto quads = mesh.linear_cells();
    const std::size_t per_element = quads.size() / static_cast<std::size_t>(mesh.element_count());
    for (std::size_t q = 0; q < quads.size(); ++q) {
      cells.insert(cells.end(), quads[q].begin(), quads[q].end());
      const std::size_t e = q / per_element;
      element.push_back(static_cast<std::int64_t>(e));
      cell_von_mises.push_back(von_mises[e]);
      cell_energy.push_back(energy[e]);
    }
  }
  io::CellBlock block{"Quadrilateral", 4, cells.data(), cells.size() / 4};
  plate_fields_->write(
      t, x.size(), x.data(), y.data(),
      {io::Field::vector("displacement", "m", displacement.data()),
       io::Field::vector("velocity", "m/s", velocity.data()),
       io::Field::scalar("von_mises", "Pa", cell_von_mises.data(), io::Center::kCell),
       io::Field::scalar("strain_energy_density", "J/m^3", cell_energy.data(), io::Center::kCell),
       io::Field::ids("element", element.data(), io::Center::kCell)},
      &block);
}

void Simulation::write_cable_fields(double t) {
  if (!cable_fields_) return;
  ScopedTimer timer(timers_, "fields");
  std::vector<double> x, y, force, stress;
  std::vector<std::int64_t> cells, index;
  if (rank_ == 0 && parts_.plate) {  // the cables' state is the plate's, replicated on its ranks
    for (std::size_t i = 0; i < parts_.cables.size(); ++i) {
      const auto& element = *parts_.cables[i];
      const auto& set = parts_.cable_setups[i].set;
      const Eigen::Vector2d plate_end = parts_.plate->position(element.nodes()[0]);
      const auto curve = cable::catenary_curve(element.anchor(), plate_end, element.properties(),
                                               element.last_solution(), kCableSegments);
      const auto first = static_cast<std::int64_t>(x.size());
      for (std::size_t k = 0; k < curve.size(); ++k) {
        x.push_back(curve[k].position.x());
        y.push_back(curve[k].position.y());
        force.push_back(cable::tension_per_cable(set, curve[k].tension));  // one real cable's, as the probes
        stress.push_back(cable::tension_stress(set, curve[k].tension));
        index.push_back(static_cast<std::int64_t>(i));
        if (k > 0)
          cells.insert(cells.end(),
                       {first + static_cast<std::int64_t>(k) - 1, first + static_cast<std::int64_t>(k)});
      }
    }
  }
  io::CellBlock block{"Polyline", 2, cells.data(), cells.size() / 2};
  cable_fields_->write(
      t, x.size(), x.data(), y.data(),
      {io::Field::scalar("tension", "N", force.data()), io::Field::scalar("stress", "Pa", stress.data()),
       io::Field::ids("cable", index.data())},
      &block);
}

void Simulation::write_tank_outline() {
  // The walls and the floor, once (a continued run keeps the first frame).
  if (!tank_fields_ || tank_fields_->frames() > 0) return;
  const auto& p = *parts_.fluid_params;
  std::vector<double> x, y;
  std::vector<std::int64_t> cells;
  if (rank_ == 0) {
    x = {0.0, 0.0, p.tank_length, p.tank_length};
    y = {p.tank_height, 0.0, 0.0, p.tank_height};
    cells = {0, 1, 1, 2, 2, 3};
  }
  io::CellBlock block{"Polyline", 2, cells.data(), cells.size() / 2};
  tank_fields_->write(0.0, x.size(), x.data(), y.data(), {}, &block);
}

}  // namespace halfeti::app
