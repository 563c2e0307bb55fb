// User-facing errors. Anything the user can get wrong (a file, a flag, a
// parameter) throws UserError with one line that names the place and the
// allowed values; programmer errors use assert. Library code never exits.
#pragma once

#include <stdexcept>
#include <string>

namespace ll {

class UserError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// "file:line:col: message" (line/col omitted when 0).
std::string formatLocation(const std::string& file, int line, int column);

[[noreturn]] void throwUserError(const std::string& message);
[[noreturn]] void throwUserError(const std::string& file, int line, int column,
                                 const std::string& message);

// "a, b, c" for error messages listing allowed values.
template <class Range>
std::string joinNames(const Range& names, const char* sep = ", ") {
  std::string out;
  for (const auto& n : names) {
    if (!out.empty()) out += sep;
    out += n;
  }
  return out;
}

}  // namespace ll
