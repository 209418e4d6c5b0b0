// SPDX-License-Identifier: MIT
// The `.pvs` container: header, version 2's tagged sections or version 1's fixed ones, checksum.
// docs/pvs-format.md is the byte-level description this code follows.
#include <osgVis/core/pvs/PvsFormat.h>

#include "Checksum.h"
#include "PvsCellPortalCodec.h"
#include "PvsSections.h"
#include "PvsTileCodec.h"
#include "PvsViewCellCodec.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <utility>

namespace osgVis::core
{
namespace
{
constexpr std::uint8_t Magic[8] = {'O', 'S', 'G', 'V', 'P', 'V', 'S', '\0'};
constexpr std::size_t HeaderBytes = 20; // magic, version, body size
constexpr std::size_t ChecksumBytes = 4;

constexpr PvsTag ModelTag{"HEAD", "model header"};
constexpr PvsTag BuildTag{"BILD", "build identity"};
constexpr PvsTag GeometryTag{"GEOM", "geometry fingerprint"};
constexpr PvsTag CellPortalTag{"CPDT", "cell-portal data"};
constexpr PvsTag SourceRangeTag{"CPRG", "cell-portal source range"};
constexpr PvsTag TileTag{"TILE", "tile keys"};
constexpr PvsTag ViewCellTag{"VCEL", "view cells"};

// The writer refuses what the reader would refuse, so a bake bug shows when saving, not loading;
// and it refuses data it would silently leave out.
void checkEncodable(const PvsFile& file)
{
    const CellPortalData& d = file.data;
    if (file.hasCellPortal)
        checkCellPortalEncodable(d);
    else if (!d.graph.cells.empty() || !d.sources.empty())
        throw PvsFormatError("cannot encode .pvs: cell-portal data given but hasCellPortal is false");
    if (file.sourceRange)
    {
        const auto [first, end] = *file.sourceRange;
        if (!file.hasCellPortal)
            throw PvsFormatError("cannot encode .pvs: a source range without cell-portal data");
        if (!(first < end && end <= d.sources.size()))
            throw PvsFormatError("cannot encode .pvs: source range " + std::to_string(first) + ":" +
                                 std::to_string(end) + " outside the " + std::to_string(d.sources.size()) + " cells");
    }
    if (d.tiles)
    {
        if (!file.hasCellPortal)
            throw PvsFormatError("cannot encode .pvs: tile keys without cell-portal data");
        checkTilesEncodable(*d.tiles, d.objectCount);
    }
    const ViewCellPvs& v = file.viewCells;
    if (file.hasViewCells)
        checkViewCellsEncodable(v, d.objectCount);
    else if (!v.cellIndices.empty() || !v.cells.empty() || !v.pvs.empty() || v.totalCells != 0)
        throw PvsFormatError("cannot encode .pvs: view cells given but hasViewCells is false");
}

template <typename Write> void writeSection(PvsByteWriter& out, const PvsTag& tag, Write&& write)
{
    const std::size_t body = beginSection(out, tag, SectionRequired);
    write();
    endPart(out, body);
}

void writeModelHeader(PvsByteWriter& out, const PvsFile& file)
{
    out.u64(file.data.fingerprint);
    out.u32(file.data.objectCount);
    out.string(file.modelPath);
}

void readModelHeader(PvsByteReader& s, PvsFile& file)
{
    file.data.fingerprint = s.u64();
    file.data.objectCount = s.u32();
    file.modelPath = s.string();
}

void readBuildIdentity(PvsByteReader& s, PvsFile& file)
{
    file.method = s.string();
    file.options = s.string();
    file.nearDistance = s.finiteF64();
    if (file.nearDistance < 0.0)
    {
        std::ostringstream text;
        text << "negative near distance " << file.nearDistance;
        s.fail(text.str());
    }
}

void readGeometryFingerprint(PvsByteReader& s, PvsFile& file)
{
    file.geometryFingerprint = s.u64();
}

void readCellPortalSection(PvsByteReader& s, PvsFile& file)
{
    readCellPortalParts(s, file.data, 2);
    file.hasCellPortal = true;
}

// After CPDT: which sources the file baked; every other one must be a placeholder, so that a range
// file can never pass for complete data with empty PVS.
void readSourceRangeSection(PvsByteReader& s, PvsFile& file)
{
    if (!file.hasCellPortal)
        s.fail("a source range without cell-portal data");
    const std::uint32_t first = s.u32(), end = s.u32();
    const std::vector<SourceCellVisibility>& sources = file.data.sources;
    if (!(first < end && end <= sources.size()))
        s.fail("source range " + std::to_string(first) + ":" + std::to_string(end) + " outside the " +
               std::to_string(sources.size()) + " cells");
    for (std::size_t c = 0; c < sources.size(); ++c)
        if ((c < first || c >= end) && !isPlaceholderSource(sources[c]))
            s.fail("source cell " + std::to_string(c) + " outside the range " + std::to_string(first) + ":" +
                   std::to_string(end) + " holds data");
    file.sourceRange = std::make_pair(first, end);
}

// After CPDT: the tile of each object of a bake on a whole paged database.
void readTileSection(PvsByteReader& s, PvsFile& file)
{
    if (!file.hasCellPortal)
        s.fail("tile keys without cell-portal data");
    file.data.tiles = std::make_shared<const SceneTiles>(readTiles(s, file.data.objectCount));
}

void readViewCellSection(PvsByteReader& s, PvsFile& file)
{
    file.viewCells = readViewCells(s, file.data.objectCount);
    file.hasViewCells = true;
}

// Version 2's sections in the order it stores them; the first three in every file.
struct KnownSection
{
    const PvsTag& tag;
    bool inEveryFile;
    bool holdsParts; // framed parts inside: a truncated file can say in which one it ends
    void (*read)(PvsByteReader&, PvsFile&);
};
const KnownSection KnownSections[] = {
    {ModelTag, true, false, readModelHeader},
    {BuildTag, true, false, readBuildIdentity},
    {GeometryTag, true, false, readGeometryFingerprint},
    {CellPortalTag, false, true, readCellPortalSection},
    {SourceRangeTag, false, false, readSourceRangeSection},
    {TileTag, false, false, readTileSection},
    {ViewCellTag, false, false, readViewCellSection},
};
constexpr std::size_t KnownSectionCount = std::size(KnownSections);

std::string hex(std::uint32_t value)
{
    char text[11];
    std::snprintf(text, sizeof text, "0x%08x", value);
    return text;
}

std::string sectionText(const PvsTag& tag)
{
    return std::string("section '") + tag.tag + "' (" + tag.name + ")";
}

// Fails unless every section of every file in KnownSections[from, to) has been read, i.e. unless
// none of them lies in that range.
void requirePresent(std::size_t from, std::size_t to, const std::string& where)
{
    for (std::size_t k = from; k < to; ++k)
        if (KnownSections[k].inEveryFile)
            throw PvsFormatError("missing " + sectionText(KnownSections[k].tag) + " " + where);
}

// Reads version 2's sections up to the end of `in`. `complete` is false for the part of a truncated
// file that is there: sections then may be missing at its end.
PvsFile readSectionsVersion2(PvsByteReader& in, bool complete)
{
    PvsFile file;
    file.version = 2;
    file.hasCellPortal = false;
    std::size_t next = 0; // the first known section still allowed
    while (in.remaining() != 0)
    {
        in.setContext("section header");
        const std::size_t at = in.position();
        const std::uint32_t tag = in.u32();
        const std::uint32_t flags = in.u32();
        const std::uint64_t length = in.u64();
        std::size_t k = 0;
        while (k < KnownSectionCount && tagValue(KnownSections[k].tag) != tag)
            ++k;
        if (k == KnownSectionCount)
        {
            if (flags & SectionRequired)
                throw PvsFormatError("required section '" + tagText(tag) + "' at byte " + std::to_string(at) +
                                     " is unknown to this osgVis (the file was written by a newer osgVis)");
            in.setContext("an unknown optional section");
            in.take(length); // skipped: a reader that does not know it may do without it
            continue;
        }
        const KnownSection& known = KnownSections[k];
        if (flags != SectionRequired)
            throw PvsFormatError(sectionText(known.tag) + " at byte " + std::to_string(at) + " has flags " +
                                 hex(flags) + " where " + hex(SectionRequired) + " is expected");
        if (k < next)
            throw PvsFormatError(sectionText(known.tag) + " at byte " + std::to_string(at) +
                                 " out of order or repeated (version 2 stores HEAD, BILD, GEOM, CPDT, CPRG, TILE, VCEL in this "
                                 "order, each at most once)");
        requirePresent(next, k, "before byte " + std::to_string(at));
        in.setContext(known.tag.name);
        if (!complete && known.holdsParts && length > in.remaining())
        {
            PvsByteReader rest = in;
            PvsByteReader there = rest.take(rest.remaining());
            known.read(there, file); // throws where the part that is cut short ends
        }
        PvsByteReader body = in.take(length);
        known.read(body, file);
        closePart(body);
        next = k + 1;
    }
    if (complete)
        requirePresent(next, KnownSectionCount, "at the end of the file");
    return file;
}

PvsFile readSectionsVersion1(PvsByteReader& in)
{
    PvsFile file;
    file.version = 1;
    file.method = "cellportal";
    readPart(in, ModelTag, [&](PvsByteReader& s) { readModelHeader(s, file); });
    readCellPortalParts(in, file.data, 1);
    return file;
}

PvsFile readSections(PvsByteReader& in, std::uint32_t version, bool complete)
{
    return version == 1 ? readSectionsVersion1(in) : readSectionsVersion2(in, complete);
}
} // namespace

std::vector<std::uint8_t> encodePvs(const PvsFile& file)
{
    checkEncodable(file);
    PvsByteWriter out;
    for (std::uint8_t byte : Magic)
        out.u8(byte);
    out.u32(PvsFormatVersion);
    out.u64(0); // body size, patched below
    writeSection(out, ModelTag, [&] { writeModelHeader(out, file); });
    writeSection(out, BuildTag,
                 [&]
                 {
                     out.string(file.method);
                     out.string(file.options);
                     out.f64(file.nearDistance);
                 });
    writeSection(out, GeometryTag, [&] { out.u64(file.geometryFingerprint); });
    if (file.hasCellPortal)
        writeSection(out, CellPortalTag, [&] { writeCellPortalParts(out, file.data); });
    if (file.sourceRange)
        writeSection(out, SourceRangeTag,
                     [&]
                     {
                         out.u32(file.sourceRange->first);
                         out.u32(file.sourceRange->second);
                     });
    if (file.data.tiles)
        writeSection(out, TileTag, [&] { writeTiles(out, *file.data.tiles); });
    if (file.hasViewCells)
        writeSection(out, ViewCellTag, [&] { writeViewCells(out, file.viewCells); });

    out.patchU64(12, out.size() - HeaderBytes);
    out.u32(crc32(out.bytes().data(), out.size()));
    // The writer's own output must read back: this catches invalid data (bad indices, NaN) at save.
    try
    {
        decodePvs(out.bytes().data(), out.size());
    }
    catch (const PvsFormatError& e)
    {
        throw PvsFormatError(std::string("cannot encode .pvs, the data are inconsistent: ") + e.what());
    }
    return std::move(out.bytes());
}

PvsFile decodePvs(const std::uint8_t* bytes, std::size_t size)
{
    PvsByteReader header(bytes, 0, size);
    const std::size_t magicBytes = std::min(size, sizeof Magic);
    if (magicBytes > 0 && std::memcmp(bytes, Magic, magicBytes) != 0)
        throw PvsFormatError("not a .pvs file: bad magic (the file must start with \"OSGVPVS\\0\")");
    for (std::size_t i = 0; i < sizeof Magic; ++i)
        header.u8();
    header.setContext("format version");
    const std::uint32_t version = header.u32();
    if (version > PvsFormatVersion)
        throw PvsFormatError("unsupported .pvs format version " + std::to_string(version) +
                             ": this osgVis reads versions 1 to " + std::to_string(PvsFormatVersion) +
                             " (the file was written by a newer osgVis)");
    if (version == 0)
        throw PvsFormatError("invalid .pvs format version 0");
    header.setContext("header");
    const std::uint64_t bodySize = header.u64();

    const std::size_t available = size - HeaderBytes;
    if (bodySize > available || available - bodySize < ChecksumBytes)
    {
        // Parse what is there, so the message says in which part the file ends.
        const bool bodyComplete = bodySize <= available;
        PvsByteReader body(bytes, HeaderBytes, bodyComplete ? HeaderBytes + std::size_t(bodySize) : size);
        readSections(body, version, bodyComplete);
        throw PvsFormatError("truncated at byte " + std::to_string(size) + " while reading " +
                             (bodyComplete ? "the checksum" : "the next section") + " (the header announces " +
                             std::to_string(bodySize) + " body bytes)");
    }
    const std::size_t checksumAt = HeaderBytes + static_cast<std::size_t>(bodySize);
    if (available - bodySize > ChecksumBytes)
        throw PvsFormatError(std::to_string(size - checksumAt - ChecksumBytes) +
                             " unexpected bytes after the checksum at byte " +
                             std::to_string(checksumAt + ChecksumBytes));
    PvsByteReader trailer(bytes, checksumAt, size);
    trailer.setContext("checksum");
    const std::uint32_t stored = trailer.u32();
    const std::uint32_t computed = crc32(bytes, checksumAt);
    if (stored != computed)
        throw PvsFormatError("checksum mismatch: the file stores " + hex(stored) + " but its bytes give " +
                             hex(computed) + " (the file is corrupt)");

    PvsByteReader body(bytes, HeaderBytes, checksumAt);
    PvsFile file = readSections(body, version, true);
    if (body.remaining() != 0)
        body.fail(std::to_string(body.remaining()) + " unexpected bytes after the last section");
    return file;
}

void writePvsFile(const std::string& path, const PvsFile& file)
{
    const std::vector<std::uint8_t> bytes = encodePvs(file);
    const std::string temporary = path + ".tmp";
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out)
            throw PvsFormatError("cannot write .pvs file '" + temporary + "': " + std::strerror(errno));
        out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
        out.close();
        if (!out)
        {
            std::remove(temporary.c_str());
            throw PvsFormatError("cannot write .pvs file '" + temporary + "' (disk full?)");
        }
    }
    if (std::rename(temporary.c_str(), path.c_str()) != 0)
    {
        const std::string reason = std::strerror(errno);
        std::remove(temporary.c_str());
        throw PvsFormatError("cannot rename '" + temporary + "' to '" + path + "': " + reason);
    }
}

PvsFile readPvsFile(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw PvsFormatError("cannot open .pvs file '" + path + "': " + std::strerror(errno));
    const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad())
        throw PvsFormatError("cannot read .pvs file '" + path + "'");
    try
    {
        return decodePvs(bytes.data(), bytes.size());
    }
    catch (const PvsFormatError& e)
    {
        throw PvsFormatError(path + ": " + e.what());
    }
}
} // namespace osgVis::core
