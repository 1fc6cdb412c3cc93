// Ground motions: one-cycle pulses (the paper's idealised near-fault impulses, Fig. 4) and sampled records.
#include "halfeti/excitation/ground_motion.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "halfeti/core/error.hpp"

namespace halfeti::excitation {

namespace {

constexpr double kPi = 3.14159265358979323846;

class Still final : public GroundMotion {
 public:
  double acceleration(double) const override { return 0.0; }
  std::string describe() const override { return "none (still tank)"; }
};

class OneCyclePulse final : public GroundMotion {
 public:
  OneCyclePulse(bool cosine, double amplitude, double period, double start)
      : cosine_(cosine), amplitude_(amplitude), period_(period), start_(start) {}
  double acceleration(double t) const override {
    const double s = t - start_;
    if (s < 0.0 || s > period_) return 0.0;
    const double phase = 2.0 * kPi * s / period_;
    return amplitude_ * (cosine_ ? std::cos(phase) : std::sin(phase));
  }
  std::string describe() const override {
    std::ostringstream os;
    os << "one-cycle " << (cosine_ ? "cosine" : "sine") << " pulse, amplitude " << amplitude_
       << " m/s^2, period " << period_ << " s, from t = " << start_ << " s";
    return os.str();
  }

 private:
  bool cosine_;
  double amplitude_, period_, start_;
};

class SampledRecord final : public GroundMotion {
 public:
  SampledRecord(std::vector<double> t, std::vector<double> a, double start, double end, std::string source)
      : t_(std::move(t)), a_(std::move(a)), start_(start), end_(end), source_(std::move(source)) {}
  double acceleration(double t) const override {
    if (t < start_ || t > end_ || t < t_.front() || t > t_.back()) return 0.0;
    const auto it = std::upper_bound(t_.begin(), t_.end(), t);
    if (it == t_.end()) return a_.back();
    const size_t i = static_cast<size_t>(it - t_.begin());
    if (i == 0) return a_.front();
    const double w = (t - t_[i - 1]) / (t_[i] - t_[i - 1]);
    return (1.0 - w) * a_[i - 1] + w * a_[i];
  }
  std::string describe() const override {
    double peak = 0.0;
    for (double a : a_) peak = std::max(peak, std::abs(a));
    std::ostringstream os;
    os << "record " << source_ << ", " << t_.size() << " samples, t = " << t_.front() << " .. " << t_.back()
       << " s, peak " << peak << " m/s^2, applied on [" << start_ << ", " << end_ << "] s";
    return os.str();
  }

 private:
  std::vector<double> t_, a_;
  double start_, end_;
  std::string source_;
};

}  // namespace

std::unique_ptr<GroundMotion> make_still() {
  return std::make_unique<Still>();
}

std::unique_ptr<GroundMotion> make_sine_pulse(double amplitude, double period, double start) {
  HALFETI_CHECK(period > 0, "pulse period must be positive");
  return std::make_unique<OneCyclePulse>(false, amplitude, period, start);
}

std::unique_ptr<GroundMotion> make_cosine_pulse(double amplitude, double period, double start) {
  HALFETI_CHECK(period > 0, "pulse period must be positive");
  return std::make_unique<OneCyclePulse>(true, amplitude, period, start);
}

std::unique_ptr<GroundMotion> make_record(std::vector<double> times, std::vector<double> accelerations,
                                          double start, double end, std::string source) {
  HALFETI_CHECK(times.size() == accelerations.size() && times.size() >= 2,
                "a record needs two or more samples");
  return std::make_unique<SampledRecord>(std::move(times), std::move(accelerations), start, end,
                                         std::move(source));
}

}  // namespace halfeti::excitation
