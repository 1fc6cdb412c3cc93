// Errors and check macros shared by every module.
//
// Two families, as in MFEM's general/error.hpp:
//   HALFETI_CHECK(cond, msg)        always on; an internal invariant (a bug if it fails)
//   HALFETI_DEBUG_CHECK(cond, msg)  compiled only without NDEBUG
// and two user-facing raisers that carry the error class the program exits with:
//   HALFETI_USER_ERROR(msg)         bad input: scene, file, option (exit status 2)
//   HALFETI_NUMERICAL_ERROR(msg)    a method that failed: blow-up, no convergence (exit status 3)
//   HALFETI_IO_ERROR(msg)           an output that could not be written: disk full, no permission (exit status 6)
// `msg` is a stream expression: HALFETI_CHECK(n > 0, "n = " << n << " must be positive").
#pragma once

#include <sstream>
#include <stdexcept>
#include <string>

namespace halfeti {

enum class ErrorKind { kUser, kNumerical, kInternal, kIo };

class Error : public std::runtime_error {
 public:
  Error(ErrorKind kind, const std::string& what) : std::runtime_error(what), kind_(kind) {}
  ErrorKind kind() const { return kind_; }

 private:
  ErrorKind kind_;
};

class UserError : public Error {
 public:
  explicit UserError(const std::string& what) : Error(ErrorKind::kUser, what) {}
};

class NumericalError : public Error {
 public:
  explicit NumericalError(const std::string& what) : Error(ErrorKind::kNumerical, what) {}
};

class IoError : public Error {
 public:
  explicit IoError(const std::string& what) : Error(ErrorKind::kIo, what) {}
};

class InternalError : public Error {
 public:
  explicit InternalError(const std::string& what) : Error(ErrorKind::kInternal, what) {}
};

// Exit status the program uses for each kind (README documents these).
int exit_status(ErrorKind kind);
// A run stopped by a signal or --max-wall at a step boundary, with a checkpoint to resume from.
constexpr int kExitStoppedResumable = 5;

namespace detail {
[[noreturn]] void raise_internal(const char* cond, const std::string& msg, const char* func, const char* file,
                                 int line);
}  // namespace detail

}  // namespace halfeti

#define HALFETI_STREAM_(msg) (static_cast<std::ostringstream&&>(std::ostringstream() << msg)).str()

#define HALFETI_CHECK(cond, msg)                                                                    \
  do {                                                                                              \
    if (!(cond))                                                                                    \
      ::halfeti::detail::raise_internal(#cond, HALFETI_STREAM_(msg), __func__, __FILE__, __LINE__); \
  } while (0)

#ifdef NDEBUG
#define HALFETI_DEBUG_CHECK(cond, msg) \
  do {                                 \
  } while (0)
#else
#define HALFETI_DEBUG_CHECK(cond, msg) HALFETI_CHECK(cond, msg)
#endif

#define HALFETI_USER_ERROR(msg) throw ::halfeti::UserError(HALFETI_STREAM_(msg))
#define HALFETI_NUMERICAL_ERROR(msg) throw ::halfeti::NumericalError(HALFETI_STREAM_(msg))
#define HALFETI_IO_ERROR(msg) throw ::halfeti::IoError(HALFETI_STREAM_(msg))
