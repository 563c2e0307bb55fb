// UTF-8 checks for text LightLab did not write: file contents, names, a
// student's messages. What reaches JSON, HTML, SVG or the screen must be
// valid UTF-8, and invalid bytes are replaced, never thrown on.
#pragma once

#include <cstddef>
#include <string>

namespace ll {

// The offset of the first byte at or after `from` that does not start a
// well-formed UTF-8 sequence (RFC 3629: no overlong forms, no surrogates, at
// most U+10FFFF), or std::string::npos if there is none.
size_t firstInvalidUtf8(const std::string& s, size_t from = 0);

// `s` with each byte of an ill-formed sequence replaced by U+FFFD (the
// replacement character), as nlohmann's error_handler_t::replace does.
std::string replaceInvalidUtf8(const std::string& s);

}  // namespace ll
