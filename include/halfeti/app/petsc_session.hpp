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
  // The options given that no PETSc object read (PETSc's own bookkeeping): misspelt or for a solver not in use.
  std::vector<std::string> unused_options() const;
};

}  // namespace halfeti::app
