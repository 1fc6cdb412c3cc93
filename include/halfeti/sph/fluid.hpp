// The water: weakly compressible delta-SPH particles distributed over MPI ranks by cells (DESIGN.md, "One time
// step", fluid part). One force evaluation per step; leap-frog in its kick-drift form:
//   compute_forces()   halo, neighbours, density_gradient, forces (and dt)
//   [caller may set extra_acceleration_x/y(): Delta C of eq. 4, per owned particle]
//   advance()          integrate, health, rebalance, migrate
// step() does both. Results are bitwise identical on any number of ranks.
#pragma once

#include <mpi.h>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "halfeti/core/communicator.hpp"
#include "halfeti/core/particle_arrays.hpp"
#include "halfeti/core/timers.hpp"
#include "halfeti/excitation/ground_motion.hpp"
#include "halfeti/parallel/cell_grid.hpp"
#include "halfeti/parallel/halo_plan.hpp"
#include "halfeti/sph/delta_sph.hpp"
#include "halfeti/sph/health.hpp"
#include "halfeti/sph/neighbour_list.hpp"
#include "halfeti/sph/params.hpp"
#include "halfeti/sph/plate_wall.hpp"
#include "halfeti/sph/walls.hpp"

namespace halfeti::sph {

// c0: the scene's, or eq. 10's from the deepest water block and the peak ground acceleration (FluidParams).
double resolved_sound_speed(const FluidParams& p);

class Fluid {
 public:
  // Collective over comm (duplicated). motion may be null (still tank); it must outlive the Fluid.
  Fluid(MPI_Comm comm, const FluidParams& params, const excitation::GroundMotion* motion = nullptr);

  void step();
  void compute_forces();
  void advance();  // predict() then finish()
  // advance() in two halves, for the contact coupling between them (DESIGN.md steps 2 and 6): predict() kicks,
  // updates the density and drifts (time += dt); finish() checks health, rebalances and migrates. Between them
  // the owned particles keep their indices, so per-particle corrections can be applied.
  // With PlateDensity::kDeferred, predict() leaves the density at the step's start and update_density() advances it
  // with the plate wall's term at the faces' velocities of `motion`: the converged plate-water exchange knows the
  // plate's motion over the step only after the coupling (docs/coupling.md, section 16). The same arithmetic as
  // predict() alone when the velocities are the same. Between predict() and apply_corrections().
  enum class PlateDensity { kWithStep, kDeferred };
  void predict(PlateDensity plate = PlateDensity::kWithStep);
  void update_density(const PlateOutline& motion);
  void finish();
  bool forces_ready() const { return forces_ready_; }  // compute_forces() done for the present particles
  // Adds the coupling's corrections (position, velocity, density: eqs. 4, 22, 24) to the owned particles listed
  // in `touched`; each array holds one entry per owned particle.
  void apply_corrections(const std::vector<int>& touched, const double* dx, const double* dy,
                         const double* dvx, const double* dvy, const double* drho);

  double time() const { return time_; }
  long step_count() const { return step_; }
  double dt() const { return dt_; }  // the step chosen by the last compute_forces()
  double sound_speed() const { return c0_; }
  double smoothing_length() const { return kernel_.h; }
  const FluidParams& params() const { return params_; }
  MPI_Comm comm() const { return comm_.get(); }

  // Owned particles (for output); sizes = owned_count().
  std::size_t owned_count() const { return static_cast<std::size_t>(n_owned_); }
  long global_count() const { return n_global_; }
  const std::vector<std::int64_t>& gid() const { return gid_; }  // (ghost rows may follow: use owned_count())
  const std::vector<double>& x() const { return x_; }
  const std::vector<double>& y() const { return y_; }
  const std::vector<double>& vx() const { return vx_; }
  const std::vector<double>& vy() const { return vy_; }
  const std::vector<double>& rho() const { return rho_; }
  std::vector<double> pressure() const;                      // owned particles, eq. 9
  const std::vector<double>& mass() const { return mass_; }  // kg/m per unit depth
  // The renormalised density gradient (eq. 6) of the last compute_forces(), 2 per particle, owned first; empty
  // for the standard scheme.
  const std::vector<double>& renormalised_density_gradient() const { return grad_rho_; }

  // Delta C (eq. 4) hook: extra acceleration per owned particle, zeroed by compute_forces() and added by advance().
  std::vector<double>& extra_acceleration_x() { return extra_ax_; }
  std::vector<double>& extra_acceleration_y() { return extra_ay_; }
  // Fluid pairs whose segment crosses one of these lines do not interact (added to the internal walls).
  void set_barriers(const std::vector<Barrier>& extra);
  // The plate's surface as a moving wall in the SPH sums (plate_wall.hpp), from the next compute_forces() on;
  // an empty outline turns it off. Its mid-line (as the lattice sees the plate) becomes the barrier, in place of
  // any earlier extra barriers. The loads of the last compute_forces() on the surface points, per particle.
  void set_plate_outline(const PlateOutline& outline);
  // How the initial lattice sees the plate's faces (before the first set_plate_outline()).
  void set_plate_offsets(const LatticeOffsets& offsets) { plate_wall_.set_offsets(offsets); }
  const std::vector<PlateWallLoad>& plate_wall_loads() const { return plate_wall_.loads(); }
  // Water separating from a face meets it as a free surface (PlateWall::set_free_surface; the marked particles'
  // pressure floored at zero in every sum, their halo copies too), from the next compute_forces() on; off: every
  // particle's ghosts continue its pressure.
  void set_plate_free_surface(bool on) { plate_free_surface_ = on; }

  // Probes: collective, same value on every rank, bitwise independent of the rank count.
  // Kernel interpolation over fluid particles, first-order corrected (MLS; Shepard where the moments are singular).
  double pressure_at(double x, double y) const;
  std::array<double, 2> velocity_at(double x, double y) const;
  double free_surface_elevation(double x) const;  // top fluid particle in |x_i - x| <= dx, + dx/2
  // The bulk's surface at x from the kernel-interpolated volume fraction (1/2 crossing upward from the floor):
  // robust to run-up jets and spray, which the top particle follows.
  double surface_level(double x) const;
  // Amplitude of the free surface's standing mode n, cos(n pi x / L), from surface_level at `samples` midpoints
  // x_k = (k + 1/2) L / samples: (2 / samples) sum_k level(x_k) cos(n pi x_k / L) [m]. The midpoint sum of the
  // cosine vanishes, so the still depth needs no subtracting. Needs samples >= 2 n.
  double surface_mode(int n, int samples) const;
  double front_position(double y_max) const;  // max x of fluid particles below y_max, + dx/2
  double total_mass() const;
  // Water that left over the tank's open top (removed from the run, per unit depth [kg/m]), every rank.
  double spilled_mass() const { return spilled_mass_; }
  double kinetic_energy() const;
  double max_density_variation() const;     // max |rho - rho0| / rho0
  double plate_free_surface_count() const;  // particles beside the plate marked at the last compute_forces()
  double floored_count() const;  // particles the free-surface floor raised at the last compute_forces()
  double min_spacing() const;    // closest fluid pair at the last neighbour search, in dx (over every rank)

  const PhaseTimers& timers() const { return timers_; }
  // This rank's halo and migration messages since the run (or its restart) started.
  const parallel::Traffic& traffic() const { return traffic_; }
  const std::vector<HealthEvent>& health_events() const { return events_; }

  // ---- restart ----
  // The whole state at a step boundary: the particles (those this rank owns from state(); every particle for
  // restore()), the clock, the spilled water and the health log with its active warnings. Everything else a step
  // reads (neighbours, halo, rates, dt) is rebuilt from these, so a restored fluid steps bit for bit as the one
  // saved, on any number of ranks.
  struct State {
    ParticleArrays particles;
    double time = 0.0, spilled_mass = 0.0;
    long step = 0;
    std::vector<HealthEvent> events;
    std::vector<std::string> active_warnings;
  };
  State state() const;  // (taken inside a step, at a failure, it is for inspection: between_steps() is false)
  // At a step boundary (the forces of the next step may already be computed: they follow from the state).
  bool between_steps() const { return !predicted_; }

  // ---- a step taken back (the converged plate-water exchange's iterations) ----
  // Everything a step changes (particles, their order and owners, neighbours, halo, rates, clock, health log),
  // copied into a reusable buffer and put back: the step then repeats bit for bit. The timers are not put back.
  struct Snapshot;
  void snapshot(Snapshot& into) const;
  void rollback(const Snapshot& from);
  void restore(State all);  // collective; the particles partitioned afresh over this run's ranks
  // Cell -> owning rank map of the current decomposition (diagnostics of the balance).
  const std::vector<int>& cell_owner() const { return owner_; }

 private:
  void initialise_particles();
  // Partitions the cells by their counts of `all` and keeps this rank's particles, in (cell, gid) order.
  void distribute(ParticleArrays all);
  // The cell -> rank map, and the halo peers it gives (kept together).
  void set_owner(std::vector<int> owner);
  bool excluded(double px, double py) const;
  bool near_internal_wall(double x, double y) const;
  // Orders the owned particles by (cell, gid); `cells_current`: cell_ already holds each one's cell.
  void sort_owned_by_cell(bool cells_current = false);
  void exchange_halo();
  // FluidParams::free_surface_floor: the separated particles' density raised to rho0, after the neighbour search
  void floor_separated_density(const ParticleView& pv);
  // Local particle i's pressure (eq. 9) and volume m / rho from its density
  void refresh_pressure_and_volume(int i);
  void check_health();
  // What this rank's pass over its particles found (the checks' local halves; one reduction joins them).
  struct LocalHealth {
    long spilled = 0, spilled_key = 0;  // particles over the open top, and the lowest id among them
    double spilled_mass = 0.0, spilled_x = 0.0, spilled_y = 0.0;
    std::string spilled_msg;
    // lowest id with a NaN or outside the tank, and its message (without the time and step)
    long bad_key = 0;
    std::string bad_msg;
    double density_variation = 0.0;  // largest |rho - rho0| / rho0, at owned particle `densest` (-1: none)
    int densest = -1;
    bool far = false;  // a particle's new cell is owned by a rank that is not a halo peer
  };
  LocalHealth scan_health();
  void report_spilled(const LocalHealth& mine, bool anywhere);
  void maybe_rebalance();
  void migrate();
  std::vector<long> global_cell_counts() const;
  // A warning's episode (start, end by hysteresis, worst value and place while it holds); a fatal event, recorded
  // and raised as NumericalError.
  void warn(const std::string& kind, bool active, bool cleared, const std::string& message,
            double value = 0.0, double x = 0.0, double y = 0.0);
  [[noreturn]] void fatal(const std::string& kind, const std::string& message);
  int closest_pair_particle(double dmin) const;
  HealthEvent* open_warning(const std::string& kind);  // the episode of `kind` under way, or null

  Communicator comm_;
  int rank_ = 0, size_ = 1;
  FluidParams params_;
  const excitation::GroundMotion* motion_;
  Kernel kernel_;
  double c0_ = 0.0, dx_ = 0.0;
  parallel::CellGrid grid_;
  std::vector<int> owner_;  // cell -> rank
  std::vector<int> peers_;  // the ranks owning cells around this rank's: whom the halo talks to (from owner_)
  parallel::HaloPlan halo_plan_;
  parallel::Traffic traffic_;  // messages, bytes and MPI waiting of the halo and the migration (a diagnostic)
  WallParticles walls_;
  WallGhosts ghosts_;
  NeighbourSearch search_;
  FluidPairList pairs_;
  PairList wall_pairs_, ghost_pairs_;

  // Local particles: [0, n_owned_) owned, then ghosts (after exchange_halo()).
  int n_owned_ = 0, n_local_ = 0;
  long n_global_ = 0;
  double spilled_mass_ = 0.0;
  std::vector<std::int64_t> gid_;
  std::vector<double> x_, y_, vx_, vy_, rho_, mass_, p_, volume_;
  // owned particles' cells (set by the health scan for the migration that follows it)
  std::vector<int> cell_;
  // the step's migration must find its senders over the whole communicator (a particle went past the halo peers,
  // or the cells were partitioned afresh); set by check_health() and maybe_rebalance(), read by migrate()
  bool far_move_ = false;
  std::vector<double> grad_rho_;
  Rates rates_;
  RateConstants constants_{};
  std::vector<double> extra_ax_, extra_ay_;
  PlateWall plate_wall_;
  bool plate_free_surface_ = false;
  // owned particles FluidParams::free_surface_floor raised at the last compute_forces() (kept: no allocation a step)
  std::vector<int> floored_;

  double time_ = 0.0, dt_ = 0.0;
  long step_ = 0;
  bool forces_ready_ = false, predicted_ = false, density_pending_ = false;
  PhaseTimers timers_;
  std::vector<HealthEvent> events_;
  std::vector<std::string> active_warnings_;

 public:
// The members a step changes, listed once for the snapshot's copy both ways.
// clang-format off
#define HALFETI_FLUID_STEP_STATE(X)                                                                                  \
  X(owner_) X(peers_) X(halo_plan_) X(search_) X(pairs_) X(wall_pairs_) X(ghost_pairs_) X(n_owned_) X(n_local_)      \
  X(n_global_) X(spilled_mass_) X(gid_) X(x_) X(y_) X(vx_) X(vy_) X(rho_) X(mass_) X(p_) X(volume_) X(cell_)         \
  X(grad_rho_) X(rates_) X(constants_) X(extra_ax_) X(extra_ay_) X(plate_wall_) X(time_) X(dt_) X(step_)            \
  X(forces_ready_) X(predicted_) X(density_pending_) X(events_) X(active_warnings_)
  // clang-format on
  struct Snapshot {
#define HALFETI_FLUID_DECLARE(m) \
  std::optional<decltype(Fluid::m)> m;  // (some members have no default constructor)
    HALFETI_FLUID_STEP_STATE(HALFETI_FLUID_DECLARE)
#undef HALFETI_FLUID_DECLARE
  };
};

}  // namespace halfeti::sph
