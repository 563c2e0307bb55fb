#include "core/files.h"

#include <filesystem>
#include <system_error>

#include "core/error.h"

namespace ll {

void createParentDirectory(const std::string& path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  if (parent.empty()) return;
  std::error_code ec;
  std::filesystem::create_directories(parent, ec);
  if (ec) throwUserError(path + ": cannot create the folder " + parent.string() + ": " + ec.message());
}

std::filesystem::file_time_type writeTime(const std::filesystem::path& path) {
  std::error_code ec;
  const auto t = std::filesystem::last_write_time(path, ec);
  return ec ? std::filesystem::file_time_type{} : t;
}

}  // namespace ll
