// The schema resolver alone: defaults, ranges, unknown keys, variants, overrides.
#include <gtest/gtest.h>

#include "halfeti/core/error.hpp"
#include "halfeti/core/registry.hpp"
#include "halfeti/core/scene.hpp"

using namespace halfeti;
using scene::Key;
using scene::Schema;

namespace {

std::shared_ptr<Schema> test_schema() {
  auto inner = std::make_shared<Schema>();
  inner->add(Key::real("spacing", "dx", "m").required().positive());
  inner->add(Key::real("delta", "delta-SPH coefficient").def(0.1).in(0.0, 1.0));
  inner->add(Key::choice("scheme", "scheme", {"delta", "standard"}).def("delta"));
  inner->add(Key::integer("every", "steps").def(10).at_least(1));
  inner->add(Key::point("origin", "corner", "m").def_point(0.0, 0.0));
  auto root = std::make_shared<Schema>();
  root->add(Key::section("fluid", "water", inner));
  root->add(Key::boolean("verbose", "chatty").def(false));
  return root;
}

std::string error_of(const std::string& text, const std::vector<std::string>& sets = {}) {
  try {
    scene::parse_scene(text, "t.yaml", sets, *test_schema());
  } catch (const UserError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(Schema, FillsDefaultsInSchemaOrder) {
  const auto s = scene::parse_scene("fluid: {spacing: 0.002}\n", "t.yaml", {}, *test_schema());
  const auto f = s.root().section("fluid");
  EXPECT_DOUBLE_EQ(f.real("spacing"), 0.002);
  EXPECT_DOUBLE_EQ(f.real("delta"), 0.1);
  EXPECT_EQ(f.string("scheme"), "delta");
  EXPECT_EQ(f.integer("every"), 10);
  EXPECT_FALSE(s.root().boolean("verbose"));
  // The resolved text runs again as it is.
  const auto again = scene::parse_scene(s.resolved_text(), "r.yaml", {}, *test_schema());
  EXPECT_EQ(again.resolved_text(), s.resolved_text());
}

TEST(Schema, AbsentSectionStaysAbsent) {
  const auto s = scene::parse_scene("verbose: true\n", "t.yaml", {}, *test_schema());
  EXPECT_FALSE(s.root().has("fluid"));
}

TEST(Schema, ErrorsNameFileLineKeyFoundAndExpected) {
  EXPECT_EQ(error_of("fluid:\n  spacing: -1\n"),
            "t.yaml:2:12: fluid.spacing: expected a number > 0 (m), found '-1'");
  EXPECT_EQ(error_of("fluid:\n  spacing: 1\n  delat: 0.2\n"),
            "t.yaml:3:3: unknown key 'fluid.delat'; did you mean 'delta'?");
  EXPECT_EQ(error_of("fluid:\n  delta: 0.2\n"),
            "t.yaml:2:3: fluid.spacing: required key missing: expected a number > 0 (m)");
  EXPECT_EQ(error_of("fluid: {spacing: 1, every: 2.5}\n"),
            "t.yaml:1:28: fluid.every: expected a whole number >= 1, found '2.5'");
  EXPECT_EQ(error_of("fluid: {spacing: 1, origin: [1]}\n"),
            "t.yaml:1:29: fluid.origin: expected a point [x, y] (m), found a list");
  EXPECT_EQ(error_of("verbose: maybe\n"), "t.yaml:1:10: verbose: expected true or false, found 'maybe'");
  EXPECT_EQ(error_of("fluid: 3\n"), "t.yaml:1:8: fluid: expected a section (key: value lines), found '3'");
}

TEST(Schema, OverridesGoThroughTheSameChecks) {
  const auto s =
      scene::parse_scene("fluid: {spacing: 0.002}\n", "t.yaml", {"fluid.delta=0.3"}, *test_schema());
  EXPECT_DOUBLE_EQ(s.root().section("fluid").real("delta"), 0.3);
  EXPECT_EQ(error_of("fluid: {spacing: 0.002}\n", {"fluid.delta=2"}),
            "--set fluid.delta=2: fluid.delta: expected a number in [0, 1], found '2'");
  EXPECT_EQ(error_of("fluid: {spacing: 0.002}\n", {"fluid.sheme=standard"}),
            "--set fluid.sheme=standard: unknown key 'fluid.sheme'; did you mean 'scheme'?");
  EXPECT_NE(error_of("fluid: {spacing: 0.002}\n", {"fluid.delta"}).find("expected key.path=value"),
            std::string::npos);
}

TEST(Schema, ClosestNameOnlyForNearMisses) {
  EXPECT_EQ(scene::closest_name("spacnig", {"spacing", "delta"}), "spacing");
  EXPECT_EQ(scene::closest_name("zzzzzz", {"spacing", "delta"}), "");
}

TEST(Registry, VariantsComeFromTheRegistry) {
  using Factory = std::function<int(const scene::Node&)>;
  Registry<Factory> r;
  auto one = std::make_shared<Schema>();
  one->add(Key::real("value", "v").required());
  r.add("one", "first", one, [](const scene::Node& n) { return static_cast<int>(n.real("value")); });
  r.add("two", "second", std::make_shared<Schema>(), [](const scene::Node&) { return 2; });
  auto root = std::make_shared<Schema>();
  root->add(Key::section("thing", "a thing", r.section_schema("kind", "")));
  const auto s = scene::parse_scene("thing: {kind: one, value: 7}\n", "t.yaml", {}, *root);
  const auto t = s.root().section("thing");
  EXPECT_EQ(r.get(t.string("kind")).make(t), 7);
  try {
    scene::parse_scene("thing: {kind: two, value: 7}\n", "t.yaml", {}, *root);
    FAIL() << "a key of another variant was accepted";
  } catch (const UserError& e) {
    EXPECT_EQ(std::string(e.what()),
              "t.yaml:1:20: unknown key 'thing.value' for kind 'two'; expected one of: kind");
  }
  EXPECT_THROW(r.add("one", "again", one, nullptr), InternalError);
}

TEST(Schema, ReferenceListsEveryKey) {
  const std::string md = scene::reference_markdown(*test_schema(), "ref");
  for (const char* k : {"spacing", "delta", "scheme", "every", "origin", "verbose"})
    EXPECT_NE(md.find(std::string("`") + k + "`"), std::string::npos) << k;
}

TEST(Schema, ImpliedSectionAppearsOnlyWithItsSiblings) {
  auto inner = std::make_shared<Schema>();
  inner->add(Key::real("k", "a knob").def(2.0));
  auto root = std::make_shared<Schema>();
  root->add(Key::section("a", "a part", std::make_shared<Schema>()));
  root->add(Key::section("b", "another part", std::make_shared<Schema>()));
  root->add(Key::section("ab", "what joins them", inner).implied_by({"a", "b"}));
  EXPECT_FALSE(scene::parse_scene("a: {}\n", "t.yaml", {}, *root).root().has("ab"));
  const auto both = scene::parse_scene("a: {}\nb: {}\n", "t.yaml", {}, *root);
  ASSERT_TRUE(both.root().has("ab"));
  EXPECT_DOUBLE_EQ(both.root().section("ab").real("k"), 2.0);
}
