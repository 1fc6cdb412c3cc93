// The health log's bookkeeping (core/health.hpp): worst values by kind, the tally, the text form a checkpoint keeps.
#include <gtest/gtest.h>

#include <cmath>

#include "halfeti/core/error.hpp"
#include "halfeti/core/health.hpp"

using namespace halfeti;

namespace {
HealthEvent event(const std::string& kind, double t, long long step, bool fatal = false) {
  return health_event(t, step, kind, kind + " at step " + std::to_string(step), fatal);
}
}  // namespace

TEST(Health, AnEpisodeKeepsItsWorstValueWhereAndWhen) {
  HealthEvent e = event("density_variation", 0.1, 10);
  EXPECT_TRUE(std::isnan(e.worst));
  health_observe(e, 0.012, 0.1, 10, 1.0, 2.0);
  health_observe(e, 0.030, 0.2, 20, 3.0, 4.0);
  health_observe(e, 0.020, 0.3, 30, 5.0, 6.0);  // not worse: kept 0.030
  EXPECT_EQ(e.worst, 0.030);
  EXPECT_EQ(e.worst_time, 0.2);
  EXPECT_EQ(e.worst_step, 20);
  EXPECT_EQ(e.worst_x, 3.0);
  EXPECT_EQ(e.worst_y, 4.0);
  // A margin: the smaller spacing is the worse.
  HealthEvent s = event("spacing_collapse", 0.1, 10);
  health_observe(s, 0.4, 0.1, 10, 0, 0);
  health_observe(s, 0.2, 0.2, 20, 0, 0);
  health_observe(s, 0.3, 0.3, 30, 0, 0);
  EXPECT_EQ(s.worst, 0.2);
}

TEST(Health, TheTallyCountsEpisodesByKindAndWarningsApartFromTheFailure) {
  HealthLog log = {event("density_variation", 0.1, 10), event("spilled", 0.2, 20),
                   event("density_variation", 0.3, 30), event("nan", 0.4, 40, true)};
  health_observe(log[0], 0.02, 0.1, 10, 0, 0);
  health_observe(log[2], 0.05, 0.3, 30, 0, 0);
  const HealthTally t = tally(log);
  EXPECT_EQ(t.warnings, 3);
  ASSERT_EQ(t.kinds.size(), 3u);
  EXPECT_EQ(t.kinds.at("density_variation").episodes, 2);
  EXPECT_EQ(t.kinds.at("density_variation").first, &log[0]);
  EXPECT_EQ(t.kinds.at("density_variation").worst, &log[2]);  // 0.05 in the second episode
  EXPECT_TRUE(t.kinds.at("nan").fatal);
  EXPECT_EQ(warnings_line(t), "3 warnings (density_variation 2, spilled 1)");
  EXPECT_EQ(warnings_line(tally({})), "no warnings");
}

TEST(Health, TheTextFormReadsBackBitForBitIncludingUnmeasuredValues) {
  HealthLog log = {event("density_variation", 0.1 / 3.0, 12345), event("nan", 1.0 / 7.0, 99, true)};
  health_observe(log[0], 1.0 / 3.0, 0.7, 17, -0.1, 1e-300);
  log[0].message = "a message\twith a tab";
  const HealthLog back = decode_health_log(encode_health_log(log));
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[0].time, log[0].time);
  EXPECT_EQ(back[0].step, 12345);
  EXPECT_EQ(back[0].worst, log[0].worst);
  EXPECT_EQ(back[0].worst_time, 0.7);
  EXPECT_EQ(back[0].worst_step, 17);
  EXPECT_EQ(back[0].worst_y, 1e-300);
  EXPECT_EQ(back[0].message, "a message with a tab");
  EXPECT_TRUE(back[1].fatal);
  EXPECT_TRUE(std::isnan(back[1].worst));  // never measured: NaN survives the round trip
  EXPECT_THROW(decode_health_log("0x1p+0\t1\t0\n"), UserError);
}
