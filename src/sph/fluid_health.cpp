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

void Fluid::remove_spilled() {
  // The tank is open at the top: water thrown over it leaves the run, as it would leave the real tank. Removed in
  // place (owned particles are compacted before migration), counted, and reported once per episode.
  const double H = params_.tank_height;
  long removed = 0, key = std::numeric_limits<long>::max();
  double mass = 0.0, first_x = 0.0, first_y = 0.0;
  std::string msg;
  int kept = 0;
  for (int i = 0; i < n_owned_; ++i) {
    if (std::isfinite(y_[i]) && y_[i] > H) {
      ++removed;
      mass += mass_[i];
      if (gid_[i] < key) {
        key = gid_[i];
        first_x = x_[i];
        first_y = y_[i];
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
    os << where(time_, step_) << static_cast<long>(sums[0])
       << " particle(s) left over the tank's open top (first: " << first << "); removed, " << spilled_mass_
       << " kg/m spilled so far";
  // Worst: the water spilled so far [kg/m]; place: where the first particle over the top (lowest id) was.
  double place[2] = {first_x, first_y};
  if (sums[0] > 0) MPI_Bcast(place, 2, MPI_DOUBLE, first_rank(comm_.get(), removed > 0, key), comm_.get());
  // One episode while water keeps leaving: it ends after 0.05 s without a spill (a sloshing wave throws its crest
  // over the top particle by particle, over a few steps each).
  constexpr double kQuiet = 0.05;                     // [s]
  const HealthEvent* open = open_warning("spilled");  // before warn() opens or closes one
  const bool quiet = sums[0] == 0 && (!open || time_ - open->worst_time > kQuiet);
  warn("spilled", sums[0] > 0, quiet, os.str(), spilled_mass_, place[0], place[1]);
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
    if (!std::isfinite(x_[i]) || !std::isfinite(y_[i]))
      bad = "position";
    else if (!std::isfinite(vx_[i]) || !std::isfinite(vy_[i]))
      bad = "velocity";
    else if (!std::isfinite(rho_[i]))
      bad = "density";
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
  const std::string failed = first_problem(comm_.get(), mine, key, msg);
  if (!failed.empty()) fatal(failed.find("NaN") != std::string::npos ? "nan" : "outside_tank", failed);
  if (dt_ < params_.min_dt) {
    std::ostringstream os;
    os << at << "time step " << dt_ << " s fell below the floor " << params_.min_dt
       << " s (a particle accelerates violently: check the walls and the sound speed)";
    fatal("dt_floor", os.str());
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
    double place[2] = {0.0, 0.0};
    if (rank_ == global.r && worst >= 0) {
      std::ostringstream os;
      os << at << "density variation " << 100.0 * global.v << "% > " << 100.0 * params_.max_density_variation
         << "% at particle " << gid_[worst] << " " << point(x_[worst], y_[worst])
         << " (weak compressibility lost: raise the sound speed)";
      m = os.str();
      place[0] = x_[worst];
      place[1] = y_[worst];
    }
    m = first_problem(comm_.get(), rank_ == global.r, 0, m);
    if (params_.density_variation_fatal) fatal("density_variation", m);
    MPI_Bcast(place, 2, MPI_DOUBLE, global.r, comm_.get());
    warn("density_variation", true, false, m, global.v, place[0], place[1]);
  } else {
    warn("density_variation", false, global.v < 0.8 * params_.max_density_variation, "");
  }

  // Spacing collapse (tensile instability): closest pair found by the last neighbour search, in dx; its place
  // (the pair's first particle, where it is now) looked up only while the condition holds.
  double dmin = search_.min_distance();
  MPI_Allreduce(MPI_IN_PLACE, &dmin, 1, MPI_DOUBLE, MPI_MIN, comm_.get());
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
