#include "halfeti/app/run_health.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "halfeti/cable/cable_set.hpp"
#include "halfeti/core/error.hpp"

namespace halfeti::app {

namespace {
std::string at(double t, long long step) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "t = %.4f s, step %lld: ", t, step);
  return buf;
}
}  // namespace

void RunHealth::check_cables(MPI_Comm comm, const Parts& parts, double t, long long step) {
  const std::size_t n = parts.cable_setups.size();
  if (n == 0) return;
  // Per cable: slack (1/0), the shortfall L0 - chord [m], the larger end stress of one cable [Pa], the plate end.
  std::vector<double> s(5 * n, 0.0);
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  if (rank == 0 && parts.structure_rank)
    for (std::size_t i = 0; i < n; ++i) {
      const auto& sol = parts.cables[i]->last_solution();
      const auto& setup = parts.cable_setups[i];
      s[5 * i] = sol.state == cable::CableState::kSlack ? 1.0 : 0.0;
      s[5 * i + 1] = setup.unstretched_length - sol.chord;
      s[5 * i + 2] = cable::tension_stress(setup.set, std::max(sol.tension_start, sol.tension_end));
      const Eigen::Vector2d end = parts.plate->position(parts.cables[i]->nodes().back());
      s[5 * i + 3] = end.x();
      s[5 * i + 4] = end.y();
    }
  MPI_Bcast(s.data(), static_cast<int>(s.size()), MPI_DOUBLE, 0, comm);
  if (cables_.size() != n) {
    cables_.assign(n, Cable::kUnknown);
    open_.assign(n, -1);
  }
  for (std::size_t i = 0; i < n; ++i) {
    const bool slack = s[5 * i] != 0.0;
    const double shortfall = s[5 * i + 1], stress = s[5 * i + 2], x = s[5 * i + 3], y = s[5 * i + 4];
    const std::string& name = parts.cable_setups[i].name;
    const Cable was = cables_[i];
    const auto open = [&](const std::string& kind, const std::string& message) {
      events_.push_back(health_event(t, step, kind, message));
      open_[i] = static_cast<long>(events_.size()) - 1;
    };
    if (slack && was != Cable::kSlack) {
      std::ostringstream os;
      os << at(t, step) << "cable '" << name << "' went slack (its chord " << shortfall
         << " m shorter than its unstretched length): it holds nothing until it is taut again, then snaps "
            "(a cable_snap warning follows)";
      open("cable_slack", os.str());
      cables_[i] = Cable::kSlack;
    } else if (!slack && was == Cable::kSlack) {
      std::ostringstream os;
      os << at(t, step) << "cable '" << name << "' taut again after "
         << t - events_[static_cast<std::size_t>(open_[i])].time
         << " s slack: it snaps (the snap load, its peak stress, is in summary.json; a smaller "
            "structure.time_step resolves it)";
      open("cable_snap", os.str());
      cables_[i] = Cable::kSnapped;
    } else if (!slack && was == Cable::kUnknown) {
      cables_[i] = Cable::kTaut;
    }
    if (open_[i] >= 0 && cables_[i] != Cable::kTaut)
      health_observe(events_[static_cast<std::size_t>(open_[i])], slack ? shortfall : stress, t, step, x, y);
  }
}

void RunHealth::record_failure(double t, long long step, const std::string& message, const HealthLog& fluid) {
  if (!fluid.empty() && fluid.back().fatal && fluid.back().step == step) return;  // the fluid's own, recorded
  const std::string kind = message.rfind("structure", 0) == 0 ? "structure_failure"
                           : message.rfind("contact", 0) == 0 || message.rfind("coupling", 0) == 0
                               ? "coupling_failure"
                               : "numerical_failure";
  events_.push_back(health_event(t, step, kind, message, true));
}

void RunHealth::announce(io::RunLog& log, const HealthLog& fluid) {
  const auto say = [&](const HealthEvent& e) {
    if (e.fatal) return;  // a failure is the run's last line
    int& printed = printed_[e.kind];
    if (printed < kPrinted)
      log.warning(e.message);
    else if (printed == kPrinted)
      log.warning("further '" + e.kind + "' warnings are counted in summary.json, not printed");
    ++printed;
  };
  for (; announced_fluid_ < fluid.size(); ++announced_fluid_) say(fluid[announced_fluid_]);
  for (; announced_own_ < events_.size(); ++announced_own_) say(events_[announced_own_]);
}

HealthLog RunHealth::merged(const HealthLog& fluid) const {
  HealthLog all = fluid;
  all.insert(all.end(), events_.begin(), events_.end());
  std::stable_sort(all.begin(), all.end(),
                   [](const HealthEvent& a, const HealthEvent& b) { return a.step < b.step; });
  return all;
}

std::string RunHealth::save_state() const {
  std::string cables;
  for (std::size_t i = 0; i < cables_.size(); ++i)
    cables += std::to_string(static_cast<int>(cables_[i])) + " " + std::to_string(open_[i]) + " ";
  return cables + "\n" + encode_health_log(events_);
}

void RunHealth::restore_state(const std::string& text, const HealthLog& fluid) {
  const std::size_t eol = text.find('\n');
  if (eol == std::string::npos) HALFETI_USER_ERROR("restart: the checkpoint's run health state is malformed");
  std::istringstream in(text.substr(0, eol));
  cables_.clear();
  open_.clear();
  for (int state = 0; in >> state;) {
    long open = -1;
    if (!(in >> open) || state < 0 || state > 3)
      HALFETI_USER_ERROR("restart: the checkpoint's cable health states are malformed");
    cables_.push_back(static_cast<Cable>(state));
    open_.push_back(open);
  }
  events_ = decode_health_log(text.substr(eol + 1));
  // What the run said before it stopped is not said again.
  announced_fluid_ = fluid.size();
  announced_own_ = events_.size();
  printed_.clear();
  for (const auto& e : merged(fluid))
    if (!e.fatal) ++printed_[e.kind];
}

}  // namespace halfeti::app
