#include "npy.h"

#include <sys/stat.h>

#include <bit>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <string_view>

namespace collide::external {
namespace {

constexpr char magic[] = "\x93NUMPY";
constexpr std::size_t magic_size = 6;
// NumPy itself refuses a header longer than this (numpy.lib.format._MAX_HEADER_SIZE, 10000
// bytes since NumPy 1.24, "to guard against excessive memory use or execution time"); a
// float64 array's header is 128 bytes at most.
constexpr std::size_t max_header_bytes = 10000;
// The most that is ever read before the header is parsed: magic, version, length, header.
constexpr std::size_t max_prefix_bytes = 12 + max_header_bytes;

// The header is a Python dict literal, {'descr': '<f8', 'fortran_order': False, 'shape': (2, 3), },
// read here by a small scanner that loops (no recursion, no backtracking regex: 65,000 spaces
// overflowed std::regex's stack) and keeps each value's text. Like NumPy's
// numpy.lib.format._read_array_header, it accepts exactly the three keys; a key given twice
// is refused (Python's dict keeps the last one and NumPy would read that; a reader that took
// the first would see another array).
class HeaderScanner {
public:
    explicit HeaderScanner(std::string_view text) : text_(text) {}

    std::map<std::string, std::string> entries() {
        std::map<std::string, std::string> out;
        skip_space();
        expect('{');
        for (skip_space(); !at('}'); skip_space()) {
            const std::string key = string_literal();
            skip_space();
            expect(':');
            skip_space();
            const std::string value = value_text();
            if (!out.emplace(key, value).second)
                throw NpyError("the header names '" + key + "' twice (NumPy would read the last one; refused)");
            skip_space();
            if (at('}')) break;
            expect(',');
        }
        ++pos_;
        skip_space();
        if (pos_ != text_.size()) throw NpyError("the header has text after its closing '}'");
        return out;
    }

private:
    bool at(char c) const { return pos_ < text_.size() && text_[pos_] == c; }
    void skip_space() {
        while (pos_ < text_.size() && std::strchr(" \t\r\n", text_[pos_]) && text_[pos_] != '\0') ++pos_;
    }
    [[noreturn]] void malformed(const std::string& expected) const {
        throw NpyError("the header is not a dict literal: expected " + expected + " at byte " + std::to_string(pos_));
    }
    void expect(char c) {
        if (!at(c)) malformed(std::string("'") + c + "'");
        ++pos_;
    }
    std::string string_literal() {
        if (!at('\'') && !at('"')) malformed("a quoted key");
        const char quote = text_[pos_++];
        const std::size_t end = text_.find(quote, pos_);
        if (end == std::string_view::npos) malformed("the closing quote");
        std::string out(text_.substr(pos_, end - pos_));
        pos_ = end + 1;
        return out;
    }
    // A quoted string, True, False, or a tuple of whole numbers, as its text.
    std::string value_text() {
        const std::size_t start = pos_;
        if (at('\'') || at('"')) {
            string_literal();
        } else if (at('(')) {
            const std::size_t end = text_.find(')', pos_);
            if (end == std::string_view::npos) malformed("')'");
            pos_ = end + 1;
        } else {
            for (const std::string_view word : {"True", "False"})
                if (text_.substr(pos_, word.size()) == word) pos_ += word.size();
            if (pos_ == start) malformed("a string, True, False or a tuple");
        }
        return std::string(text_.substr(start, pos_ - start));
    }

    std::string_view text_;
    std::size_t pos_ = 0;
};

std::vector<std::size_t> parse_shape(const std::string& text) {
    if (text.front() != '(') throw NpyError("the shape " + text + " is not a tuple");
    std::vector<std::size_t> shape;
    std::size_t pos = 1;
    while (pos < text.size() - 1) {
        const std::size_t comma = std::min(text.find(',', pos), text.size() - 1);
        std::string item = text.substr(pos, comma - pos);
        pos = comma + 1;
        const auto first = item.find_first_not_of(" \t\r\n");
        if (first == std::string::npos) continue;  // the trailing comma of (3,)
        const auto last = item.find_last_not_of(" \t\r\nL");
        const std::string digits = item.substr(first, last - first + 1);
        if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 15)
            throw NpyError("the shape " + text + " is not a tuple of whole numbers");
        shape.push_back(std::stoull(digits));
    }
    return shape;
}

// The parsed header: the array's shape and where its data starts.
struct NpyHeader {
    std::vector<std::size_t> shape;
    std::size_t data_offset = 0;
    std::size_t data_bytes = 0;  // the shape's count of float64 values, in bytes
};

// `bytes` holds at least the start of the file (magic, version, header length and header).
NpyHeader parse_header(std::string_view bytes) {
    if (bytes.size() < magic_size + 4 || bytes.substr(0, magic_size) != std::string_view(magic, magic_size))
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
    if (header_length > max_header_bytes)
        throw NpyError("the .npy header is " + std::to_string(header_length) + " bytes long, more than the " +
                       std::to_string(max_header_bytes) + " NumPy itself reads (np.save writes 128 at most here)");
    if (bytes.size() < header_start + header_length) throw NpyError("the .npy header is cut short");
    const auto entries = HeaderScanner(bytes.substr(header_start, header_length)).entries();
    for (const char* key : {"descr", "fortran_order", "shape"})
        if (!entries.count(key)) throw NpyError(std::string("the header has no '") + key + "' entry");
    if (entries.size() != 3)
        for (const auto& [key, value] : entries)
            if (key != "descr" && key != "fortran_order" && key != "shape")
                throw NpyError("the header has the key '" + key + "'; NumPy accepts only descr, fortran_order and shape");
    const std::string& quoted = entries.at("descr");
    if (quoted.front() != '\'' && quoted.front() != '"') throw NpyError("the header's descr " + quoted + " is not a string");
    const std::string descr = quoted.substr(1, quoted.size() - 2);
    if (descr != "<f8" && descr != "f8" && descr != "=f8")
        throw NpyError("dtype '" + descr + "', expected '<f8' (little-endian float64)");
    if (entries.at("fortran_order") != "False")
        throw NpyError("Fortran order, expected C order (np.save writes C order for an ordinary array)");
    NpyHeader header;
    header.shape = parse_shape(entries.at("shape"));
    std::size_t count = 1;
    for (std::size_t n : header.shape) {
        if (n != 0 && count > (std::numeric_limits<std::size_t>::max() / sizeof(double)) / n)
            throw NpyError("the shape " + shape_text(header.shape) + " is too large");
        count *= n;
    }
    header.data_offset = header_start + header_length;
    header.data_bytes = count * sizeof(double);
    return header;
}

void check_data_size(const NpyHeader& header, std::uintmax_t file_bytes) {
    const std::uintmax_t data_bytes = file_bytes - std::min<std::uintmax_t>(file_bytes, header.data_offset);
    if (data_bytes != header.data_bytes)
        throw NpyError("the shape " + shape_text(header.shape) + " holds " + std::to_string(header.data_bytes / 8) +
                       " numbers (" + std::to_string(header.data_bytes) + " bytes) but the file has " +
                       std::to_string(data_bytes) + " bytes of data");
}

NpyArray read_checked(const std::string& path, const std::optional<std::vector<std::size_t>>& expected) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) throw NpyError("cannot read it: " + std::string(std::strerror(errno)));
    if (!S_ISREG(st.st_mode)) throw NpyError("not a regular file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw NpyError("cannot open it");
    // The header first, at most max_prefix_bytes: a file's size is judged before its data is read.
    std::string prefix(std::size_t(std::min<std::uintmax_t>(std::uintmax_t(st.st_size), max_prefix_bytes)), '\0');
    in.read(prefix.data(), std::streamsize(prefix.size()));
    prefix.resize(std::size_t(in.gcount()));
    const NpyHeader header = parse_header(prefix);
    if (expected && header.shape != *expected)
        throw NpyError("shape " + shape_text(header.shape) + ", expected " + shape_text(*expected));
    check_data_size(header, std::uintmax_t(st.st_size));
    NpyArray out;
    out.shape = header.shape;
    out.data.resize(header.data_bytes / sizeof(double));
    in.clear();
    in.seekg(std::streamoff(header.data_offset));
    in.read(reinterpret_cast<char*>(out.data.data()), std::streamsize(header.data_bytes));
    if (std::size_t(in.gcount()) != header.data_bytes) throw NpyError("the file was cut short while it was read");
    return out;
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
    const NpyHeader header = parse_header(bytes);
    check_data_size(header, bytes.size());
    NpyArray out;
    out.shape = header.shape;
    out.data.resize(header.data_bytes / sizeof(double));
    if (header.data_bytes) std::memcpy(out.data.data(), bytes.data() + header.data_offset, header.data_bytes);
    return out;
}

NpyArray read_npy(const std::string& path, const std::optional<std::vector<std::size_t>>& expected_shape) {
    try {
        return read_checked(path, expected_shape);
    } catch (const NpyError& e) {
        throw NpyError(path + ": " + e.what());
    }
}

}  // namespace collide::external
