// Text placed in HTML or SVG/XML markup (grade reports, JUnit XML, slide
// pages, plots): escaped for elements and for attributes quoted either way.
#pragma once

#include <string>

namespace ll {

// Escapes & < > " '; drops the control characters XML 1.0 forbids; replaces
// bytes that are not UTF-8 with U+FFFD (a student's message, a Latin-1 file
// name), so the page always parses. `text` (element content) keeps line
// breaks and tabs; otherwise (attribute values) they become references.
std::string escapeMarkup(const std::string& s, bool text = false);

}  // namespace ll
