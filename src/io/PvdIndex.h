#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace sphcast {

// One cloud at one written time in the ParaView collection (<case>.pvd).
struct PvdEntry {
  double time = 0;       // for sorting
  std::string timeName;  // the time folder's name, written as is ("0.1", not 0.1000000000000001)
  std::string part;      // the cloud's name
  std::string file;      // relative to the .pvd's folder, e.g. "0.1/metal.vtp"

  bool operator==(const PvdEntry&) const = default;
};

// Writes the ParaView collection that lists every cloud at every time, replacing pvdFile
// atomically (the solver rewrites it after each write; VTK has no writer for such an index).
// Entries are sorted by (time, part); of entries with the same time and part the last given is
// kept. Each DataSet's part index is the position of its cloud name among all the distinct names,
// so a cloud keeps its index at every time.
void writePvd(const std::filesystem::path& pvdFile, std::vector<PvdEntry> entries);

// Reads a collection written by writePvd, in file order. An unreadable file or a DataSet
// without timestep, name or file is an Error naming the file.
std::vector<PvdEntry> readPvd(const std::filesystem::path& pvdFile);

}  // namespace sphcast
