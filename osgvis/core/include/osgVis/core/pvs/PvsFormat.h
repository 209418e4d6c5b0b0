// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// The `.pvs` file (docs/pvs-format.md): versioned little-endian binary. Version 2, which encodePvs
/// writes, is a header and tagged sections (model, build identity, geometry fingerprint, then
/// cell-portal data and/or view cells) under a checksum; version 1 files (cell-portal data and the
/// model path) still read. The reader never trusts bytes: anything corrupt, truncated or
/// inconsistent is an error, never a crash.
#include <osgVis/core/pvs/CellPortalData.h>
#include <osgVis/core/pvs/ViewCellPvs.h>

#include <cstdint>
#include <optional>
#include <utility>
#include <stdexcept>
#include <string>
#include <vector>

namespace osgVis::core
{
/// The version encodePvs writes.
constexpr std::uint32_t PvsFormatVersion = 2;

struct PvsFormatError : std::runtime_error
{
    using std::runtime_error::runtime_error;
};

struct PvsFile
{
    std::string modelPath; ///< as written: usually relative to the .pvs file's folder
    /// How the data were baked: the method ("cellportal", "multifocal"), its options as the baker
    /// spells them canonically (equal options, equal strings), and the near-plane distance it
    /// assumed (0: none). Version 1 files read as "cellportal", "", 0.
    std::string method, options;
    double nearDistance = 0.0;
    /// sceneGeometryFingerprint() of the model; 0 when unknown (version 1 files), and then only
    /// data.fingerprint identifies the model.
    std::uint64_t geometryFingerprint = 0;
    /// data.fingerprint (sceneFingerprint()) and data.objectCount identify the model whatever the
    /// file holds; the rest of `data` is stored only with hasCellPortal. True by default so that
    /// code filling only `data`, as for version 1, still writes it.
    bool hasCellPortal = true;
    CellPortalData data;
    /// With hasCellPortal, a range file of a split bake (osgvispvs --cells, --shard, MPI units):
    /// only source cells [first, end) are baked and every other source is a placeholder
    /// (isPlaceholderSource). Nothing may use it as visibility; mergeCellPortalPvs joins ranges.
    std::optional<std::pair<std::uint32_t, std::uint32_t>> sourceRange;
    bool hasViewCells = false;
    ViewCellPvs viewCells;                    ///< its sets have capacity data.objectCount
    std::uint32_t version = PvsFormatVersion; ///< as read; encodePvs writes PvsFormatVersion whatever it says
};

/// Throws PvsFormatError for data the reader would refuse ("cannot encode .pvs: ..."): the same
/// file always gives the same bytes.
std::vector<std::uint8_t> encodePvs(const PvsFile& file);
/// Reads versions 1 and 2. Throws PvsFormatError saying what is wrong (bad magic, unsupported
/// version, truncated, checksum mismatch, an unknown required section, inconsistent counts or
/// indices); unknown optional sections are skipped.
PvsFile decodePvs(const std::uint8_t* bytes, std::size_t size);

/// File helpers: write atomically (temporary file, then rename); read throws PvsFormatError, also
/// for a missing or unreadable file.
void writePvsFile(const std::string& path, const PvsFile& file);
PvsFile readPvsFile(const std::string& path);
} // namespace osgVis::core
