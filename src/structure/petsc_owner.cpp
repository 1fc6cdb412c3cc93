#include "halfeti/structure/petsc_owner.hpp"

#include <sstream>

#include "halfeti/core/error.hpp"

namespace halfeti::structure::detail {

void raise_petsc_error(PetscErrorCode code, const char* call, const char* func, const char* file, int line) {
  const char* text = nullptr;
  PetscErrorMessage(code, &text, nullptr);
  std::ostringstream os;
  os << "PETSc error " << static_cast<int>(code) << " (" << (text ? text : "unknown") << ") from " << call
     << " in " << func << " at " << file << ":" << line;
  throw InternalError(os.str());
}

}  // namespace halfeti::structure::detail
