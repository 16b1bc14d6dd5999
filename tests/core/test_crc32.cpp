// CRC-32 against the published check values of the IEEE 802.3 / zlib CRC (the "check" value of
// the CRC catalogue: CRC-32 of the ASCII digits "123456789" is 0xCBF43926), and the table
// against the bit-at-a-time definition it replaces.
#include <gtest/gtest.h>

#include <string>

#include "core/numerics/crc32.h"

namespace collide {
namespace {

std::uint32_t crc32_bit_at_a_time(std::string_view bytes) {
    std::uint32_t crc = 0xFFFFFFFFu;
    for (unsigned char byte : bytes) {
        crc ^= byte;
        for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

TEST(Crc32, PublishedCheckValues) {
    EXPECT_EQ(crc32("123456789"), 0xCBF43926u);
    EXPECT_EQ(crc32(""), 0x00000000u);
    EXPECT_EQ(crc32("The quick brown fox jumps over the lazy dog"), 0x414FA339u);
    EXPECT_EQ(crc32_text("123456789"), "crc32:cbf43926");
}

TEST(Crc32, TableGivesTheBitAtATimeValueForEveryByte) {
    std::string all;
    for (int byte = 0; byte < 256; ++byte) {
        const std::string one(1, char(byte));
        EXPECT_EQ(crc32(one), crc32_bit_at_a_time(one)) << "byte " << byte;
        all += one;
    }
    EXPECT_EQ(crc32(all), crc32_bit_at_a_time(all));
}

// Slicing-by-8 folds eight bytes per step and the rest one at a time: every length from 0 to 40
// and every start within a word gives the bit-at-a-time value (the tail and the word loop both).
TEST(Crc32, EightBytesAtATimeGiveTheBitAtATimeValueForEveryLengthAndStart) {
    std::string text;
    for (int k = 0; k < 48; ++k) text += char((k * 151 + 7) & 0xFF);
    for (std::size_t start = 0; start < 8; ++start)
        for (std::size_t length = 0; length + start <= 48 && length <= 40; ++length) {
            const std::string_view piece = std::string_view(text).substr(start, length);
            EXPECT_EQ(crc32(piece), crc32_bit_at_a_time(piece)) << "start " << start << ", length " << length;
        }
}

}  // namespace
}  // namespace collide
