#pragma once

#include <filesystem>
#include <string_view>

namespace sphcast {

// Files a run writes (time folders, the .pvd index) are replaced atomically: a reader, or a run
// killed at any moment, sees either the old complete file or the new complete file, never a half
// one (doc/design.md §2). The content goes to "<file>.tmp", is flushed to disk and is renamed over
// the file. Every failure throws an Error naming the file and the system's reason.

// Writes content to file through "<file>.tmp", fsync and rename.
void writeFileAtomically(const std::filesystem::path& file, std::string_view content);

// The temporary name writeFileAtomically uses for file: "<file>.tmp".
std::filesystem::path temporaryPathFor(const std::filesystem::path& file);

// Flushes an already written file's data to disk (fsync), e.g. one written by a library.
void syncFileToDisk(const std::filesystem::path& file);

// Renames from over to (replacing it atomically), then syncs the folder so the rename survives a
// crash.
void renameAtomically(const std::filesystem::path& from, const std::filesystem::path& to);

}  // namespace sphcast
