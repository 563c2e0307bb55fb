// Files the user names. Output: what a command writes goes where the user
// said, folders included (`-o out/a2.png` in a fresh checkout makes out/).
// Input: a file is checked (exists, is a file, size within a stated limit)
// before a byte is read, so a wrong path or a 2 GB file is one line, not a
// frozen program.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace ll {

// Creates the folders above `path` if they are missing. Throws UserError
// naming the folder if it cannot.
void createParentDirectory(const std::string& path);

// The file's last modification time, or file_time_type{} if it cannot be read
// (missing): what the GUI polls to notice a saved scene or task file.
std::filesystem::file_time_type writeTime(const std::filesystem::path& path);

// Size limits of the files LightLab reads, in bytes (stated in the errors).
inline constexpr std::uintmax_t kMaxTextFileBytes = 64ull << 20;   // scene JSON, presets, decks
inline constexpr std::uintmax_t kMaxMeshFileBytes = 1ull << 30;    // .obj, .ply, .off, .stl
inline constexpr std::uintmax_t kMaxImageFileBytes = 256ull << 20; // textures, reference images

// "64 MB", "2.0 GB", "512 bytes": a size for messages.
std::string formatBytes(std::uintmax_t bytes);

// Throws UserError unless `path` names a regular file of at most `maxBytes`;
// returns its size. `what` names the kind of file in the message ("scene file").
std::uintmax_t checkInputFile(const std::string& path, const std::string& what, std::uintmax_t maxBytes);

// Throws UserError "file:line:col: a NUL byte ..." if `text` holds one: a text
// file holds none, and a parser (nlohmann's among them) would silently stop
// at it, accepting a valid file followed by binary data or zeros.
void rejectNulBytes(const std::string& text, const std::string& file, const std::string& what);

// checkInputFile, then rejectNulBytes over the file read in blocks, without
// holding it: for text files another library parses (OBJ).
void checkTextFile(const std::string& path, const std::string& what, std::uintmax_t maxBytes);

// checkInputFile, then the whole file, then rejectNulBytes.
std::string readTextFile(const std::string& path, const std::string& what,
                         std::uintmax_t maxBytes = kMaxTextFileBytes);

}  // namespace ll
