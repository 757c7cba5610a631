#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "particles/ParticleCloud.h"

namespace sphcast {

// A cloud of a parallel run, one piece per rank: <name>.pvtp, the index ParaView opens as one
// cloud (its fields' names and types, and the pieces), and <name>/<name>_<r>.vtp, rank r's
// particles as writeCloudVtp writes a cloud. VTK's parallel writer writes such an index only
// through its own MPI controller and leaves out empty pieces (and with them the fields of a
// cloud no rank holds yet), so the index is written here with VTK's XML element writer.

// Where piece `piece` of pvtpFile lies: <folder>/<name>/<name>_<piece>.vtp.
std::filesystem::path pieceFile(const std::filesystem::path& pvtpFile, int piece);
// pieceFile's path relative to the index's folder, as the index lists it.
std::string pieceSource(const std::filesystem::path& pvtpFile, int piece);

// Writes the index of `pieces` pieces of a cloud with the fields of `cloud`, atomically (one
// rank writes it; each rank writes its piece with writeCloudVtp at pieceFile(file, rank)).
void writeCloudPvtpIndex(const ParticleCloud& cloud, const std::filesystem::path& pvtpFile,
                         int pieces);

// The piece files the index lists, in order; an unreadable index, or one without pieces, is an
// Error naming the file.
std::vector<std::filesystem::path> readPvtpPieces(const std::filesystem::path& pvtpFile);

// The particles of pieces first, first + stride, ... of the index as one cloud (a serial tool
// reads all of them; rank r of n reads r, r + n, ...), with the fields and attributes of the
// cloud even where it reads no piece. Every problem is readCloudVtp's Error, naming the piece.
ParticleCloud readCloudPvtp(const std::filesystem::path& pvtpFile, const std::string& cloudName,
                            int first = 0, int stride = 1);

}  // namespace sphcast
