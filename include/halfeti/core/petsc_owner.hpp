// RAII owners of PETSc objects and the PetscCall-style check that turns a PETSc error code into a halfeti
// error. Life cycle everywhere: Create -> set defaults -> XSetFromOptions last -> use -> the owner's
// destructor destroys.
#pragma once

#include <petscksp.h>

#include <string>
#include <utility>

namespace halfeti {

namespace detail {
[[noreturn]] void raise_petsc_error(PetscErrorCode code, const char* call, const char* func, const char* file,
                                    int line);
}  // namespace detail

// Checks a PETSc return code; a failure becomes halfeti::InternalError naming the call, the PETSc message and
// where it happened.
#define HALFETI_PETSC_CALL(call)                                                                      \
  do {                                                                                                \
    PetscErrorCode halfeti_petsc_code_ = (call);                                                      \
    if (halfeti_petsc_code_ != 0)                                                                     \
      ::halfeti::detail::raise_petsc_error(halfeti_petsc_code_, #call, __func__, __FILE__, __LINE__); \
  } while (0)

// Solves with `ksp` and returns the converged reason; a negative reason is returned, not thrown, so the caller
// can name the context. ksp_failure() spells a failed reason out, with the preconditioner's own reason when the
// preconditioner failed.
KSPConvergedReason solve_with(KSP ksp, Mat matrix, Vec rhs, Vec solution);
std::string ksp_failure(KSP ksp, KSPConvergedReason reason);

// ADD_VALUES of values[k] at rows[k] of v, skipping rows -1 (clamped dofs), as MatSetValues does.
// VecSetValues itself skips them only on a vector with VEC_IGNORE_NEGATIVE_INDICES; otherwise an optimised
// PETSc adds to v[-1], before the vector's array. A row below -1 or past the vector's size is an internal
// error naming `what`.
void add_to_vector(Vec v, int n, const PetscInt* rows, const PetscScalar* values, const char* what);

// Owns one PETSc handle (Mat, Vec, KSP, ...). Destroy is PETSc's XDestroy; it runs only while PETSc is alive.
template <typename Handle, PetscErrorCode (*Destroy)(Handle*)>
class PetscOwner {
 public:
  PetscOwner() = default;
  ~PetscOwner() { reset(); }
  PetscOwner(const PetscOwner&) = delete;
  PetscOwner& operator=(const PetscOwner&) = delete;
  PetscOwner(PetscOwner&& o) noexcept : handle_(std::exchange(o.handle_, nullptr)) {}
  PetscOwner& operator=(PetscOwner&& o) noexcept {
    if (this != &o) {
      reset();
      handle_ = std::exchange(o.handle_, nullptr);
    }
    return *this;
  }

  Handle get() const { return handle_; }
  // For XCreate(comm, owner.out()): releases what was held and hands PETSc the slot.
  Handle* out() {
    reset();
    return &handle_;
  }
  void reset() {
    PetscBool finalized = PETSC_FALSE;
    PetscFinalized(&finalized);
    if (handle_ != nullptr && !finalized) Destroy(&handle_);
    handle_ = nullptr;
  }

 private:
  Handle handle_ = nullptr;
};

using OwnedMat = PetscOwner<Mat, MatDestroy>;
using OwnedVec = PetscOwner<Vec, VecDestroy>;
using OwnedKsp = PetscOwner<KSP, KSPDestroy>;

}  // namespace halfeti
