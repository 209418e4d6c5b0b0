// SPDX-License-Identifier: MIT
#pragma once
// The framing of the `.pvs` file's pieces (docs/pvs-format.md). A *part* is a tag, a u64 length and
// its body: version 1's sections, and the parts inside version 2's cell-portal section. A version 2
// *section* adds a u32 flags word between tag and length (bit 0: required).
#include "PvsByteStream.h"

#include <cstdint>
#include <string>

namespace osgVis::core
{
struct PvsTag
{
    char tag[5];
    const char* name; // what messages call it
};

constexpr std::uint32_t SectionRequired = 1u;

std::uint32_t tagValue(const PvsTag& tag);
// The four bytes as text, '?' for what is not printable ASCII.
std::string tagText(std::uint32_t value);

// Writes the tag and a zero length; returns where the body starts, for endPart.
std::size_t beginPart(PvsByteWriter& out, const PvsTag& tag);
std::size_t beginSection(PvsByteWriter& out, const PvsTag& tag, std::uint32_t flags);
// Patches the length written before `bodyStart` (parts and sections alike).
void endPart(PvsByteWriter& out, std::size_t bodyStart);

// Reads a part that must carry `tag` and returns a reader over its body; `read(body)` must use the
// body exactly ("N unread bytes at the end of the section" otherwise).
PvsByteReader openPart(PvsByteReader& in, const PvsTag& tag);
void closePart(const PvsByteReader& body);
template <typename Read> void readPart(PvsByteReader& in, const PvsTag& tag, Read&& read)
{
    PvsByteReader body = openPart(in, tag);
    read(body);
    closePart(body);
}
// Writes a part carrying `tag` whose body `write()` writes.
template <typename Write> void writePart(PvsByteWriter& out, const PvsTag& tag, Write&& write)
{
    const std::size_t body = beginPart(out, tag);
    write();
    endPart(out, body);
}
} // namespace osgVis::core
