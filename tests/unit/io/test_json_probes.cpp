#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "halfeti/core/error.hpp"
#include "halfeti/io/json.hpp"
#include "halfeti/io/probe_writer.hpp"

using namespace halfeti;

TEST(Json, WritesNestedObjectsInOrderAndEscapes) {
  io::Json j = io::Json::object();
  j.set("b", 1).set("a", "x\"y\n");
  io::Json arr = io::Json::array();
  arr.push(1.5).push(true).push(io::Json());
  j.set("list", arr);
  j.set("nan", std::nan(""));
  EXPECT_EQ(j.dump(0), "{\"b\":1,\"a\":\"x\\\"y\\n\",\"list\":[1.5,true,null],\"nan\":null}");
  j.set("b", 2);  // replaces, keeps its place
  EXPECT_EQ(j.dump(0).substr(0, 7), "{\"b\":2,");
}

TEST(ProbeWriter, RoundTrip) {
  const std::string path = std::string(HALFETI_BINARY_DIR) + "/probe_roundtrip.csv";
  {
    io::ProbeWriter w(path, {"p5", "tip_x"}, true);
    w.write(0.0, {998.1, 0.0});
    w.write(0.005, {1001.25, -1.5e-4});
    EXPECT_THROW(w.write(0.01, {1.0}), InternalError);
  }
  const auto t = io::read_probe_csv(path);
  ASSERT_EQ(t.names, (std::vector<std::string>{"t", "p5", "tip_x"}));
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_DOUBLE_EQ(t.column("p5")[1], 1001.25);
  EXPECT_DOUBLE_EQ(t.column("tip_x")[1], -1.5e-4);
  EXPECT_DOUBLE_EQ(t.column("t")[1], 0.005);
  std::remove(path.c_str());
}

TEST(ProbeWriter, RejectsNamesThatBreakTheCsv) {
  EXPECT_THROW(io::ProbeWriter("/dev/null", {"a,b"}, false), InternalError);
  // An output that cannot be written is an I/O error (exit status 6), not bad input.
  EXPECT_THROW(io::ProbeWriter("/nonexistent/dir/probes.csv", {"a"}, true), IoError);
}
