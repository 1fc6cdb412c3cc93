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
double global_value(long long i, int field) { return 0.25 * static_cast<double>(i) + 1000.0 * field; }
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
  series.write(0.0, n_local, x.data(), y.data(), {{"p", p.data()}});
  for (auto& v : p) v += 1.0;
  const std::string second = series.write(0.05, n_local, x.data(), y.data(), {{"p", p.data()}});
  MPI_Barrier(MPI_COMM_WORLD);

  const auto d = io::read_field_file(second);
  EXPECT_DOUBLE_EQ(d.time, 0.05);
  ASSERT_EQ(static_cast<long long>(d.x.size()), total);
  for (long long i = 0; i < total; ++i) {
    EXPECT_EQ(d.x[i], global_value(i, 0));
    EXPECT_EQ(d.y[i], global_value(i, 1));
    EXPECT_EQ(d.field("p")[i], global_value(i, 2) + 1.0);
  }
  // The XDMF series names both frames and their times.
  std::ifstream xdmf(series.xdmf_path());
  std::stringstream text;
  text << xdmf.rdbuf();
  EXPECT_NE(text.str().find("fluid_000000.h5:/p"), std::string::npos);
  EXPECT_NE(text.str().find("<Time Value=\"0.05\"/>"), std::string::npos);
  EXPECT_NE(text.str().find("Polyvertex"), std::string::npos);
}

TEST(Fields, MeshSeriesCarriesCells) {
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  const std::string dir = std::string(HALFETI_BINARY_DIR) + "/fields_mesh_np" + std::to_string(size);
  // Rank 0 holds a 2-cell strip of 6 nodes; other ranks hold nothing.
  std::vector<double> x, y, u;
  std::vector<std::int64_t> cells;
  if (rank == 0) {
    x = {0, 1, 2, 0, 1, 2};
    y = {0, 0, 0, 1, 1, 1};
    u = {0, 1, 2, 3, 4, 5};
    cells = {0, 1, 4, 3, 1, 2, 5, 4};
  }
  io::CellBlock block{"Quadrilateral", 4, cells.data(), cells.size() / 4};
  io::FieldSeries series(MPI_COMM_WORLD, dir, "plate");
  const std::string f = series.write(1.0, x.size(), x.data(), y.data(), {{"ux", u.data()}}, &block);
  MPI_Barrier(MPI_COMM_WORLD);
  const auto d = io::read_field_file(f);
  EXPECT_EQ(d.cells, (std::vector<std::int64_t>{0, 1, 4, 3, 1, 2, 5, 4}));
  EXPECT_EQ(d.field("ux")[5], 5.0);
}
