// Output files: what a command writes goes where the user said, folders
// included (`-o out/a2.png` in a fresh checkout makes out/).
#pragma once

#include <string>

namespace ll {

// Creates the folders above `path` if they are missing. Throws UserError
// naming the folder if it cannot.
void createParentDirectory(const std::string& path);

}  // namespace ll
