// Field output: parallel HDF5, one file per output time, each rank writing its slab at an offset from a collective
// scan, plus one XDMF file per series that ParaView opens as a time series (Cabana's HDF5ParticleOutput idea).
// The reader opens the same files, so every writer has a round-trip test. Each file is written under a temporary
// name and renamed when complete, so a file of the series is whole or absent.
#pragma once

#include <mpi.h>

#include <cstdint>
#include <string>
#include <vector>

namespace halfeti::io {

// Where a field lives: one value per point or one per cell of a mesh series.
enum class Center { kNode, kCell };

// One field of a frame: a scalar, a vector (three components, z = 0 in the 2-D model, so that ParaView's glyphs
// and warps take it as it is) or integer ids, with its unit (SI; "-" for a pure number, "" for an id), which goes
// to the HDF5 dataset's `unit` attribute and to an XDMF Information element.
struct Field {
  std::string name;
  std::string unit;
  bool is_integer = false;                // the same on every rank (a rank without points passes no data)
  const double* real = nullptr;           // `components` values per point (or cell), one point after another
  const std::int64_t* integer = nullptr;  // or one integer per point (or cell)
  int components = 1;
  Center center = Center::kNode;

  static Field scalar(std::string name, std::string unit, const double* values,
                      Center center = Center::kNode) {
    return {std::move(name), std::move(unit), false, values, nullptr, 1, center};
  }
  static Field vector(std::string name, std::string unit, const double* xyz, Center center = Center::kNode) {
    return {std::move(name), std::move(unit), false, xyz, nullptr, 3, center};
  }
  static Field ids(std::string name, const std::int64_t* values, Center center = Center::kNode) {
    return {std::move(name), "", true, nullptr, values, 1, center};
  }
};

// What a stored field is, as the XDMF and a reader need it (its values aside).
struct FieldLayout {
  std::string unit;
  int components = 1;
  Center center = Center::kNode;
  bool integer = false;
};

// Cells of a mesh series: `nodes_per_cell` global point indices per local cell, XDMF topology name
// ("Quadrilateral", "Quadrilateral_9", "Polyline", ...).
struct CellBlock {
  std::string xdmf_topology;
  int nodes_per_cell = 0;
  const std::int64_t* connectivity = nullptr;  // n_local_cells * nodes_per_cell global point indices
  std::size_t n_local_cells = 0;
};

class FieldSeries {
 public:
  // Collective over `comm`. Files go to `dir/<name>_NNNNNN.h5`, the series to `dir/<name>.xdmf`.
  FieldSeries(MPI_Comm comm, std::string dir, std::string name);

  // Collective: every rank passes its local points (possibly none). Without cells the points are a cloud
  // (Polyvertex). Returns the path of the file written.
  // Cell fields need cells.
  std::string write(double time, std::size_t n_local, const double* x, const double* y,
                    const std::vector<Field>& fields, const CellBlock* cells = nullptr);

  // Collective: continue the series found in dir (a restart into the run's own folder): its files up to `time`
  // are kept, later ones removed, and the next write follows them.
  void resume(double time);

  int frames() const { return static_cast<int>(frames_.size()); }
  const std::string& xdmf_path() const { return xdmf_path_; }

 private:
  struct Frame {
    double time;
    std::string file;  // relative to dir
    long long n_points, n_cells;
    std::vector<std::string> names;    // the fields, in their order of writing
    std::vector<FieldLayout> layouts;  // aligned with names
    std::string topology;
    int nodes_per_cell;
  };
  void write_xdmf() const;

  MPI_Comm comm_;
  std::string dir_, name_, xdmf_path_;
  std::vector<Frame> frames_;
};

// A whole frame read back (serially, any rank).
struct FieldFrameData {
  using Info = FieldLayout;
  double time = 0.0;
  std::vector<std::string> names;  // fields in their order of writing, without x and y
  std::vector<Info> info;          // aligned with names
  std::vector<double> x, y;
  std::vector<std::vector<double>> values;  // aligned with names: components per point (cell); ids exact
  std::vector<std::int64_t> cells;          // empty for point clouds
  std::string topology;                     // XDMF topology of the cells (with cells)
  int nodes_per_cell = 0;
  const std::vector<double>& field(const std::string& name) const;
  const Info& field_info(const std::string& name) const;
};
FieldFrameData read_field_file(const std::string& path);

// Collective: rank 0 renames `from` to `to` (a file written under a temporary name, now complete); an IoError on
// every rank if it cannot.
void rename_on_root(MPI_Comm comm, const std::string& from, const std::string& to);

}  // namespace halfeti::io
