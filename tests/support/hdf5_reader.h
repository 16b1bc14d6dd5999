// Reading run files back in tests, with the plain HDF5 C API (independent of RunWriter's
// own code, so a test of the writer does not trust the writer to read itself).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/io/hdf5_handle.h"

namespace collide::test {

class Hdf5File {
public:
    explicit Hdf5File(const std::string& path) : path_(path) {
        silence_hdf5_error_printing();
        file_ = file_handle(checked(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), path, "open"));
    }

    bool has(const std::string& object) const {
        // H5Lexists needs every parent to exist, so walk the path one link at a time.
        std::string prefix;
        std::size_t start = 1;
        while (start <= object.size()) {
            const std::size_t slash = object.find('/', start);
            prefix = object.substr(0, slash);
            if (H5Lexists(file_.get(), prefix.c_str(), H5P_DEFAULT) <= 0) return false;
            if (slash == std::string::npos) break;
            start = slash + 1;
        }
        return true;
    }

    std::vector<hsize_t> shape(const std::string& dataset) const {
        Hdf5Handle d = open_dataset(dataset);
        Hdf5Handle space = dataspace_handle(checked(H5Dget_space(d.get()), dataset, "get the dataspace"));
        std::vector<hsize_t> dims(std::size_t(checked(H5Sget_simple_extent_ndims(space.get()), dataset, "get rank")));
        H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
        return dims;
    }

    std::vector<double> doubles(const std::string& dataset) const { return read<double>(dataset, H5T_NATIVE_DOUBLE); }
    std::vector<std::int64_t> int64s(const std::string& dataset) const {
        return read<std::int64_t>(dataset, H5T_NATIVE_INT64);
    }

    bool has_attribute(const std::string& object, const std::string& name) const {
        return H5Aexists_by_name(file_.get(), object.c_str(), name.c_str(), H5P_DEFAULT) > 0;
    }

    std::string string_attribute(const std::string& object, const std::string& name) const {
        Hdf5Handle attribute = open_attribute(object, name);
        Hdf5Handle type = variable_length_string_type(path_);
        char* text = nullptr;
        checked(H5Aread(attribute.get(), type.get(), &text), path_, "read attribute " + name);
        std::string value(text ? text : "");
        H5free_memory(text);
        return value;
    }

    double double_attribute(const std::string& object, const std::string& name) const {
        double value = 0;
        checked(H5Aread(open_attribute(object, name).get(), H5T_NATIVE_DOUBLE, &value), path_, "read " + name);
        return value;
    }

    std::int64_t int64_attribute(const std::string& object, const std::string& name) const {
        std::int64_t value = 0;
        checked(H5Aread(open_attribute(object, name).get(), H5T_NATIVE_INT64, &value), path_, "read " + name);
        return value;
    }

    // The filters (e.g. H5Z_FILTER_DEFLATE) and chunk shape of a dataset ({} if contiguous).
    std::vector<H5Z_filter_t> filters(const std::string& dataset) const {
        Hdf5Handle properties = property_list_handle(H5Dget_create_plist(open_dataset(dataset).get()));
        std::vector<H5Z_filter_t> result;
        const int count = H5Pget_nfilters(properties.get());
        for (int k = 0; k < count; ++k) {
            unsigned flags = 0;
            std::size_t elements = 0;
            result.push_back(H5Pget_filter2(properties.get(), unsigned(k), &flags, &elements, nullptr, 0, nullptr, nullptr));
        }
        return result;
    }

    bool is_chunked(const std::string& dataset) const {
        Hdf5Handle properties = property_list_handle(H5Dget_create_plist(open_dataset(dataset).get()));
        return H5Pget_layout(properties.get()) == H5D_CHUNKED;
    }

private:
    Hdf5Handle open_dataset(const std::string& dataset) const {
        return dataset_handle(checked(H5Dopen2(file_.get(), dataset.c_str(), H5P_DEFAULT), path_, "open " + dataset));
    }

    Hdf5Handle open_attribute(const std::string& object, const std::string& name) const {
        return attribute_handle(checked(H5Aopen_by_name(file_.get(), object.c_str(), name.c_str(), H5P_DEFAULT,
                                                        H5P_DEFAULT),
                                        path_, "open attribute " + object + " " + name));
    }

    template <typename T>
    std::vector<T> read(const std::string& dataset, hid_t memory_type) const {
        std::size_t count = 1;
        for (hsize_t extent : shape(dataset)) count *= extent;
        std::vector<T> values(count);
        checked(H5Dread(open_dataset(dataset).get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()),
                path_, "read " + dataset);
        return values;
    }

    std::string path_;
    Hdf5Handle file_;
};

}  // namespace collide::test
