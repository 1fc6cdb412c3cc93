#include "halfeti/core/error.hpp"

#include "halfeti/core/collective.hpp"

namespace halfeti {

int exit_status(ErrorKind kind) {
  switch (kind) {
    case ErrorKind::kUser:
      return 2;
    case ErrorKind::kNumerical:
      return 3;
    case ErrorKind::kInternal:
      return 4;
    case ErrorKind::kIo:
      return 6;
  }
  return 4;
}

namespace detail {
void raise_shared(int kind, const std::string& message) {
  switch (static_cast<ErrorKind>(kind)) {
    case ErrorKind::kUser:
      throw UserError(message);
    case ErrorKind::kNumerical:
      throw NumericalError(message);
    case ErrorKind::kIo:
      throw IoError(message);
    case ErrorKind::kInternal:
      break;
  }
  throw InternalError(message);
}

void raise_internal(const char* cond, const std::string& msg, const char* func, const char* file, int line) {
  std::ostringstream os;
  os << "internal check failed: " << msg << " [" << cond << " in " << func << " at " << file << ":" << line
     << "]";
  throw InternalError(os.str());
}
}  // namespace detail

}  // namespace halfeti
