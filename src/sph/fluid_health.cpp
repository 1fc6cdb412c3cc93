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

void Fluid::warn(const std::string& kind, bool active, bool cleared, const std::string& message) {
  // One event when a condition starts; re-armed only once it has clearly gone (hysteresis), so a measure that
  // hovers at its threshold does not flood the list.
  auto it = std::find(active_warnings_.begin(), active_warnings_.end(), kind);
  if (active && it == active_warnings_.end()) {
    active_warnings_.push_back(kind);
    events_.push_back({time_, step_, kind, message, false});
  } else if (cleared && it != active_warnings_.end()) {
    active_warnings_.erase(it);
  }
}

void Fluid::remove_spilled() {
  // The tank is open at the top: water thrown over it leaves the run, as it would leave the real tank. Removed in
  // place (owned particles are compacted before migration), counted, and reported once per episode.
  const double H = params_.tank_height;
  long removed = 0, key = std::numeric_limits<long>::max();
  double mass = 0.0;
  std::string msg;
  int kept = 0;
  for (int i = 0; i < n_owned_; ++i) {
    if (std::isfinite(y_[i]) && y_[i] > H) {
      ++removed;
      mass += mass_[i];
      if (gid_[i] < key) {
        key = gid_[i];
        msg = "particle " + std::to_string(gid_[i]) + " at " + point(x_[i], y_[i]);
      }
      continue;
    }
    for (auto* v : {&x_, &y_, &vx_, &vy_, &rho_, &mass_}) (*v)[kept] = (*v)[i];
    gid_[kept] = gid_[i];
    ++kept;
  }
  for (auto* v : {&x_, &y_, &vx_, &vy_, &rho_, &mass_}) v->resize(kept);
  gid_.resize(kept);
  n_owned_ = n_local_ = kept;
  double sums[2] = {static_cast<double>(removed), mass};
  MPI_Allreduce(MPI_IN_PLACE, sums, 2, MPI_DOUBLE, MPI_SUM, comm_.get());
  const std::string first = first_problem(comm_.get(), removed > 0, key, msg);
  n_global_ -= static_cast<long>(sums[0]);
  spilled_mass_ += sums[1];
  std::ostringstream os;
  if (sums[0] > 0)
    os << where(time_, step_) << static_cast<long>(sums[0]) << " particle(s) left over the tank's open top (first: "
       << first << "); removed, " << spilled_mass_ << " kg/m spilled so far";
  warn("spilled", sums[0] > 0, sums[0] == 0, os.str());
}

void Fluid::check_health() {
  remove_spilled();
  const std::string at = where(time_, step_);
  // Fatal: NaN/Inf, then a particle outside the tank. The lowest global id found on any rank is reported.
  long key = std::numeric_limits<long>::max();
  std::string msg, kind;
  const double L = params_.tank_length, H = params_.tank_height;
  for (int i = 0; i < n_owned_; ++i) {
    const char* bad = nullptr;
    if (!std::isfinite(x_[i]) || !std::isfinite(y_[i])) bad = "position";
    else if (!std::isfinite(vx_[i]) || !std::isfinite(vy_[i])) bad = "velocity";
    else if (!std::isfinite(rho_[i])) bad = "density";
    std::string m, k;
    if (bad) {
      k = "nan";
      m = at + "particle " + std::to_string(gid_[i]) + " at " + point(x_[i], y_[i]) + " has NaN " + bad +
          " (check dt and the sound speed)";
    } else if (x_[i] < 0.0 || x_[i] > L || y_[i] < 0.0 || y_[i] > H) {
      k = "outside_tank";
      m = at + "particle " + std::to_string(gid_[i]) + " at " + point(x_[i], y_[i]) +
          " left the tank through a wall (wall repulsion too weak for this speed, or dt too large)";
    } else {
      continue;
    }
    if (gid_[i] < key) {
      key = gid_[i];
      msg = m;
      kind = k;
    }
  }
  const bool mine = !msg.empty();
  const std::string fatal = first_problem(comm_.get(), mine, key, msg);
  if (!fatal.empty()) {
    const std::string k = fatal.find("NaN") != std::string::npos ? "nan" : "outside_tank";
    events_.push_back({time_, step_, k, fatal, true});
    HALFETI_NUMERICAL_ERROR(fatal);
  }
  if (dt_ < params_.min_dt) {
    std::ostringstream os;
    os << at << "time step " << dt_ << " s fell below the floor " << params_.min_dt
       << " s (a particle accelerates violently: check the walls and the sound speed)";
    events_.push_back({time_, step_, "dt_floor", os.str(), true});
    HALFETI_NUMERICAL_ERROR(os.str());
  }

  // Density variation (weak compressibility lost): warning, fatal only if the scene says so.
  struct {
    double v;
    int r;
  } local{0.0, rank_}, global{0.0, 0};
  int worst = -1;
  for (int i = 0; i < n_owned_; ++i) {
    const double v = std::abs(rho_[i] - params_.density) / params_.density;
    if (v > local.v) {
      local.v = v;
      worst = i;
    }
  }
  MPI_Allreduce(&local, &global, 1, MPI_DOUBLE_INT, MPI_MAXLOC, comm_.get());
  const bool dense = global.v > params_.max_density_variation;
  if (dense) {
    std::string m;
    if (rank_ == global.r && worst >= 0) {
      std::ostringstream os;
      os << at << "density variation " << 100.0 * global.v << "% > " << 100.0 * params_.max_density_variation
         << "% at particle " << gid_[worst] << " " << point(x_[worst], y_[worst])
         << " (weak compressibility lost: raise the sound speed)";
      m = os.str();
    }
    m = first_problem(comm_.get(), rank_ == global.r, 0, m);
    if (params_.density_variation_fatal) {
      events_.push_back({time_, step_, "density_variation", m, true});
      HALFETI_NUMERICAL_ERROR(m);
    }
    warn("density_variation", true, false, m);
  } else {
    warn("density_variation", false, global.v < 0.8 * params_.max_density_variation, "");
  }

  // Spacing collapse (tensile instability): closest pair found by the last neighbour search.
  double dmin = search_.min_distance();
  MPI_Allreduce(MPI_IN_PLACE, &dmin, 1, MPI_DOUBLE, MPI_MIN, comm_.get());
  const bool collapsed = dmin < params_.spacing_collapse_fraction * dx_;
  std::ostringstream os;
  if (collapsed)
    os << at << "two particles came within " << dmin << " m (" << dmin / dx_
       << " dx): spacing collapse, tensile instability (keep the tensile correction on)";
  warn("spacing_collapse", collapsed, dmin > 1.5 * params_.spacing_collapse_fraction * dx_, os.str());
}

}  // namespace halfeti::sph
