#include "core/files.h"

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
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

std::string formatBytes(std::uintmax_t bytes) {
  char text[32];
  const double b = static_cast<double>(bytes);
  if (bytes < 1024) std::snprintf(text, sizeof text, "%ju bytes", bytes);
  else if (bytes < (1ull << 20)) std::snprintf(text, sizeof text, "%.0f KB", b / 1024.0);
  else if (bytes < (1ull << 30)) std::snprintf(text, sizeof text, "%.0f MB", b / 1048576.0);
  else std::snprintf(text, sizeof text, "%.1f GB", b / 1073741824.0);
  return text;
}

std::uintmax_t checkInputFile(const std::string& path, const std::string& what, std::uintmax_t maxBytes) {
  namespace fs = std::filesystem;
  // The error_code overloads: a name too long for the system is a message, not a filesystem_error.
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (!fs::exists(status)) {
    const bool missing = !ec || ec == std::errc::no_such_file_or_directory;
    throwUserError(path + ": " + (missing ? "no such " + what : "cannot open " + what + " (" + ec.message() + ")"));
  }
  if (fs::is_directory(status)) throwUserError(path + ": is a folder, not a " + what);
  if (!fs::is_regular_file(status)) throwUserError(path + ": is not a regular file (a " + what + " must be one)");
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) throwUserError(path + ": cannot read the size of this " + what + " (" + ec.message() + ")");
  if (size > maxBytes)
    throwUserError(path + ": this " + what + " is " + formatBytes(size) + "; LightLab reads a " + what +
                   " of at most " + formatBytes(maxBytes) + " (is it the right file?)");
  return size;
}

std::string readTextFile(const std::string& path, const std::string& what, std::uintmax_t maxBytes) {
  const std::uintmax_t size = checkInputFile(path, what, maxBytes);
  std::ifstream in(path, std::ios::binary);
  if (!in) throwUserError(path + ": cannot open " + what);
  // The size it had when checked; a file written to meanwhile is reread by the watcher once saved.
  std::string text(static_cast<size_t>(size), '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<size_t>(in.gcount()));
  if (in.bad()) throwUserError(path + ": cannot read " + what);
  rejectNulBytes(text, path, what);
  return text;
}

namespace {

// Advances (line, column) over text[0, end).
void advance(const char* text, size_t end, int& line, int& column) {
  for (size_t i = 0; i < end; ++i) {
    if (text[i] == '\n') ++line, column = 1;
    else ++column;
  }
}

[[noreturn]] void throwNulByte(const std::string& file, int line, int column, const std::string& what) {
  throwUserError(file, line, column,
                 "a NUL byte (0x00): a " + what + " is text, and this one holds binary data from here on");
}

}  // namespace

void rejectNulBytes(const std::string& text, const std::string& file, const std::string& what) {
  const size_t nul = text.find('\0');
  if (nul == std::string::npos) return;
  int line = 1, column = 1;
  advance(text.data(), nul, line, column);
  throwNulByte(file, line, column, what);
}

void checkTextFile(const std::string& path, const std::string& what, std::uintmax_t maxBytes) {
  checkInputFile(path, what, maxBytes);
  std::ifstream in(path, std::ios::binary);
  if (!in) throwUserError(path + ": cannot open " + what);
  std::string block(1 << 20, '\0');
  int line = 1, column = 1;
  while (in) {
    in.read(block.data(), static_cast<std::streamsize>(block.size()));
    const auto n = static_cast<size_t>(in.gcount());
    const auto* nul = static_cast<const char*>(std::memchr(block.data(), '\0', n));
    if (nul) {
      advance(block.data(), static_cast<size_t>(nul - block.data()), line, column);
      throwNulByte(path, line, column, what);
    }
    advance(block.data(), n, line, column);
  }
  if (in.bad()) throwUserError(path + ": cannot read " + what);
}

}  // namespace ll
