#include "npy.h"

#include <bit>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>

namespace collide::external {
namespace {

constexpr char magic[] = "\x93NUMPY";
constexpr std::size_t magic_size = 6;
// Files bigger than this are refused before reading (a solver writing without end).
constexpr std::uintmax_t max_npy_bytes = std::uintmax_t(8) << 30;

bool is_quote(char c) { return c == '\'' || c == '"'; }

std::size_t skip_spaces(const std::string& text, std::size_t at) {
    const std::size_t end = text.find_first_not_of(" \t\n\r\f\v", at);
    return end == std::string::npos ? text.size() : end;
}

// The value of `key` in the header, a Python dict literal:
//   {'descr': '<f8', 'fortran_order': False, 'shape': (2, 3), }
// a (tuple), a 'string' or "string", True or False, as the text of the first quoted `key`
// followed by ':'. Read by hand, not with std::regex: libstdc++'s matcher recurses once per
// character it repeats over, and a header of 65,000 spaces overflowed the stack.
std::string header_value(const std::string& header, const std::string& key) {
    for (std::size_t at = header.find(key); at != std::string::npos; at = header.find(key, at + 1)) {
        const std::size_t after = at + key.size();
        if (at == 0 || after >= header.size() || !is_quote(header[at - 1]) || !is_quote(header[after])) continue;
        std::size_t i = skip_spaces(header, after + 1);
        if (i >= header.size() || header[i] != ':') continue;
        i = skip_spaces(header, i + 1);
        if (i >= header.size()) break;
        const char open = header[i];
        const std::size_t close = open == '(' ? header.find(')', i) : is_quote(open) ? header.find(open, i + 1)
                                                                                      : std::string::npos;
        if (close != std::string::npos) return header.substr(i, close - i + 1);
        for (const char* word : {"True", "False"})
            if (header.compare(i, std::strlen(word), word) == 0) return word;
    }
    throw NpyError("the header has no '" + key + "' entry");
}

std::vector<std::size_t> parse_shape(const std::string& text) {
    std::vector<std::size_t> shape;
    std::string inner = text.substr(1, text.size() - 2);
    std::stringstream in(inner);
    std::string item;
    while (std::getline(in, item, ',')) {
        const auto first = item.find_first_not_of(" \t");
        if (first == std::string::npos) continue;  // the trailing comma of (3,)
        const auto last = item.find_last_not_of(" \tL");
        const std::string digits = item.substr(first, last - first + 1);
        if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 15)
            throw NpyError("the shape " + text + " is not a tuple of whole numbers");
        shape.push_back(std::stoull(digits));
    }
    return shape;
}

}  // namespace

std::string shape_text(const std::vector<std::size_t>& shape) {
    std::string out = "(";
    for (std::size_t i = 0; i < shape.size(); ++i) out += (i ? ", " : "") + std::to_string(shape[i]);
    return out + (shape.size() == 1 ? ",)" : ")");
}

std::string npy_bytes(const std::vector<double>& data, const std::vector<std::size_t>& shape) {
    static_assert(std::numeric_limits<double>::is_iec559, "the protocol's arrays are IEEE 754 binary64");
    static_assert(std::endian::native == std::endian::little, "the protocol's arrays are little-endian: memcpy needs a little-endian host");
    std::string header = "{'descr': '<f8', 'fortran_order': False, 'shape': " + shape_text(shape) + ", }";
    // Magic (6) + version (2) + header length (2) + header, padded with spaces to a multiple of
    // 64 and ended by a newline (the format's rule, so the data is aligned).
    const std::size_t total = magic_size + 4 + header.size() + 1;
    header.append((64 - total % 64) % 64, ' ');
    header += '\n';
    std::string out(magic, magic_size);
    out += '\x01';
    out += '\x00';
    out += char(header.size() & 0xff);
    out += char((header.size() >> 8) & 0xff);
    out += header;
    const std::size_t start = out.size();
    out.resize(start + data.size() * sizeof(double));
    std::memcpy(out.data() + start, data.data(), data.size() * sizeof(double));
    return out;
}

NpyArray parse_npy(const std::string& bytes) {
    if (bytes.size() < magic_size + 4 || bytes.compare(0, magic_size, magic, magic_size) != 0)
        throw NpyError("not a .npy file (it does not start with \\x93NUMPY)");
    const unsigned major = static_cast<unsigned char>(bytes[6]);
    std::size_t header_length = 0, header_start = 0;
    if (major == 1) {
        header_length = std::size_t(static_cast<unsigned char>(bytes[8])) |
                        std::size_t(static_cast<unsigned char>(bytes[9])) << 8;
        header_start = 10;
    } else if (major == 2 || major == 3) {
        if (bytes.size() < 12) throw NpyError("the .npy header is cut short");
        for (int k = 0; k < 4; ++k) header_length |= std::size_t(static_cast<unsigned char>(bytes[8 + k])) << (8 * k);
        header_start = 12;
    } else {
        throw NpyError(".npy format version " + std::to_string(major) + " (expected 1, 2 or 3)");
    }
    if (bytes.size() < header_start + header_length) throw NpyError("the .npy header is cut short");
    const std::string header = bytes.substr(header_start, header_length);
    std::string descr = header_value(header, "descr");
    descr = descr.substr(1, descr.size() - 2);
    if (descr != "<f8" && descr != "f8" && descr != "=f8")
        throw NpyError("dtype '" + descr + "', expected '<f8' (little-endian float64)");
    if (header_value(header, "fortran_order") != "False")
        throw NpyError("Fortran order, expected C order (np.save writes C order for an ordinary array)");
    const std::string shape = header_value(header, "shape");
    if (shape.front() != '(') throw NpyError("the shape " + shape + " is not a tuple");
    NpyArray out;
    out.shape = parse_shape(shape);
    std::size_t count = 1;
    for (std::size_t n : out.shape) {
        if (n != 0 && count > (std::numeric_limits<std::size_t>::max() / sizeof(double)) / n)
            throw NpyError("the shape " + shape_text(out.shape) + " is too large");
        count *= n;
    }
    const std::size_t data_bytes = bytes.size() - header_start - header_length;
    if (data_bytes != count * sizeof(double))
        throw NpyError("the shape " + shape_text(out.shape) + " holds " + std::to_string(count) +
                       " numbers (" + std::to_string(count * sizeof(double)) + " bytes) but the file has " +
                       std::to_string(data_bytes) + " bytes of data");
    out.data.resize(count);
    if (count) std::memcpy(out.data.data(), bytes.data() + header_start + header_length, data_bytes);
    return out;
}

NpyArray read_npy(const std::string& path) {
    std::error_code ec;
    const auto size = std::filesystem::file_size(path, ec);
    if (ec) throw NpyError(path + ": cannot read it: " + ec.message());
    if (size > max_npy_bytes) throw NpyError(path + ": " + std::to_string(size) + " bytes, more than any response needs");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw NpyError(path + ": cannot open it");
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    try {
        return parse_npy(bytes);
    } catch (const NpyError& e) {
        throw NpyError(path + ": " + e.what());
    }
}

}  // namespace collide::external
