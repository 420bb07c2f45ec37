#pragma once

// The HDF5 C API (Debian's libhdf5) as results.h5 uses it: identifiers that close themselves, calls whose
// failure throws, and a file built in memory whose bytes depend only on what was written into it. Only the
// result writers include this header; the library links HDF5 privately.
#include <hdf5.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace dropscope {

// Throws std::runtime_error "HDF5: cannot WHAT (HDF5's innermost message)" when `status` is negative.
void checkHdf5(herr_t status, const std::string& what);

// One HDF5 identifier (file, group, dataset, attribute, dataspace, datatype or property list), closed by its
// own close function when the handle goes.
class Hdf5Handle {
public:
    using Close = herr_t (*)(hid_t);
    // Takes `id` as a call that does WHAT returned it; throws as checkHdf5 when it is negative (the call failed).
    Hdf5Handle(hid_t id, Close close, const std::string& what);
    Hdf5Handle(Hdf5Handle&& other) noexcept;
    Hdf5Handle& operator=(Hdf5Handle&& other) noexcept;
    Hdf5Handle(const Hdf5Handle&) = delete;
    Hdf5Handle& operator=(const Hdf5Handle&) = delete;
    ~Hdf5Handle();

    hid_t id() const { return id_; }

private:
    hid_t id_ = H5I_INVALID_HID;
    Close close_ = nullptr;
};

// The path of an open object in its file ("/tables/angular"), for messages.
std::string hdf5Path(hid_t object);

// An HDF5 file in memory (the core driver without a backing store) made to give the same bytes for the same
// content: no object records a time, and every group keeps its links and attributes in the order they were
// created, which is the order h5py lists them in. Numbers are little-endian in the file; texts are UTF-8
// variable-length strings. Every failing call throws as checkHdf5, naming the object.
class Hdf5MemoryFile {
public:
    Hdf5MemoryFile();

    hid_t root() const { return file_.id(); }
    Hdf5Handle createGroup(hid_t parent, const std::string& name);

    // Attributes: a scalar, a 1-D array, a null value (an empty H5S_NULL dataspace: h5py gives h5py.Empty)
    // and a fixed-length ASCII text (the form the HDF5 image specification gives its attributes).
    void setAttribute(hid_t object, const std::string& name, std::uint64_t value);
    void setAttribute(hid_t object, const std::string& name, double value);
    void setAttribute(hid_t object, const std::string& name, bool value);  // the enum {FALSE, TRUE} of h5py's bool
    void setAttribute(hid_t object, const std::string& name, const std::string& value);
    void setAttribute(hid_t object, const std::string& name, const std::vector<std::uint64_t>& values);
    void setAttribute(hid_t object, const std::string& name, const std::vector<std::string>& values);
    void setNullAttribute(hid_t object, const std::string& name);
    void setAsciiAttribute(hid_t object, const std::string& name, const std::string& value);

    // A contiguous, uncompressed dataset of `shape` (row-major; empty: a scalar) holding `values`.
    Hdf5Handle writeDataset(hid_t parent, const std::string& name, const std::vector<hsize_t>& shape,
                            const std::vector<std::uint64_t>& values);
    Hdf5Handle writeDataset(hid_t parent, const std::string& name, const std::vector<hsize_t>& shape,
                            const std::vector<double>& values);
    Hdf5Handle writeDataset(hid_t parent, const std::string& name, const std::vector<hsize_t>& shape,
                            const std::vector<std::uint8_t>& values);
    Hdf5Handle writeDataset(hid_t parent, const std::string& name, const std::vector<hsize_t>& shape,
                            const std::vector<std::string>& values);

    // The file as it stands, flushed: what a file on disk would hold.
    std::vector<std::byte> bytes() const;

private:
    void setAttributeData(hid_t object, const std::string& name, hid_t fileType, hid_t memoryType, hid_t space,
                          const void* data);
    Hdf5Handle writeDatasetData(hid_t parent, const std::string& name, const std::vector<hsize_t>& shape,
                                hid_t fileType, hid_t memoryType, const void* data);

    Hdf5Handle groupCreation_;    // no times; links and attributes in creation order
    Hdf5Handle datasetCreation_;  // no times; attributes in creation order
    Hdf5Handle text_;             // variable-length UTF-8 string
    Hdf5Handle flag_;             // enum {FALSE = 0, TRUE = 1} on int8
    Hdf5Handle file_;
};

}  // namespace dropscope
