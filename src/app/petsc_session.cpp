#include "halfeti/app/petsc_session.hpp"

#include <petscsys.h>

#include "halfeti/core/error.hpp"

namespace halfeti::app {

PetscSession::PetscSession(const std::vector<std::string>& options) {
  std::vector<std::string> storage{"halfeti"};
  storage.insert(storage.end(), options.begin(), options.end());
  std::vector<char*> argv;
  for (auto& s : storage) argv.push_back(s.data());
  argv.push_back(nullptr);
  int argc = static_cast<int>(storage.size());
  char** args = argv.data();
  if (PetscInitialize(&argc, &args, nullptr, nullptr) != 0)
    HALFETI_USER_ERROR("PETSc did not start with the options given after '--'");
}

PetscSession::~PetscSession() {
  PetscFinalize();
}

std::vector<std::string> PetscSession::unused_options() const {
  PetscInt n = 0;
  char** names = nullptr;
  char** values = nullptr;
  std::vector<std::string> out;
  if (PetscOptionsLeftGet(nullptr, &n, &names, &values) != 0) return out;
  for (PetscInt i = 0; i < n; ++i) out.push_back(std::string("-") + names[i]);
  PetscOptionsLeftRestore(nullptr, &n, &names, &values);
  return out;
}

}  // namespace halfeti::app
