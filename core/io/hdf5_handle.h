// Small helpers over the HDF5 C API, shared by the run writer and the code that reads runs back:
//
//   Hdf5Handle      owns one hid_t (file, group, dataset, dataspace, type, attribute, property
//                   list) and closes it with the right H5*close function, like a unique_ptr.
//   Hdf5Error       the exception every failed HDF5 call becomes, with HDF5's own innermost
//                   reason ("unable to open file: ... error message = 'Permission denied'").
//   checked(...)    turns a negative HDF5 return value into an Hdf5Error naming what we tried.
//
// HDF5 prints its error stack to stderr by default; silence_hdf5_error_printing() switches
// that off, so a failure reaches the user once, as one clear message.
#pragma once

#include <hdf5.h>

#include <stdexcept>
#include <string>
#include <utility>

namespace collide {

class Hdf5Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Stops HDF5 printing its error stack itself (errors are still recorded and reported by us).
inline void silence_hdf5_error_printing() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

// HDF5 1.10 crashes in its exit-time cleanup (H5F__close_cb) when closing a file failed, as
// on a full disk. A program that closes its files itself calls this first thing in main(),
// before any other HDF5 call, so the library skips that cleanup and exits cleanly.
inline void skip_hdf5_cleanup_at_exit() { H5dont_atexit(); }

// Sets the library up now. A process that forks many children (the suite's case processes)
// calls it first, so that each child inherits a set-up library instead of paying for one.
inline void initialise_hdf5() { H5open(); }

// The description of the innermost entry on HDF5's current error stack, where the failure
// was detected (e.g. the operating system's reason for a failed open), or "" if there is none.
inline std::string hdf5_error_reason() {
    std::string reason;
    auto take_innermost = [](unsigned, const H5E_error2_t* entry, void* data) -> herr_t {
        auto* out = static_cast<std::string*>(data);
        if (out->empty() && entry && entry->desc) *out = entry->desc;
        return 0;
    };
    H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, take_innermost, &reason);
    H5Eclear2(H5E_DEFAULT);
    // A failed write ("file write failed: time = ..., errno = 28, error message = 'No space
    // left on device', buf = ...") is shortened to the system's reason.
    const std::string marker = "error message = '";
    const auto at = reason.find(marker), colon = reason.find(':');
    if (at != std::string::npos && colon != std::string::npos) {
        const auto begin = at + marker.size(), end = reason.find('\'', begin);
        if (end != std::string::npos) reason = reason.substr(0, colon) + ": " + reason.substr(begin, end - begin);
    }
    return reason;
}

// Throws Hdf5Error("<context>: cannot <action> (<HDF5's reason>)") when `status` < 0
// (every HDF5 call reports failure as a negative hid_t or herr_t); returns `status` otherwise.
template <typename Status>
Status checked(Status status, const std::string& context, const std::string& action) {
    if (status < 0) {
        const std::string reason = hdf5_error_reason();
        throw Hdf5Error(context + ": cannot " + action + (reason.empty() ? "" : " (" + reason + ")"));
    }
    return status;
}

class Hdf5Handle {
public:
    using Closer = herr_t (*)(hid_t);

    Hdf5Handle() = default;
    Hdf5Handle(hid_t id, Closer close) : id_(id), close_(close) {}
    ~Hdf5Handle() { reset(); }
    Hdf5Handle(Hdf5Handle&& other) noexcept
        : id_(std::exchange(other.id_, H5I_INVALID_HID)), close_(other.close_) {}
    Hdf5Handle& operator=(Hdf5Handle&& other) noexcept {
        if (this != &other) {
            reset();
            id_ = std::exchange(other.id_, H5I_INVALID_HID);
            close_ = other.close_;
        }
        return *this;
    }
    Hdf5Handle(const Hdf5Handle&) = delete;
    Hdf5Handle& operator=(const Hdf5Handle&) = delete;

    hid_t get() const { return id_; }
    explicit operator bool() const { return id_ >= 0; }

    // Closes the object now; returns HDF5's status (negative on failure, e.g. a failed flush).
    herr_t reset() {
        herr_t status = 0;
        if (id_ >= 0 && close_) status = close_(id_);
        id_ = H5I_INVALID_HID;
        return status;
    }

private:
    hid_t id_ = H5I_INVALID_HID;
    Closer close_ = nullptr;
};

// Constructors for each kind of handle, so the closer cannot be mixed up.
inline Hdf5Handle file_handle(hid_t id) { return {id, H5Fclose}; }
inline Hdf5Handle group_handle(hid_t id) { return {id, H5Gclose}; }
inline Hdf5Handle dataset_handle(hid_t id) { return {id, H5Dclose}; }
inline Hdf5Handle dataspace_handle(hid_t id) { return {id, H5Sclose}; }
inline Hdf5Handle datatype_handle(hid_t id) { return {id, H5Tclose}; }
inline Hdf5Handle attribute_handle(hid_t id) { return {id, H5Aclose}; }
inline Hdf5Handle property_list_handle(hid_t id) { return {id, H5Pclose}; }

// A variable-length UTF-8 string type: holds a scene file of any length.
inline Hdf5Handle variable_length_string_type(const std::string& context) {
    Hdf5Handle type = datatype_handle(checked(H5Tcopy(H5T_C_S1), context, "copy the string type"));
    checked(H5Tset_size(type.get(), H5T_VARIABLE), context, "make a variable-length string type");
    checked(H5Tset_cset(type.get(), H5T_CSET_UTF8), context, "set the string type to UTF-8");
    return type;
}

}  // namespace collide
