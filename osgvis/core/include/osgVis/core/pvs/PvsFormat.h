// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// The `.pvs` file (docs/pvs-format.md): versioned little-endian binary holding CellPortalData and
/// the path of the model it was baked for, with compressed per-cell bitsets and a checksum. The
/// reader never trusts bytes: anything corrupt, truncated or inconsistent is an error, never a crash.
#include <osgVis/core/pvs/CellPortalData.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace osgVis::core
{
struct PvsFormatError : std::runtime_error
{
    using std::runtime_error::runtime_error;
};

struct PvsFile
{
    std::string modelPath; ///< as written: usually relative to the .pvs file's folder
    CellPortalData data;
};

std::vector<std::uint8_t> encodePvs(const PvsFile& file);
/// Throws PvsFormatError saying what is wrong (bad magic, unsupported version, truncated, checksum
/// mismatch, inconsistent counts or indices).
PvsFile decodePvs(const std::uint8_t* bytes, std::size_t size);

/// File helpers: write atomically (temporary file, then rename); read throws PvsFormatError, also
/// for a missing or unreadable file.
void writePvsFile(const std::string& path, const PvsFile& file);
PvsFile readPvsFile(const std::string& path);
} // namespace osgVis::core
