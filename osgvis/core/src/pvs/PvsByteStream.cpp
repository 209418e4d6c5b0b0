// SPDX-License-Identifier: MIT
#include "PvsByteStream.h"

#include <cmath>
#include <cstring>

namespace osgVis::core
{
std::uint32_t encodableCount(std::size_t count, const char* what)
{
    if (count > 0xFFFFFFFFu)
        throw PvsFormatError(std::string("cannot encode .pvs: too many ") + what);
    return static_cast<std::uint32_t>(count);
}

void PvsByteWriter::u32(std::uint32_t value)
{
    for (int i = 0; i < 4; ++i)
        _bytes.push_back(static_cast<std::uint8_t>(value >> (8 * i)));
}

void PvsByteWriter::u64(std::uint64_t value)
{
    for (int i = 0; i < 8; ++i)
        _bytes.push_back(static_cast<std::uint8_t>(value >> (8 * i)));
}

void PvsByteWriter::f64(double value)
{
    std::uint64_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    u64(bits);
}

void PvsByteWriter::varint(std::uint64_t value)
{
    while (value >= 0x80)
    {
        _bytes.push_back(static_cast<std::uint8_t>(value | 0x80));
        value >>= 7;
    }
    _bytes.push_back(static_cast<std::uint8_t>(value));
}

void PvsByteWriter::string(const std::string& value)
{
    if (value.size() > 0xFFFFFFFFu)
        throw PvsFormatError("cannot write a string of " + std::to_string(value.size()) + " bytes to a .pvs file");
    u32(static_cast<std::uint32_t>(value.size()));
    _bytes.insert(_bytes.end(), value.begin(), value.end());
}

void PvsByteWriter::box(const Aabb& value)
{
    for (int i = 0; i < 3; ++i)
        f64(value.min[i]);
    for (int i = 0; i < 3; ++i)
        f64(value.max[i]);
}

void PvsByteWriter::patchU64(std::size_t offset, std::uint64_t value)
{
    for (int i = 0; i < 8; ++i)
        _bytes[offset + i] = static_cast<std::uint8_t>(value >> (8 * i));
}

PvsByteReader::PvsByteReader(const std::uint8_t* bytes, std::size_t begin, std::size_t end)
    : _bytes(bytes), _pos(begin), _end(end)
{
}

void PvsByteReader::fail(const std::string& message) const
{
    throw PvsFormatError(message + " at byte " + std::to_string(_pos) + " while reading " + _context);
}

void PvsByteReader::need(std::size_t count)
{
    if (count > remaining())
        throw PvsFormatError("truncated at byte " + std::to_string(_end) + " while reading " + _context);
}

std::uint8_t PvsByteReader::u8()
{
    need(1);
    return _bytes[_pos++];
}

template <typename T> T PvsByteReader::littleEndian()
{
    need(sizeof(T));
    T value = 0;
    for (std::size_t i = 0; i < sizeof(T); ++i)
        value |= T(_bytes[_pos + i]) << (8 * i);
    _pos += sizeof(T);
    return value;
}

std::uint32_t PvsByteReader::u32()
{
    return littleEndian<std::uint32_t>();
}

std::uint64_t PvsByteReader::u64()
{
    return littleEndian<std::uint64_t>();
}

double PvsByteReader::f64()
{
    const std::uint64_t bits = u64();
    double value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
}

double PvsByteReader::finiteF64()
{
    const double value = f64();
    if (!std::isfinite(value))
    {
        _pos -= 8;
        fail("non-finite number");
    }
    return value;
}

std::uint64_t PvsByteReader::varint()
{
    const std::size_t start = _pos;
    std::uint64_t value = 0;
    for (int shift = 0;; shift += 7)
    {
        const std::uint8_t byte = u8();
        // note: the tenth byte may carry only the top bit of a u64; more is an overlong encoding.
        if (shift == 63 && byte > 1)
        {
            _pos = start;
            fail("varint overflows 64 bits");
        }
        value |= std::uint64_t(byte & 0x7F) << shift;
        if (!(byte & 0x80))
        {
            // note: a zero last byte after others is a longer spelling of a shorter varint; each
            // value has one spelling, so a file that reads back re-encodes to the same bytes.
            if (byte == 0 && shift > 0)
            {
                _pos = start;
                fail("overlong varint");
            }
            return value;
        }
    }
}

namespace
{
bool isWellFormedUtf8(const std::uint8_t* s, std::size_t size)
{
    std::size_t i = 0;
    while (i < size)
    {
        const std::uint8_t lead = s[i];
        std::size_t length;
        std::uint32_t code;
        if (lead < 0x80)
            length = 1, code = lead;
        else if ((lead & 0xE0) == 0xC0)
            length = 2, code = lead & 0x1Fu;
        else if ((lead & 0xF0) == 0xE0)
            length = 3, code = lead & 0x0Fu;
        else if ((lead & 0xF8) == 0xF0)
            length = 4, code = lead & 0x07u;
        else
            return false;
        if (length > size - i)
            return false;
        for (std::size_t k = 1; k < length; ++k)
        {
            if ((s[i + k] & 0xC0) != 0x80)
                return false;
            code = (code << 6) | (s[i + k] & 0x3Fu);
        }
        static const std::uint32_t smallest[5] = {0, 0, 0x80, 0x800, 0x10000};
        if (code < smallest[length] || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF))
            return false; // overlong, out of range, or a surrogate
        i += length;
    }
    return true;
}
} // namespace

std::string PvsByteReader::string()
{
    const std::uint32_t size = u32();
    if (size > remaining())
        throw PvsFormatError("truncated at byte " + std::to_string(_end) + " while reading " + _context +
                             " (a string of " + std::to_string(size) + " bytes)");
    if (!isWellFormedUtf8(_bytes + _pos, size))
        fail("string that is not well-formed UTF-8");
    std::string value(reinterpret_cast<const char*>(_bytes + _pos), size);
    _pos += size;
    return value;
}

Aabb PvsByteReader::finiteBox()
{
    Aabb value;
    for (int i = 0; i < 3; ++i)
        value.min[i] = finiteF64();
    for (int i = 0; i < 3; ++i)
        value.max[i] = finiteF64();
    return value;
}

PvsByteReader PvsByteReader::take(std::uint64_t length)
{
    if (length > remaining())
        throw PvsFormatError("truncated at byte " + std::to_string(_end) + " while reading " + _context + " (" +
                             std::to_string(length) + " bytes announced, " + std::to_string(remaining()) + " present)");
    PvsByteReader part(_bytes, _pos, _pos + static_cast<std::size_t>(length));
    part._context = _context;
    _pos += static_cast<std::size_t>(length);
    return part;
}

void PvsByteReader::requireItems(std::uint64_t count, std::size_t minItemBytes)
{
    if (count > remaining() / minItemBytes)
        throw PvsFormatError("count " + std::to_string(count) + " of items of at least " +
                             std::to_string(minItemBytes) + " bytes exceeds the " + std::to_string(remaining()) +
                             " bytes left at byte " + std::to_string(_pos) + " while reading " + _context);
}
} // namespace osgVis::core
