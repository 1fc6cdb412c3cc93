#include "halfeti/core/error.hpp"

namespace halfeti {

int exit_status(ErrorKind kind) {
  switch (kind) {
    case ErrorKind::kUser:
      return 2;
    case ErrorKind::kNumerical:
      return 3;
    case ErrorKind::kInternal:
      return 4;
  }
  return 4;
}

namespace detail {
void raise_internal(const char* cond, const std::string& msg, const char* func, const char* file, int line) {
  std::ostringstream os;
  os << "internal check failed: " << msg << " [" << cond << " in " << func << " at " << file << ":" << line << "]";
  throw InternalError(os.str());
}
}  // namespace detail

}  // namespace halfeti
