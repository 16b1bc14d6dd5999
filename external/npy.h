// The NumPy .npy format (version 1.0 and 2.0, little-endian float64 only), which the external
// solver protocol uses for arrays (docs/your-solver.md): NumPy reads and writes it with
// np.load/np.save, and any other language with a dozen lines (the C client shows how).
// A file that comes back from an outside program is untrusted: read_npy checks every part of
// it and names what is wrong.
#pragma once

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace collide::external {

class NpyError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct NpyArray {
    std::vector<std::size_t> shape;
    std::vector<double> data;  // C order
};

// The bytes of a version 1.0 .npy file holding `data` (C order, '<f8') of the given shape.
std::string npy_bytes(const std::vector<double>& data, const std::vector<std::size_t>& shape);

// Parses .npy bytes; throws NpyError naming the fault ("not a .npy file", "dtype '<f4', expected
// '<f8' (float64)", "Fortran order", "shape (3, 4) holds 12 numbers but the file has 11", a
// header over NumPy's own 10,000-byte limit, a header key given twice, ...).
NpyArray parse_npy(const std::string& bytes);

// Reads and parses a regular file; NpyError messages start with the file name. The header is
// read first (at most 10,012 bytes) and judged before the data: with `expected_shape` a file of
// another shape is refused unread, and a file whose size is not the header plus its shape's
// data is refused before any data is read, so an 8 GiB answer to a 1 KB request costs nothing.
NpyArray read_npy(const std::string& path, const std::optional<std::vector<std::size_t>>& expected_shape = std::nullopt);

// "(3, 4)" as NumPy prints a shape.
std::string shape_text(const std::vector<std::size_t>& shape);

}  // namespace collide::external
