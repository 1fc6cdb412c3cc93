// `halfeti cable`: JSON output and user errors.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <sstream>

#include "halfeti/cable/cable_tool.hpp"
#include "halfeti/core/error.hpp"

namespace halfeti::cable {
namespace {

std::vector<std::string> paper_args(const std::string& length_option, const std::string& value) {
  return {"--from",  "0,0.01", "--to",           "0.1485,0.08", "--modulus",   "1.14e6",
          "--area",  "4e-6",   "--density",      "1150",        "--count",     "3",
          "--depth", "0.15",   "--submerged-in", "1000",        length_option, value};
}

YAML::Node run(const std::vector<std::string>& args) {
  std::ostringstream out;
  EXPECT_EQ(run_cable_tool(args, out), 0);
  return YAML::Load(out.str());  // JSON is YAML
}

TEST(CableTool, TensionStressModeFindsTheUnstretchedLength) {
  const YAML::Node j = run(paper_args("--tension-stress", "135e3"));
  EXPECT_NEAR(j["unstretched_length"].as<double>(), 0.14679, 5e-5);
  EXPECT_NEAR(j["tension_to"]["stress"].as<double>(), 135e3, 1e-3);
  EXPECT_NEAR(j["tension_to"]["tension_per_cable"].as<double>(), 0.54, 1e-8);
  EXPECT_NEAR(j["tension_to"]["tension_per_depth"].as<double>(), 10.8, 1e-8);
  EXPECT_LT(j["tension_from"]["stress"].as<double>(), 135e3);
  EXPECT_EQ(j["state"].as<std::string>(), "taut");
  EXPECT_NEAR(j["chord"].as<double>(), 0.164171, 1e-6);
  EXPECT_NEAR(j["axial_stiffness_per_depth"].as<double>(), 91.2, 1e-9);
  EXPECT_GT(j["tension_components_from"]["Tx"].as<double>(), 0.0);
  EXPECT_GE(j["sag"].as<double>(), 0.0);
  const YAML::Node k = j["tangent_stiffness"];
  ASSERT_EQ(k.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    ASSERT_EQ(k[i].size(), 4u);
    for (int m = 0; m < 4; ++m) EXPECT_NEAR(k[i][m].as<double>(), k[m][i].as<double>(), 1e-8);
    EXPECT_GT(k[i][i].as<double>(), 0.0);
  }
}

TEST(CableTool, UnstretchedLengthMode) {
  const YAML::Node j = run(paper_args("--unstretched-length", "0.162"));
  EXPECT_DOUBLE_EQ(j["unstretched_length"].as<double>(), 0.162);
  EXPECT_NEAR(j["tension_to"]["stress"].as<double>(), 15341.0, 5.0);
}

TEST(CableTool, HelpPrintsUsage) {
  std::ostringstream out;
  EXPECT_EQ(run_cable_tool({"--help"}, out), 0);
  EXPECT_NE(out.str().find("--tension-stress"), std::string::npos);
}

void expect_user_error(const std::vector<std::string>& args, const std::string& mentions) {
  std::ostringstream out;
  try {
    run_cable_tool(args, out);
    ADD_FAILURE() << "no error; expected one mentioning " << mentions;
  } catch (const UserError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(mentions), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << "one line: " << what;
  }
}

TEST(CableTool, BadInputIsAUserErrorNamingTheOption) {
  std::vector<std::string> a = paper_args("--unstretched-length", "0.162");
  auto with = [&](const std::string& option, const std::string& value) {
    std::vector<std::string> b = a;
    for (std::size_t i = 0; i + 1 < b.size(); ++i)
      if (b[i] == option) b[i + 1] = value;
    return b;
  };
  expect_user_error(with("--area", "abc"), "--area");
  expect_user_error(with("--modulus", "-5"), "--modulus");
  expect_user_error(with("--modulus", "0"), "--modulus");
  expect_user_error(with("--from", "0;0.01"), "--from");
  expect_user_error(with("--count", "2.5"), "--count");
  expect_user_error(with("--unstretched-length", "1e400"), "--unstretched-length");
  std::vector<std::string> missing_value(a.begin(), a.end() - 1);
  expect_user_error(missing_value, "--unstretched-length");
  std::vector<std::string> both = a;
  both.insert(both.end(), {"--tension-stress", "1e5"});
  expect_user_error(both, "exactly one");
  std::vector<std::string> neither(a.begin(), a.end() - 2);
  expect_user_error(neither, "exactly one");
  std::vector<std::string> unknown = a;
  unknown.insert(unknown.end(), {"--colour", "red"});
  expect_user_error(unknown, "--colour");
  std::vector<std::string> no_modulus = a;
  no_modulus.erase(no_modulus.begin() + 4, no_modulus.begin() + 6);
  expect_user_error(no_modulus, "--modulus");
}

}  // namespace
}  // namespace halfeti::cable
