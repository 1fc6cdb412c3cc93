// Health monitors of the fluid (DESIGN.md "Health monitors").
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "halfeti/core/error.hpp"
#include "halfeti/sph/fluid.hpp"

namespace halfeti::sph {

namespace {
std::string where(double t, long step) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "t = %.4f s, step %ld: ", t, step);
  return buf;
}
std::string point(double x, double y) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "(%.4f, %.4f)", x, y);
  return buf;
}
}  // namespace

void Fluid::warn(const std::string& kind, bool active, bool cleared, const std::string& message, double value,
                 double x, double y) {
  // One event when a condition starts; re-armed only once it has clearly gone (hysteresis), so a measure that
  // hovers at its threshold does not flood the list. While it holds, the episode keeps its worst value and place.
  auto it = std::find(active_warnings_.begin(), active_warnings_.end(), kind);
  if (active && it == active_warnings_.end()) {
    active_warnings_.push_back(kind);
    events_.push_back(health_event(time_, step_, kind, message));
  } else if (cleared && it != active_warnings_.end()) {
    active_warnings_.erase(it);
  }
  if (HealthEvent* open = active ? open_warning(kind) : nullptr)
    health_observe(*open, value, time_, step_, x, y);
}

HealthEvent* Fluid::open_warning(const std::string& kind) {
  if (std::find(active_warnings_.begin(), active_warnings_.end(), kind) == active_warnings_.end())
    return nullptr;
  for (auto e = events_.rbegin(); e != events_.rend(); ++e)
    if (e->kind == kind && !e->fatal) return &*e;
  return nullptr;
}

void Fluid::fatal(const std::string& kind, const std::string& message) {
  events_.push_back(health_event(time_, step_, kind, message, true));
  HALFETI_NUMERICAL_ERROR(message);
}

Fluid::LocalHealth Fluid::scan_health() {
  // One pass over the owned particles. The tank is open at the top: water thrown over it leaves the run, as it
  // would leave the real tank (removed in place: owned particles are compacted before migration, and counted).
  // What remains is checked for NaN/Inf, then for a place outside the tank, and its density variation taken. The
  // lowest global id found is the one reported.
  LocalHealth h;
  h.spilled_key = h.bad_key = std::numeric_limits<long>::max();
  const double L = params_.tank_length, H = params_.tank_height, rho0 = params_.density;
  cell_.resize(n_owned_);
  int kept = 0;
  for (int i = 0; i < n_owned_; ++i) {
    if (std::isfinite(y_[i]) && y_[i] > H) {
      ++h.spilled;
      h.spilled_mass += mass_[i];
      if (gid_[i] < h.spilled_key) {
        h.spilled_key = gid_[i];
        h.spilled_x = x_[i];
        h.spilled_y = y_[i];
        h.spilled_msg = "particle " + std::to_string(gid_[i]) + " at " + point(x_[i], y_[i]);
      }
      continue;
    }
    if (kept != i) {  // only once a particle has gone: most steps write nothing
      for (auto* v : {&x_, &y_, &vx_, &vy_, &rho_, &mass_}) (*v)[kept] = (*v)[i];
      gid_[kept] = gid_[i];
    }
    const int k = kept++;
    const char* bad = nullptr;
    if (!std::isfinite(x_[k]) || !std::isfinite(y_[k]))
      bad = "position";
    else if (!std::isfinite(vx_[k]) || !std::isfinite(vy_[k]))
      bad = "velocity";
    else if (!std::isfinite(rho_[k]))
      bad = "density";
    if (bad || x_[k] < 0.0 || x_[k] > L || y_[k] < 0.0 || y_[k] > H) {
      if (gid_[k] < h.bad_key) {
        h.bad_key = gid_[k];
        h.bad_msg = "particle " + std::to_string(gid_[k]) + " at " + point(x_[k], y_[k]) +
                    (bad ? std::string(" has NaN ") + bad + " (check dt and the sound speed)"
                         : std::string(" left the tank through a wall (wall repulsion too weak for this "
                                       "speed, or dt too large)"));
      }
      continue;
    }
    const double v = std::abs(rho_[k] - rho0) / rho0;
    if (v > h.density_variation) {
      h.density_variation = v;
      h.densest = k;
    }
    // Its cell, for the migration: a step moves a particle at most into a cell next to its own, whose owner is
    // this rank or a halo peer; one that went further makes the migration find its senders (found here, joined in
    // check_health's reduction).
    const int c = grid_.cell_of(x_[k], y_[k]);
    cell_[k] = c;
    if (owner_[c] != rank_ && !std::binary_search(peers_.begin(), peers_.end(), owner_[c])) h.far = true;
  }
  if (kept != n_owned_) {
    for (auto* v : {&x_, &y_, &vx_, &vy_, &rho_, &mass_}) v->resize(kept);
    gid_.resize(kept);
    n_owned_ = n_local_ = kept;
  }
  return h;
}

void Fluid::report_spilled(const LocalHealth& mine, bool anywhere) {
  // Counted and reported once per episode (the sums and the first place are gathered only when water has left).
  double sums[2] = {0.0, 0.0};
  std::string first;
  double place[2] = {0.0, 0.0};
  if (anywhere) {
    sums[0] = static_cast<double>(mine.spilled);
    sums[1] = mine.spilled_mass;
    MPI_Allreduce(MPI_IN_PLACE, sums, 2, MPI_DOUBLE, MPI_SUM, comm_.get());
    const int root = first_rank(comm_.get(), mine.spilled > 0, mine.spilled_key);
    first = broadcast_from(comm_.get(), root, mine.spilled_msg);
    n_global_ -= static_cast<long>(sums[0]);
    spilled_mass_ += sums[1];
    place[0] = mine.spilled_x;
    place[1] = mine.spilled_y;
    MPI_Bcast(place, 2, MPI_DOUBLE, root, comm_.get());
  }
  std::ostringstream os;
  if (anywhere)
    os << where(time_, step_) << static_cast<long>(sums[0])
       << " particle(s) left over the tank's open top (first: " << first << "); removed, " << spilled_mass_
       << " kg/m spilled so far";
  // Worst: the water spilled so far [kg/m]; place: where the first particle over the top (lowest id) was.
  // One episode while water keeps leaving: it ends after 0.05 s without a spill (a sloshing wave throws its crest
  // over the top particle by particle, over a few steps each).
  constexpr double kQuiet = 0.05;                     // [s]
  const HealthEvent* open = open_warning("spilled");  // before warn() opens or closes one
  const bool quiet = !anywhere && (!open || time_ - open->worst_time > kQuiet);
  warn("spilled", anywhere, quiet, os.str(), spilled_mass_, place[0], place[1]);
}

void Fluid::check_health() {
  const LocalHealth mine = scan_health();
  const std::string at = where(time_, step_);
  // The checks' local findings joined by one reduction a step (a minimum as the maximum of its negative; ids are
  // exact in a double): whether water spilled or a particle went bad anywhere (the lowest id), the largest
  // density variation, the closest pair, and whether a particle went past the halo peers (the migration's need).
  // Only a check that found something gathers more.
  constexpr double kNone = -std::numeric_limits<double>::infinity();
  const double dmin_local = search_.min_distance();
  double all[5] = {mine.spilled > 0 ? -static_cast<double>(mine.spilled_key) : kNone,
                   mine.bad_msg.empty() ? kNone : -static_cast<double>(mine.bad_key), mine.density_variation,
                   -dmin_local, mine.far ? 1.0 : 0.0};
  MPI_Allreduce(MPI_IN_PLACE, all, 5, MPI_DOUBLE, MPI_MAX, comm_.get());
  far_move_ = all[4] > 0.0;
  report_spilled(mine, all[0] != kNone);

  // Fatal: NaN/Inf, then a particle outside the tank.
  if (all[1] != kNone) {
    const std::string failed = first_problem(comm_.get(), !mine.bad_msg.empty(), mine.bad_key, mine.bad_msg);
    fatal(failed.find("NaN") != std::string::npos ? "nan" : "outside_tank", at + failed);
  }
  if (dt_ < params_.min_dt) {
    std::ostringstream os;
    os << at << "time step " << dt_ << " s fell below the floor " << params_.min_dt
       << " s (a particle accelerates violently: check the walls and the sound speed)";
    fatal("dt_floor", os.str());
  }

  // Density variation (weak compressibility lost): warning, fatal only if the scene says so. Reported from the
  // lowest rank holding the largest value.
  const double variation = all[2];
  const bool dense = variation > params_.max_density_variation;
  if (dense) {
    const bool holds = mine.densest >= 0 && mine.density_variation == variation;
    const int root = first_rank(comm_.get(), holds, 0);
    std::string m;
    double place[2] = {0.0, 0.0};
    if (rank_ == root) {
      const int worst = mine.densest;
      std::ostringstream os;
      os << at << "density variation " << 100.0 * variation << "% > " << 100.0 * params_.max_density_variation
         << "% at particle " << gid_[worst] << " " << point(x_[worst], y_[worst])
         << " (weak compressibility lost: raise the sound speed)";
      m = os.str();
      place[0] = x_[worst];
      place[1] = y_[worst];
    }
    m = broadcast_from(comm_.get(), root, m);
    if (params_.density_variation_fatal) fatal("density_variation", m);
    MPI_Bcast(place, 2, MPI_DOUBLE, root, comm_.get());
    warn("density_variation", true, false, m, variation, place[0], place[1]);
  } else {
    warn("density_variation", false, variation < 0.8 * params_.max_density_variation, "");
  }

  // Spacing collapse (tensile instability): closest pair found by the last neighbour search, in dx; its place
  // (the pair's first particle, where it is now) looked up only while the condition holds.
  const double dmin = -all[3];
  const bool collapsed = dmin < params_.spacing_collapse_fraction * dx_;
  std::ostringstream os;
  double place[2] = {std::nan(""), std::nan("")};
  if (collapsed) {
    os << at << "two particles came within " << dmin << " m (" << dmin / dx_
       << " dx): spacing collapse, tensile instability (keep the tensile correction on)";
    const int i = closest_pair_particle(dmin);
    if (i >= 0) {
      place[0] = x_[i];
      place[1] = y_[i];
    }
    const int root = first_rank(comm_.get(), i >= 0, 0);
    MPI_Bcast(place, 2, MPI_DOUBLE, root < 0 ? 0 : root, comm_.get());
  }
  warn("spacing_collapse", collapsed, dmin > 1.5 * params_.spacing_collapse_fraction * dx_, os.str(),
       dmin / dx_, place[0], place[1]);
}

int Fluid::closest_pair_particle(double dmin) const {
  // The owned particle with a neighbour at dmin (the search's own minimum, so an exact match exists on the rank
  // that found it; -1 elsewhere), as the search recorded it.
  if (pairs_.start.size() != static_cast<std::size_t>(n_owned_) + 1) return -1;  // particles spilled since
  return search_.min_distance() <= dmin * (1.0 + 1e-12) ? search_.closest_particle() : -1;
}

}  // namespace halfeti::sph
