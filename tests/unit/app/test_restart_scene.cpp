// Whether a continued run's scene may continue a checkpoint's (app/restart.hpp): only scene.end_time,
// scene.description and output.* may change; a number is the same number however it is written.
#include <gtest/gtest.h>

#include "halfeti/app/restart.hpp"

using halfeti::app::changed_physics_key;

TEST(RestartScene, ANumberWrittenAnotherWayIsTheSameNumber) {
  // The checkpoint holds the scene's text, a --set on the command line another spelling of the same value.
  EXPECT_EQ(changed_physics_key("fluid: {spacing: 0.00182500, sound_speed: 50}",
                                "fluid: {spacing: 0.001825, sound_speed: 50.0}"),
            "");
  EXPECT_EQ(changed_physics_key("fluid: {spacing: 1.5e-3}", "fluid: {spacing: 0.0015}"), "");
}

TEST(RestartScene, AnotherValueIsRefusedWithBoth) {
  const std::string changed =
      changed_physics_key("fluid: {spacing: 0.001825}", "fluid: {spacing: 0.0018250001}");
  EXPECT_NE(changed.find("fluid.spacing"), std::string::npos) << changed;
  EXPECT_NE(changed.find("0.0018250001"), std::string::npos) << changed;
  EXPECT_NE(changed_physics_key("fluid: {scheme: delta}", "fluid: {scheme: standard}"), "");
  EXPECT_NE(changed_physics_key("fluid: {spacing: 0.001}", "fluid: {spacing: 0.001x}"), "");
}

TEST(RestartScene, TheEndTheDescriptionAndTheOutputsMayChange) {
  EXPECT_EQ(changed_physics_key("scene: {end_time: 1, description: a}\noutput: {field_interval: 0.1}",
                                "scene: {end_time: 2, description: b}\noutput: {field_interval: 0}"),
            "");
}
