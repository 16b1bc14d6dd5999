// Numbers as text that reads back to the same value: provenance attributes and messages.
// std::to_string(double) prints "%f", six digits after the point: 5e-101 becomes "0.000000"
// and 1e-7 "0.000000", so a provenance record could not say which value a run used. Here each
// double is written as the shortest decimal that parses back to the identical double (at most
// 17 significant digits, the most a binary64 value needs; IEEE 754 section 5.12.2).
#pragma once

#include <charconv>
#include <string>
#include <system_error>

namespace collide {

// 0.1 -> "0.1", 5e-101 -> "5e-101", 1.0/3 -> "0.3333333333333333"; inf -> "inf", NaN -> "nan".
inline std::string round_trip_text(double value) {
    char buffer[32];  // the longest shortest form, "-2.2250738585072014e-308", has 24 characters
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

}  // namespace collide
