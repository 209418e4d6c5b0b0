// SPDX-License-Identifier: MIT
#include "PvsSections.h"

namespace osgVis::core
{
std::uint32_t tagValue(const PvsTag& tag)
{
    std::uint32_t value = 0;
    for (int i = 0; i < 4; ++i)
        value |= std::uint32_t(std::uint8_t(tag.tag[i])) << (8 * i);
    return value;
}

std::string tagText(std::uint32_t value)
{
    std::string text;
    for (int i = 0; i < 4; ++i)
    {
        const char c = static_cast<char>(value >> (8 * i));
        text += (c >= 0x20 && c < 0x7F) ? c : '?';
    }
    return text;
}

std::size_t beginPart(PvsByteWriter& out, const PvsTag& tag)
{
    out.u32(tagValue(tag));
    out.u64(0);
    return out.size();
}

std::size_t beginSection(PvsByteWriter& out, const PvsTag& tag, std::uint32_t flags)
{
    out.u32(tagValue(tag));
    out.u32(flags);
    out.u64(0);
    return out.size();
}

void endPart(PvsByteWriter& out, std::size_t bodyStart)
{
    out.patchU64(bodyStart - 8, out.size() - bodyStart);
}

PvsByteReader openPart(PvsByteReader& in, const PvsTag& tag)
{
    in.setContext(tag.name);
    const std::size_t at = in.position();
    const std::uint32_t value = in.u32();
    if (value != tagValue(tag))
        throw PvsFormatError("section '" + tagText(value) + "' at byte " + std::to_string(at) + " where '" + tag.tag +
                             "' (" + tag.name + ") was expected");
    return in.take(in.u64());
}

void closePart(const PvsByteReader& body)
{
    if (body.remaining() != 0)
        body.fail(std::to_string(body.remaining()) + " unread bytes at the end of the section");
}
} // namespace osgVis::core
