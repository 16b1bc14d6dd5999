#include "sha256.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace collide::external {
namespace {

// FIPS 180-4, section 4.2.2: the first 32 bits of the fractional parts of the cube roots of
// the first 64 primes.
constexpr std::array<std::uint32_t, 64> round_constants = {
    0x428a2f98, 0x71374491, 0xb5c0fbcf, 0xe9b5dba5, 0x3956c25b, 0x59f111f1, 0x923f82a4, 0xab1c5ed5,
    0xd807aa98, 0x12835b01, 0x243185be, 0x550c7dc3, 0x72be5d74, 0x80deb1fe, 0x9bdc06a7, 0xc19bf174,
    0xe49b69c1, 0xefbe4786, 0x0fc19dc6, 0x240ca1cc, 0x2de92c6f, 0x4a7484aa, 0x5cb0a9dc, 0x76f988da,
    0x983e5152, 0xa831c66d, 0xb00327c8, 0xbf597fc7, 0xc6e00bf3, 0xd5a79147, 0x06ca6351, 0x14292967,
    0x27b70a85, 0x2e1b2138, 0x4d2c6dfc, 0x53380d13, 0x650a7354, 0x766a0abb, 0x81c2c92e, 0x92722c85,
    0xa2bfe8a1, 0xa81a664b, 0xc24b8b70, 0xc76c51a3, 0xd192e819, 0xd6990624, 0xf40e3585, 0x106aa070,
    0x19a4c116, 0x1e376c08, 0x2748774c, 0x34b0bcb5, 0x391c0cb3, 0x4ed8aa4a, 0x5b9cca4f, 0x682e6ff3,
    0x748f82ee, 0x78a5636f, 0x84c87814, 0x8cc70208, 0x90befffa, 0xa4506ceb, 0xbef9a3f7, 0xc67178f2};

std::uint32_t rotr(std::uint32_t x, int n) { return (x >> n) | (x << (32 - n)); }

// One 64-byte block into the hash state (section 6.2.2).
void compress(std::array<std::uint32_t, 8>& h, const unsigned char* block) {
    std::array<std::uint32_t, 64> w{};
    for (int t = 0; t < 16; ++t)
        w[t] = std::uint32_t(block[4 * t]) << 24 | std::uint32_t(block[4 * t + 1]) << 16 |
               std::uint32_t(block[4 * t + 2]) << 8 | std::uint32_t(block[4 * t + 3]);
    for (int t = 16; t < 64; ++t) {
        const std::uint32_t s0 = rotr(w[t - 15], 7) ^ rotr(w[t - 15], 18) ^ (w[t - 15] >> 3);
        const std::uint32_t s1 = rotr(w[t - 2], 17) ^ rotr(w[t - 2], 19) ^ (w[t - 2] >> 10);
        w[t] = w[t - 16] + s0 + w[t - 7] + s1;
    }
    auto v = h;  // a, b, ..., h
    for (int t = 0; t < 64; ++t) {
        const std::uint32_t e = v[4], a = v[0];
        const std::uint32_t t1 = v[7] + (rotr(e, 6) ^ rotr(e, 11) ^ rotr(e, 25)) + ((e & v[5]) ^ (~e & v[6])) +
                                 round_constants[t] + w[t];
        const std::uint32_t t2 = (rotr(a, 2) ^ rotr(a, 13) ^ rotr(a, 22)) + ((a & v[1]) ^ (a & v[2]) ^ (v[1] & v[2]));
        v = {t1 + t2, a, v[1], v[2], v[3] + t1, e, v[5], v[6]};
    }
    for (int k = 0; k < 8; ++k) h[k] += v[k];
}

// The hash state over a stream of bytes: whole 64-byte blocks are compressed as they come,
// the rest waits for more (so a file is hashed in pieces, never held whole).
class Sha256 {
public:
    void update(std::string_view bytes) {
        length_ += bytes.size();
        if (!pending_.empty()) {
            const std::size_t take = std::min(bytes.size(), 64 - pending_.size());
            pending_.append(bytes.substr(0, take));
            bytes.remove_prefix(take);
            if (pending_.size() < 64) return;
            compress(h_, reinterpret_cast<const unsigned char*>(pending_.data()));
            pending_.clear();
        }
        const std::size_t full = bytes.size() / 64 * 64;
        for (std::size_t i = 0; i < full; i += 64) compress(h_, reinterpret_cast<const unsigned char*>(bytes.data() + i));
        pending_.assign(bytes.substr(full));
    }
    std::string finish() {
        // Padding: a 1 bit, zeros, and the message length in bits as a 64-bit big-endian number.
        std::string tail = pending_;
        tail += char(0x80);
        while (tail.size() % 64 != 56) tail += '\0';
        const std::uint64_t bits = length_ * 8;
        for (int k = 7; k >= 0; --k) tail += char((bits >> (8 * k)) & 0xff);
        for (std::size_t i = 0; i < tail.size(); i += 64) compress(h_, reinterpret_cast<const unsigned char*>(tail.data() + i));
        std::string out;
        char hex[9];
        for (std::uint32_t word : h_) {
            std::snprintf(hex, sizeof hex, "%08x", word);
            out += hex;
        }
        return out;
    }

private:
    // Initial hash value: the fractional parts of the square roots of the first 8 primes.
    std::array<std::uint32_t, 8> h_ = {0x6a09e667, 0xbb67ae85, 0x3c6ef372, 0xa54ff53a,
                                       0x510e527f, 0x9b05688c, 0x1f83d9ab, 0x5be0cd19};
    std::string pending_;
    std::uint64_t length_ = 0;
};

}  // namespace

std::string sha256_hex(std::string_view bytes) {
    Sha256 hash;
    hash.update(bytes);
    return hash.finish();
}

std::string sha256_file(const std::string& path, std::uintmax_t max_bytes) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(path + ": cannot read it to hash it");
    Sha256 hash;
    std::string chunk(1 << 20, '\0');
    for (std::uintmax_t left = max_bytes; left > 0 && in;) {
        in.read(chunk.data(), std::streamsize(std::min<std::uintmax_t>(chunk.size(), left)));
        const auto got = std::size_t(in.gcount());
        hash.update(std::string_view(chunk.data(), got));
        left -= got;
        if (got == 0) break;
    }
    if (in.bad()) throw std::runtime_error(path + ": a read failed while it was hashed");
    return hash.finish();
}

}  // namespace collide::external
