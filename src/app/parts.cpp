// The parts of a run: their parameters from the scene (what `halfeti check` reads), and the plate with its cables on
// the structure's ranks.
#include "halfeti/app/parts.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "halfeti/app/coupling_section.hpp"
#include "halfeti/app/fluid_section.hpp"
#include "halfeti/app/simulation.hpp"
#include "halfeti/core/files.hpp"
#include "halfeti/coupling/lattice_alignment.hpp"
#include "halfeti/excitation/excitation_scene.hpp"

namespace halfeti::app {

const sph::FluidParams& Parts::require_fluid(const std::string& who) const {
  if (!fluid_params)
    HALFETI_USER_ERROR(who << ": this probe reads the water, but the scene has no `fluid:` section");
  return *fluid_params;
}

const StructureSetup& Parts::require_structure(const std::string& who) const {
  if (!structure_setup)
    HALFETI_USER_ERROR(who << ": this probe reads the plate, but the scene has no `structure:` section");
  return *structure_setup;
}

int Parts::cable_index(const std::string& who, const std::string& name) const {
  for (size_t i = 0; i < cable_setups.size(); ++i)
    if (cable_setups[i].name == name) return static_cast<int>(i);
  std::string known;
  for (const auto& c : cable_setups) known += (known.empty() ? "" : ", ") + c.name;
  HALFETI_USER_ERROR(who << ": no cable named '" << name << "'"
                         << (known.empty() ? " (the scene has no cables)" : " (cables: " + known + ")"));
}

namespace {

// The largest |a_g| over the run, sampled finely enough for records (0.02 s) and pulses.
double peak_ground_acceleration(const excitation::GroundMotion& m, double end) {
  double peak = 0.0;
  const int n = std::max(2000, static_cast<int>(end / 1e-3));
  for (int i = 0; i <= n; ++i) peak = std::max(peak, std::abs(m.acceleration(end * i / n)));
  return peak;
}

void read_parameters(const scene::Scene& scene, Parts& parts) {
  const scene::Node root = scene.root();
  parts.scene_dir = directory_of(scene.file);
  // The name names the output folder out/<name>: one folder name, not a path.
  const std::string name = root.section("scene").string("name");
  const bool plain =
      !name.empty() && name != "." && name != ".." && std::all_of(name.begin(), name.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
      });
  if (!plain)
    HALFETI_USER_ERROR("scene.name '" << name
                                      << "': letters, digits, '_', '-' and '.' only (it names the folder "
                                         "out/<name>)");
  parts.gravity = root.real("gravity");
  parts.motion = excitation::make_ground_motion(root.section("excitation"), parts.scene_dir);
  const double end = root.section("scene").real("end_time");
  if (root.has("fluid"))
    parts.fluid_params = fluid_params(root, peak_ground_acceleration(*parts.motion, end));
  if (root.has("structure")) parts.structure_setup = structure_setup(root);
  if (!root.list("cables").empty() && !parts.structure_setup)
    HALFETI_USER_ERROR("cables: need a `structure:` to hold (the plate they attach to)");
  if (parts.structure_setup)
    parts.cable_setups =
        cable_setups(root, *parts.structure_setup, parts.fluid_params ? parts.fluid_params->density : 0.0);
  if (parts.fluid_params && parts.structure_setup) {
    parts.coupling_params = coupling_params(root);
    // The water fills its blocks except where the plate stands, as its lattice resolves it.
    auto& fp = *parts.fluid_params;
    const auto aligned = coupling::align_plate_with_lattice(
        parts.structure_setup->params.geometry, fp.spacing, fp.water.front().x0, fp.water.front().y0);
    parts.plate_offsets = aligned.offsets;
    fp.exclusions.push_back(aligned.exclusion);
  }
}
}  // namespace

std::vector<ProbeColumn> build_parameters(const scene::Scene& scene, Parts& parts) {
  // Checks across keys name the key path; the scene file is added here.
  try {
    read_parameters(scene, parts);
    return make_probes(scene.root(), parts);
  } catch (const UserError& e) {
    const std::string what = e.what();
    if (what.rfind(scene.file, 0) == 0) throw;
    throw UserError(scene.file + ": " + what);
  }
}

void build_parts(Parts& parts, MPI_Comm comm, bool trace_coupling) {
  if (parts.fluid_params)
    parts.fluid = std::make_unique<sph::Fluid>(comm, *parts.fluid_params, parts.motion.get());
  if (parts.structure_setup) build_structure(parts, comm);
  if (!parts.coupling_params) return;
  auto& cp = *parts.coupling_params;
  cp.trace = trace_coupling;
  const auto& fluid = *parts.fluid;
  cp.density = fluid.params().density;
  cp.sound_speed = fluid.sound_speed();
  cp.spacing = fluid.params().spacing;
  parts.coupling = std::make_unique<coupling::ContactCoupling>(comm, parts.plate.get(), cp);
  if (cp.plate_wall) {
    parts.fluid->set_plate_offsets(parts.plate_offsets);
    parts.fluid->set_plate_outline(parts.coupling->plate_outline());  // and its mid-line as the barrier
    parts.fluid->set_plate_free_surface(cp.plate_wall_free_surface);
  } else {
    parts.fluid->set_barriers(parts.coupling->outline());
  }
}

// The plate and its cables live on the first structure.ranks world ranks (the structure's own communicator; rank 0
// is always one of them and holds what probes and outputs read).
void build_structure(Parts& parts, MPI_Comm comm) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  const bool member = rank < parts.structure_setup->ranks;
  MPI_Comm sub = MPI_COMM_NULL;
  MPI_Comm_split(comm, member ? 0 : MPI_UNDEFINED, rank, &sub);
  parts.structure_comm = Communicator::adopt(sub);
  parts.structure_rank = member;
  if (!parts.structure_rank) return;
  const StructureSetup& s = *parts.structure_setup;
  parts.plate =
      std::make_unique<structure::PlateSolver>(parts.structure_comm.get(), s.params, parts.motion.get());
  for (const auto& l : s.point_loads) parts.plate->add_point_load(parts.plate->mesh().node(l.node), l.force);
  for (const auto& c : parts.cable_setups) {
    const int node = parts.plate->mesh().node(c.node);
    parts.cables.push_back(std::make_unique<cable::CableElement>(
        c.anchor, node, cable::cable_properties(c.set, c.unstretched_length)));
    parts.plate->add_nodal_element(parts.cables.back().get());
  }
  // One evaluation at the initial geometry, so that t = 0 probes read the initial tension.
  for (auto& c : parts.cables) {
    const int node = c->nodes()[0];
    Eigen::VectorXd f;
    Eigen::MatrixXd k;
    c->evaluate({parts.plate->position(node)}, f, k);
  }
}

}  // namespace halfeti::app
