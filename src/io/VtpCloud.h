#pragma once

#include <filesystem>
#include <string>

#include "particles/ParticleCloud.h"

namespace sphcast {

// A particle cloud as a VTK XML PolyData file (.vtp), the restart and ParaView format of a time
// folder (doc/design.md §2). One vertex cell per particle; every field in full precision (Real as
// Float64, or Float32 in a single-precision build; ids as Int64): scalar fields as 1-component
// point data, vector fields as 3-component point data, id fields as Int64 point data; cloud
// attributes as field data of one Float64 value each. Appended data, zlib-compressed, UInt64
// block headers, base64-encoded (well-formed XML: every ParaView and XML parser opens it; a file
// written raw by an earlier sphCast still reads).

// Writes the cloud to file through "<file>.tmp" and an atomic rename, so a run killed while
// writing leaves either the old file or the new one. Throws an Error naming the file on failure.
void writeCloudVtp(const ParticleCloud& cloud, const std::filesystem::path& file);

// Reads a cloud written by writeCloudVtp (or any .vtp whose point data arrays are floating-point
// with 1 or 3 components, or integer with 1). Integer arrays become id fields, 1-component
// floating-point arrays scalar fields, 3-component ones vector fields. Every problem (missing,
// truncated or corrupt file, an unsupported array, a NaN or infinite position, field value or
// attribute, a value of mass, restDensity, rho, viscosity or volume that is not positive) is an
// Error naming the file, and the cloud, field, particle and value where they apply.
ParticleCloud readCloudVtp(const std::filesystem::path& file, const std::string& cloudName);

}  // namespace sphcast
