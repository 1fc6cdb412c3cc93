#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "halfeti/core/error.hpp"
#include "halfeti/excitation/ground_motion.hpp"

using namespace halfeti;

TEST(GroundMotion, OneCyclePulsesAreZeroOutsideTheirCycle) {
  const auto s = excitation::make_sine_pulse(3.0, 0.4, 0.1);
  const auto c = excitation::make_cosine_pulse(3.0, 0.4, 0.1);
  EXPECT_EQ(s->acceleration(0.05), 0.0);
  EXPECT_EQ(c->acceleration(0.55), 0.0);
  EXPECT_NEAR(s->acceleration(0.2), 3.0, 1e-12);   // quarter period: sine peak
  EXPECT_NEAR(c->acceleration(0.1), 3.0, 1e-12);   // start: cosine peak
  EXPECT_NEAR(c->acceleration(0.3), -3.0, 1e-12);  // half period
  // A one-cycle sine ends at rest (zero velocity change); a one-cycle cosine too.
  double dv_s = 0, dv_c = 0;
  for (int i = 0; i < 40000; ++i) {
    const double t = 0.1 + (i + 0.5) * 1e-5;
    dv_s += s->acceleration(t) * 1e-5;
    dv_c += c->acceleration(t) * 1e-5;
  }
  EXPECT_NEAR(dv_s, 0.0, 1e-9);
  EXPECT_NEAR(dv_c, 0.0, 1e-9);
}

TEST(GroundMotion, ElCentroRecordPeakAndInterpolation) {
  const std::string path = std::string(HALFETI_SOURCE_DIR) + "/inputs/records/elcentro_ns.csv";
  const auto r = excitation::read_record_csv(path, "g", 1.0, 0.0, 1e300, 0.0);
  // The file's provenance header: PGA 0.319 g at 2.04 s (Chopra's digitisation).
  double peak = 0, t_peak = 0;
  for (int i = 0; i <= 1560; ++i) {
    const double t = 0.02 * i;
    if (std::abs(r->acceleration(t)) > peak) {
      peak = std::abs(r->acceleration(t));
      t_peak = t;
    }
  }
  EXPECT_NEAR(peak / 9.80665, 0.319, 0.0005);
  EXPECT_NEAR(t_peak, 2.04, 1e-9);
  // Halfway between two samples: their mean (0.02 s: 0.00630 g, 0 s: 0).
  EXPECT_NEAR(r->acceleration(0.01), 0.5 * 0.00630 * 9.80665, 1e-12);
  // Outside [start, end]: still.
  const auto cut = excitation::read_record_csv(path, "g", 2.0, 1.0, 3.0, 0.0);
  EXPECT_EQ(cut->acceleration(0.5), 0.0);
  EXPECT_NEAR(cut->acceleration(2.04), 2.0 * r->acceleration(2.04), 1e-12);
}

TEST(GroundMotion, BadRecordsNameFileAndLine) {
  const std::string path = std::string(HALFETI_BINARY_DIR) + "/bad_record.csv";
  {
    std::ofstream f(path);
    f << "# a comment\ntime,acc\n0,0\n0.02,abc\n";
  }
  try {
    excitation::read_record_csv(path, "g", 1.0, 0.0, 1.0, 0.0);
    FAIL();
  } catch (const UserError& e) {
    EXPECT_NE(std::string(e.what()).find("bad_record.csv:4: expected 'time, acceleration' numbers"),
              std::string::npos)
        << e.what();
  }
  {
    std::ofstream f(path);
    f << "time,acc\n0,0\n0,1\n";
  }
  EXPECT_THROW(excitation::read_record_csv(path, "g", 1.0, 0.0, 1.0, 0.0), UserError);
  EXPECT_THROW(excitation::read_record_csv("/no/such/file.csv", "g", 1.0, 0.0, 1.0, 0.0), UserError);
}
