// "Fail on every rank together": work that only some ranks do (rank 0 writing a file, the structure's ranks
// solving the plate) may raise a user, numerical or I/O error there; the others must not be left waiting in the
// next collective call. collective_outcome() runs `work` where `participate` is true, then the root shares the
// outcome: on a failure every rank raises the same error (same kind, same message).
#pragma once

#include <mpi.h>

#include <string>

#include "halfeti/core/error.hpp"

namespace halfeti {

namespace detail {
[[noreturn]] void raise_shared(int kind, const std::string& message);
}  // namespace detail

// Collective: among the ranks with has_problem, the message of the one with the smallest `key` (a particle's
// global id, a rank) on every rank; empty when no rank has one. For checks that any rank may fail (the fluid's
// monitors, the plate's element loop).
std::string first_problem(MPI_Comm comm, bool has_problem, long key, const std::string& message);
// Collective: the lowest rank among those with `has` and the smallest `key`; -1 when no rank has.
int first_rank(MPI_Comm comm, bool has, long key);
// Collective: `message` as the root has it, on every rank (for a root already found by first_rank()).
std::string broadcast_from(MPI_Comm comm, int root, const std::string& message);

// The root must be among the participants (its outcome is the one shared).
template <class Work>
void collective_outcome(MPI_Comm comm, int root, bool participate, Work&& work) {
  int kind = -1;
  std::string message;
  if (participate) {
    try {
      work();
    } catch (const InternalError&) {
      throw;  // a bug: not known to be collective, main aborts every rank
    } catch (const Error& e) {
      kind = static_cast<int>(e.kind());
      message = e.what();
    }
  }
  int head[2] = {kind, static_cast<int>(message.size())};
  MPI_Bcast(head, 2, MPI_INT, root, comm);
  if (head[0] < 0) return;
  message.resize(static_cast<std::size_t>(head[1]));
  MPI_Bcast(message.data(), head[1], MPI_CHAR, root, comm);
  detail::raise_shared(head[0], message);
}

}  // namespace halfeti
