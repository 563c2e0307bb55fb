#include "grading/report_text.h"

#include <cstdio>
#include <fstream>

#include "core/error.h"
#include "core/files.h"

namespace ll::grading {

std::string formatNumber(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  std::string s = buf;
  if (s.find('.') != std::string::npos) {
    while (!s.empty() && s.back() == '0') s.pop_back();
    if (!s.empty() && s.back() == '.') s.pop_back();
  }
  if (s == "-0") s = "0";
  return s;
}

void writeTextFile(const std::string& path, const std::string& text) {
  createParentDirectory(path);
  std::ofstream out(path, std::ios::binary);
  if (!out) throwUserError("cannot write " + path);
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  out.close();
  if (!out) throwUserError("cannot write " + path);
}

}  // namespace ll::grading
