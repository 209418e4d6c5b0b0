// SPDX-License-Identifier: MIT
#pragma once
// The primitive encoding of the `.pvs` file (docs/pvs-format.md): little-endian fixed-width
// integers, IEEE-754 doubles by bit pattern, LEB128 varints, length-prefixed strings and boxes, written
// value by value whatever the host's byte order. The reader checks every byte it takes against the
// end it was given and names the part of the file it was reading when bytes run out.
#include <osgVis/core/pvs/PvsFormat.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace osgVis::core
{
// `count` as the u32 a count field holds; throws "cannot encode .pvs: too many <what>" past it.
std::uint32_t encodableCount(std::size_t count, const char* what);

class PvsByteWriter
{
public:
    void u8(std::uint8_t value) { _bytes.push_back(value); }
    void u32(std::uint32_t value);
    void u64(std::uint64_t value);
    void f64(double value);
    void varint(std::uint64_t value);
    void string(const std::string& value); // u32 byte length, then the bytes
    void box(const Aabb& value);           // min x, y, z, max x, y, z as f64
    // Overwrites a u64 written earlier at `offset` (a section length known only after its body).
    void patchU64(std::size_t offset, std::uint64_t value);

    std::size_t size() const { return _bytes.size(); }
    std::vector<std::uint8_t>& bytes() { return _bytes; }

private:
    std::vector<std::uint8_t> _bytes;
};

class PvsByteReader
{
public:
    // Reads bytes[begin, end); offsets in messages count from `bytes`, i.e. from the file's start.
    PvsByteReader(const std::uint8_t* bytes, std::size_t begin, std::size_t end);

    // What is being read, for messages ("truncated at byte N while reading portals").
    void setContext(const char* what) { _context = what; }
    const char* context() const { return _context; }

    std::uint8_t u8();
    std::uint32_t u32();
    std::uint64_t u64();
    double f64();       // any bit pattern; see finiteF64
    double finiteF64(); // throws on NaN or infinity
    std::uint64_t varint();
    std::string string(); // also checks the bytes are well-formed UTF-8
    Aabb finiteBox();     // six finite f64 (min may still lie above max)
    // Throws unless `count` items of at least `minItemBytes` each fit in the bytes left, so that a
    // corrupted count is reported before anything is allocated for it.
    void requireItems(std::uint64_t count, std::size_t minItemBytes);

    // A reader over the next `length` bytes (a section's body); this reader moves past them.
    PvsByteReader take(std::uint64_t length);

    std::size_t position() const { return _pos; }
    std::size_t remaining() const { return _end - _pos; }
    // Throws PvsFormatError "<message> at byte N while reading <context>".
    [[noreturn]] void fail(const std::string& message) const;

private:
    void need(std::size_t count);
    template <typename T> T littleEndian(); // an unsigned integer of sizeof(T) bytes

    const std::uint8_t* _bytes;
    std::size_t _pos, _end;
    const char* _context = "header";
};
} // namespace osgVis::core
