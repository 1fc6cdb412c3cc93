#include "halfeti/app/commands.hpp"

#include <iostream>
#include <memory>
#include <sstream>

#include "halfeti/app/cli.hpp"
#include "halfeti/app/petsc_session.hpp"
#include "halfeti/app/run_size.hpp"
#include "halfeti/app/scene_schema.hpp"
#include "halfeti/app/simulation.hpp"
#include "halfeti/cable/cable_tool.hpp"
#include "halfeti/core/collective.hpp"
#include "halfeti/core/error.hpp"
#include "halfeti/core/scene.hpp"
#include "halfeti/io/compare_tool.hpp"

namespace halfeti::app {

int execute(const std::vector<std::string>& args, MPI_Comm comm) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  const Command cmd = parse_command_line(args);
  switch (cmd.kind) {
    case Command::Kind::kHelp:
      if (rank == 0) std::cout << usage_text();
      return 0;
    case Command::Kind::kVersion:
      if (rank == 0) std::cout << version_text() << "\n";
      return 0;
    case Command::Kind::kReference:
      if (rank == 0) std::cout << scene::reference_markdown(*scene_schema(), "halfeti scene reference");
      return 0;
    case Command::Kind::kCable:
    case Command::Kind::kCompare: {
      // Serial tools: rank 0 answers, the others share its outcome (its error, if any, on every rank).
      std::ostringstream out;
      int status = 0;
      collective_outcome(comm, 0, rank == 0, [&] {
        status = cmd.kind == Command::Kind::kCable ? cable::run_cable_tool(cmd.tool_args, out)
                                                   : io::run_compare_tool(cmd.tool_args, out);
      });
      MPI_Bcast(&status, 1, MPI_INT, 0, comm);
      if (rank == 0) std::cout << out.str();
      return status;
    }
    case Command::Kind::kCheck: {
      scene::Scene s = scene::load_scene(cmd.scene, cmd.overrides, *scene_schema(), comm);
      Parts parts;
      build_parameters(s, parts);
      int ranks = 1;
      MPI_Comm_size(comm, &ranks);
      const SizeEstimate size = estimate_size(s, parts, ranks, cmd.max_memory);
      if (rank == 0)
        std::cout << "# " << cmd.scene << ": ok; " << size.describe() << " on " << ranks << " rank(s)\n"
                  << s.resolved_text();
      return 0;
    }
    case Command::Kind::kRun: {
      scene::Scene s = scene::load_scene(cmd.scene, cmd.overrides, *scene_schema(), comm);
      if (!cmd.petsc_args.empty() && !s.root().has("structure"))
        HALFETI_USER_ERROR("PETSc options were given after '--', but the scene has no structure to use them");
      std::unique_ptr<PetscSession> petsc;
      if (s.root().has("structure")) petsc = std::make_unique<PetscSession>(cmd.petsc_args);
      RunOptions opts;
      opts.out_dir = cmd.out_dir;
      opts.petsc_args = cmd.petsc_args;
      opts.restart = cmd.restart;
      opts.overwrite = cmd.overwrite;
      opts.max_wall = cmd.max_wall;
      opts.max_memory = cmd.max_memory;
      opts.trace_coupling = cmd.trace_coupling;
      opts.command_line = "halfeti";
      for (const auto& a : args) opts.command_line += " " + a;
      int status = 0;
      {
        Simulation sim(comm, std::move(s), opts);
        status = sim.run();
      }
      if (petsc && rank == 0) {
        const auto unused = petsc->unused_options();
        if (!unused.empty()) {
          std::string names;
          for (const auto& u : unused) names += (names.empty() ? "" : ", ") + u;
          std::cerr
              << "halfeti: warning: PETSc options given after '--' that nothing used (misspelt, or for a "
                 "solver not in use): "
              << names << "\n";
        }
      }
      return status;
    }
  }
  return 0;
}

}  // namespace halfeti::app
