// HDF5 round trip at several rank counts: each rank writes a slab of a known global field; the file read back
// serially must hold every value at its global index, whatever the decomposition.
#include <gtest/gtest.h>
#include <mpi.h>

#include <fstream>
#include <sstream>

#include "halfeti/io/fields.hpp"
#include "halfeti/io/run_log.hpp"

using namespace halfeti;

namespace {
double global_value(long long i, int field) {
  return 0.25 * static_cast<double>(i) + 1000.0 * field;
}
}  // namespace

TEST(Fields, ParallelWriteSerialReadRoundTrip) {
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  const std::string dir = std::string(HALFETI_BINARY_DIR) + "/fields_roundtrip_np" + std::to_string(size);
  // Uneven counts, one rank possibly empty: rank r holds 3r + 1 points except the last, which holds none.
  const long long n_local = (size > 1 && rank == size - 1) ? 0 : 3 * rank + 1;
  long long offset = 0;
  MPI_Exscan(&n_local, &offset, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
  if (rank == 0) offset = 0;
  long long total = 0;
  MPI_Allreduce(&n_local, &total, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);

  std::vector<double> x(n_local), y(n_local), p(n_local);
  for (long long i = 0; i < n_local; ++i) {
    x[i] = global_value(offset + i, 0);
    y[i] = global_value(offset + i, 1);
    p[i] = global_value(offset + i, 2);
  }
  io::FieldSeries series(MPI_COMM_WORLD, dir, "fluid");
  // A vector (x, y, z per point) and integer ids beside the scalar.
  std::vector<double> v(3 * n_local);
  std::vector<std::int64_t> id(n_local);
  for (long long i = 0; i < n_local; ++i) {
    for (int c = 0; c < 3; ++c) v[3 * i + c] = global_value(offset + i, 3 + c);
    id[i] = (1LL << 40) + offset + i;  // past a float's exact integers
  }
  const std::vector<io::Field> fields = {io::Field::scalar("p", "Pa", p.data()),
                                         io::Field::vector("velocity", "m/s", v.data()),
                                         io::Field::ids("gid", id.data())};
  series.write(0.0, n_local, x.data(), y.data(), fields);
  for (auto& value : p) value += 1.0;
  const std::string second = series.write(0.05, n_local, x.data(), y.data(), fields);
  MPI_Barrier(MPI_COMM_WORLD);

  const auto d = io::read_field_file(second);
  EXPECT_DOUBLE_EQ(d.time, 0.05);
  ASSERT_EQ(static_cast<long long>(d.x.size()), total);
  for (long long i = 0; i < total; ++i) {
    EXPECT_EQ(d.x[i], global_value(i, 0));
    EXPECT_EQ(d.y[i], global_value(i, 1));
    EXPECT_EQ(d.field("p")[i], global_value(i, 2) + 1.0);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(d.field("velocity")[3 * i + c], global_value(i, 3 + c));
    EXPECT_EQ(static_cast<std::int64_t>(d.field("gid")[i]), (1LL << 40) + i);
  }
  EXPECT_EQ(d.names, (std::vector<std::string>{"p", "velocity", "gid"}));  // the order of writing
  EXPECT_EQ(d.field_info("p").unit, "Pa");
  EXPECT_EQ(d.field_info("velocity").components, 3);
  EXPECT_EQ(d.field_info("velocity").unit, "m/s");
  EXPECT_TRUE(d.field_info("gid").integer);
  EXPECT_FALSE(d.field_info("p").integer);
  // The XDMF series names both frames and their times.
  std::ifstream xdmf(series.xdmf_path());
  std::stringstream text;
  text << xdmf.rdbuf();
  EXPECT_NE(text.str().find("fluid_000000.h5:/p"), std::string::npos);
  EXPECT_NE(text.str().find("<Time Value=\"0.05\"/>"), std::string::npos);
  EXPECT_NE(text.str().find("Polyvertex"), std::string::npos);
  EXPECT_NE(text.str().find("AttributeType=\"Vector\""), std::string::npos);
  EXPECT_NE(text.str().find("Dimensions=\"" + std::to_string(total) + " 3\""), std::string::npos);
  EXPECT_NE(text.str().find("<Information Name=\"unit\" Value=\"m/s\"/>"), std::string::npos);
  EXPECT_NE(text.str().find("NumberType=\"Int\" Precision=\"8\" Format=\"HDF\">fluid_000001.h5:/gid"),
            std::string::npos);
}

TEST(Fields, MeshSeriesCarriesCells) {
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  const std::string dir = std::string(HALFETI_BINARY_DIR) + "/fields_mesh_np" + std::to_string(size);
  // Rank 0 holds a 2-cell strip of 6 nodes; other ranks hold nothing.
  std::vector<double> x, y, u, stress;
  std::vector<std::int64_t> cells;
  if (rank == 0) {
    x = {0, 1, 2, 0, 1, 2};
    y = {0, 0, 0, 1, 1, 1};
    u = {0, 1, 2, 3, 4, 5};
    cells = {0, 1, 4, 3, 1, 2, 5, 4};
    stress = {7.0, 8.0};  // one per cell
  }
  io::CellBlock block{"Quadrilateral", 4, cells.data(), cells.size() / 4};
  io::FieldSeries series(MPI_COMM_WORLD, dir, "plate");
  const std::string f = series.write(1.0, x.size(), x.data(), y.data(),
                                     {io::Field::scalar("ux", "m", u.data()),
                                      io::Field::scalar("von_mises", "Pa", stress.data(), io::Center::kCell)},
                                     &block);
  MPI_Barrier(MPI_COMM_WORLD);
  const auto d = io::read_field_file(f);
  EXPECT_EQ(d.cells, (std::vector<std::int64_t>{0, 1, 4, 3, 1, 2, 5, 4}));
  EXPECT_EQ(d.field("ux")[5], 5.0);
  EXPECT_EQ(d.field("von_mises"), (std::vector<double>{7.0, 8.0}));
  EXPECT_EQ(d.field_info("von_mises").center, io::Center::kCell);
  std::ifstream xdmf(series.xdmf_path());
  std::stringstream text;
  text << xdmf.rdbuf();
  EXPECT_NE(text.str().find("<Attribute Name=\"von_mises\" AttributeType=\"Scalar\" Center=\"Cell\">"),
            std::string::npos);
}
