// SPDX-License-Identifier: MIT
#pragma once
// CRC-32 (IEEE 802.3, reflected polynomial 0xEDB88320, as zlib and PNG use): catches every burst
// error up to 32 bits and any odd number of flipped bits, which is what a file checksum must do.
#include <cstddef>
#include <cstdint>

namespace osgVis::core
{
std::uint32_t crc32(const std::uint8_t* bytes, std::size_t size);
} // namespace osgVis::core
