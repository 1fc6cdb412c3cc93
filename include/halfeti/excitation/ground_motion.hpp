// Horizontal ground acceleration of the tank, a_g(t) in m/s^2. In the tank's frame every mass feels the body force
// -a_g(t) (DESIGN.md, "The tank frame").
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace halfeti::excitation {

class GroundMotion {
 public:
  virtual ~GroundMotion() = default;
  virtual double acceleration(double t) const = 0;  // m/s^2, positive towards +x
  virtual std::string describe() const = 0;
};

// No motion.
std::unique_ptr<GroundMotion> make_still();
// One full cycle a(t) = A sin(2 pi (t - t0) / T) for t0 <= t <= t0 + T, zero elsewhere.
std::unique_ptr<GroundMotion> make_sine_pulse(double amplitude, double period, double start);
// One full cycle a(t) = A cos(2 pi (t - t0) / T) for t0 <= t <= t0 + T, zero elsewhere.
std::unique_ptr<GroundMotion> make_cosine_pulse(double amplitude, double period, double start);
// A sampled record (times ascending, accelerations in m/s^2), linearly interpolated, zero outside [start, end].
std::unique_ptr<GroundMotion> make_record(std::vector<double> times, std::vector<double> accelerations,
                                          double start, double end, std::string source);

// Reads a CSV accelerogram: '#' comment lines, one header row, then rows whose first column is t [s] and second
// the acceleration, in g (units = "g") or m/s^2 (units = "m/s2"), multiplied by `scale`. Errors name the file
// and line.
std::unique_ptr<GroundMotion> read_record_csv(const std::string& path, const std::string& units, double scale,
                                              double start, double end, double time_shift);

}  // namespace halfeti::excitation
