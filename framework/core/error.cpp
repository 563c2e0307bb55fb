#include "core/error.h"

namespace ll {

std::string formatLocation(const std::string& file, int line, int column) {
  std::string out = file;
  if (line > 0) out += ":" + std::to_string(line);
  if (line > 0 && column > 0) out += ":" + std::to_string(column);
  return out;
}

void throwUserError(const std::string& message) { throw UserError(message); }

void throwUserError(const std::string& file, int line, int column, const std::string& message) {
  throw UserError(formatLocation(file, line, column) + ": " + message);
}

}  // namespace ll
