#include "halfeti/core/petsc_owner.hpp"

#include <sstream>

#include "halfeti/core/error.hpp"

namespace halfeti {

KSPConvergedReason solve_with(KSP ksp, Mat matrix, Vec rhs, Vec solution) {
  HALFETI_PETSC_CALL(KSPSetOperators(ksp, matrix, matrix));
  HALFETI_PETSC_CALL(KSPSolve(ksp, rhs, solution));
  KSPConvergedReason reason;
  HALFETI_PETSC_CALL(KSPGetConvergedReason(ksp, &reason));
  return reason;
}

std::string ksp_failure(KSP ksp, KSPConvergedReason reason) {
  std::string text = std::string("KSP reason ") + KSPConvergedReasons[reason];
  if (reason == KSP_DIVERGED_PC_FAILED) {
    PC pc = nullptr;
    PCFailedReason pc_reason;
    HALFETI_PETSC_CALL(KSPGetPC(ksp, &pc));
    HALFETI_PETSC_CALL(PCGetFailedReason(pc, &pc_reason));
    text += std::string(" (preconditioner: ") + PCFailedReasons[pc_reason] + ")";
  }
  return text;
}

void add_to_vector(Vec v, int n, const PetscInt* rows, const PetscScalar* values, const char* what) {
  PetscInt size = 0;
  HALFETI_PETSC_CALL(VecGetSize(v, &size));
  for (int k = 0; k < n; ++k) {
    HALFETI_CHECK(rows[k] >= -1 && rows[k] < size, what << ": row " << rows[k] << " of a vector of " << size);
    if (rows[k] >= 0) HALFETI_PETSC_CALL(VecSetValues(v, 1, rows + k, values + k, ADD_VALUES));
  }
}

}  // namespace halfeti

namespace halfeti::detail {

void raise_petsc_error(PetscErrorCode code, const char* call, const char* func, const char* file, int line) {
  const char* text = nullptr;
  PetscErrorMessage(code, &text, nullptr);
  std::ostringstream os;
  os << "PETSc error " << static_cast<int>(code) << " (" << (text ? text : "unknown") << ") from " << call
     << " in " << func << " at " << file << ":" << line;
  throw InternalError(os.str());
}

}  // namespace halfeti::detail
