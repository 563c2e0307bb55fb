// Output files: what a command writes goes where the user said, folders
// included (`-o out/a2.png` in a fresh checkout makes out/).
#pragma once

#include <filesystem>
#include <string>

namespace ll {

// Creates the folders above `path` if they are missing. Throws UserError
// naming the folder if it cannot.
void createParentDirectory(const std::string& path);

// The file's last modification time, or file_time_type{} if it cannot be read
// (missing): what the GUI polls to notice a saved scene or task file.
std::filesystem::file_time_type writeTime(const std::filesystem::path& path);

}  // namespace ll
