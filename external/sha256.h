// SHA-256 (FIPS 180-4) of a file: the provenance of an outside solver names the hash of the
// program it ran, so a reader can check with `sha256sum FILE` which version produced a result.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace collide::external {

// Lower-case hex digest of `bytes`.
std::string sha256_hex(std::string_view bytes);

// The digest of the file's contents (of its first `max_bytes` bytes when it is longer), read
// in 1 MiB pieces; throws std::runtime_error when it cannot be read.
std::string sha256_file(const std::string& path, std::uintmax_t max_bytes = UINTMAX_MAX);

}  // namespace collide::external
