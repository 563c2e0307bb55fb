// Base64 (RFC 4648, with padding): how reports embed their images in one HTML file.
#pragma once

#include <string>

namespace ll {

std::string base64(const std::string& bytes);

}  // namespace ll
