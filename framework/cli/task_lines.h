// What a command says on stderr about the student tasks it ran, in one
// wording for render, trace and radiosity: each stub ("A2.4 not implemented:
// Blinn-Phong shading (...) -- its reference stood in"), each rule a task's
// code broke, and the tasks run by their reference (--reference).
#pragma once

#include <map>
#include <set>
#include <string>

namespace ll::cli {

// missing: task id -> what it is; exact: the missing ids whose reference gives the same picture;
// striped: the picture shows stripes where stubs ran; references: "A2.3,A2.5" or empty (no line).
void printTaskLines(const std::map<std::string, std::string>& missing, const std::set<std::string>& exact,
                    bool striped, const std::map<std::string, std::string>& violations = {},
                    const std::string& references = "");

}  // namespace ll::cli
