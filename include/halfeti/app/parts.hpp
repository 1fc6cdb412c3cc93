// The parts a run is built from: only those the scene names (DESIGN.md principle 2). `check` fills in the
// parameters (which cross-checks the scene); `run` also builds the parts themselves.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "halfeti/app/structure_section.hpp"
#include "halfeti/cable/cable_element.hpp"
#include "halfeti/core/communicator.hpp"
#include "halfeti/core/scene.hpp"
#include "halfeti/coupling/contact_coupling.hpp"
#include "halfeti/excitation/ground_motion.hpp"
#include "halfeti/sph/fluid.hpp"
#include "halfeti/sph/params.hpp"
#include "halfeti/structure/plate_solver.hpp"

namespace halfeti::app {

struct Parts {
  std::string scene_dir;  // anchors relative paths in the scene
  double gravity = 9.81;
  std::unique_ptr<excitation::GroundMotion> motion;

  std::optional<sph::FluidParams> fluid_params;  // the scene has `fluid:`
  std::unique_ptr<sph::Fluid> fluid;             // built for a run

  std::optional<StructureSetup> structure_setup;  // the scene has `structure:`
  std::vector<CableSetup> cable_setups;           // the scene's `cables:`
  // The structure lives on world rank 0 (its own communicator); other ranks hold nulls and receive what probes
  // and the coupling need by broadcast.
  Communicator structure_comm;
  std::unique_ptr<structure::PlateSolver> plate;
  std::vector<std::unique_ptr<cable::CableElement>> cables;
  bool structure_rank = false;

  std::optional<coupling::CouplingParameters> coupling_params;  // the scene has water and a plate
  sph::LatticeOffsets plate_offsets;  // how the water's initial lattice sees the plate's faces
  std::unique_ptr<coupling::ContactCoupling> coupling;  // on every rank (collective)
  coupling::Corrections corrections;                    // this rank's, reused every step

  // Throw UserError naming `who` when the scene lacks the part.
  const sph::FluidParams& require_fluid(const std::string& who) const;
  const StructureSetup& require_structure(const std::string& who) const;
  int cable_index(const std::string& who, const std::string& name) const;
};

// Collective: builds the parts whose parameters `parts` holds: the water, the plate and its cables (on the first
// structure.ranks ranks of `comm`; the others hold nulls), and the coupling between them.
void build_parts(Parts& parts, MPI_Comm comm, bool trace_coupling);
void build_structure(Parts& parts, MPI_Comm comm);  // the plate and cables alone (part of build_parts)

}  // namespace halfeti::app
