// PETSc is started only for scenes with a structure (DESIGN.md principle 2), after MPI, with the options the user
// gave after `--`; the destructor finalises it.
#pragma once

#include <string>
#include <vector>

namespace halfeti::app {

class PetscSession {
 public:
  explicit PetscSession(const std::vector<std::string>& options);
  ~PetscSession();
  PetscSession(const PetscSession&) = delete;
  PetscSession& operator=(const PetscSession&) = delete;
};

}  // namespace halfeti::app
