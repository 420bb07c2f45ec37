#include "results/Hdf5Writer.hpp"

#include "results/Utf8Text.hpp"

#include <atomic>
#include <stdexcept>
#include <utility>

namespace dropscope {

namespace {

// The description of the innermost error on HDF5's error stack: where it was detected, the most specific.
herr_t keepInnermost(unsigned n, const H5E_error2_t* error, void* message) {
    if (n == 0 && error->desc) *static_cast<std::string*>(message) = error->desc;
    return 0;
}

std::string innermostHdf5Error() {
    std::string message;
    H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, keepInnermost, &message);
    return message;
}

// A name of a group or dataset must be one link: not empty, no '/', not "." (the caller encodes names).
const std::string& linkName(const std::string& name, hid_t parent) {
    if (name.empty() || name == "." || name.find('/') != std::string::npos) {
        throw std::runtime_error("HDF5: \"" + name + "\" cannot name an object in " + hdf5Path(parent));
    }
    return name;
}

std::string attributeWhat(const std::string& name, hid_t object) {
    return "write attribute " + name + " of " + hdf5Path(object);
}

Hdf5Handle dataspace(const std::vector<hsize_t>& shape) {
    if (shape.empty()) return {H5Screate(H5S_SCALAR), H5Sclose, "create a scalar dataspace"};
    return {H5Screate_simple(static_cast<int>(shape.size()), shape.data(), nullptr), H5Sclose, "create a dataspace"};
}

Hdf5Handle propertyList(hid_t propertyClass) { return {H5Pcreate(propertyClass), H5Pclose, "create a property list"}; }

// Objects made with `list` record no times, and keep their attributes (and, for groups, links) in creation order.
void setDeterministicOrderAndNoTimes(hid_t list, bool group) {
    checkHdf5(H5Pset_obj_track_times(list, false), "switch off object times");
    checkHdf5(H5Pset_attr_creation_order(list, H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED),
              "track attribute creation order");
    if (group) {
        checkHdf5(H5Pset_link_creation_order(list, H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED),
                  "track link creation order");
    }
}

Hdf5Handle utf8StringType() {
    Hdf5Handle type(H5Tcopy(H5T_C_S1), H5Tclose, "copy the string type");
    checkHdf5(H5Tset_size(type.id(), H5T_VARIABLE), "make a variable-length string type");
    checkHdf5(H5Tset_cset(type.id(), H5T_CSET_UTF8), "make a UTF-8 string type");
    return type;
}

Hdf5Handle flagType() {
    Hdf5Handle type(H5Tenum_create(H5T_NATIVE_INT8), H5Tclose, "create the bool enum type");
    const std::int8_t no = 0;
    const std::int8_t yes = 1;
    checkHdf5(H5Tenum_insert(type.id(), "FALSE", &no), "add FALSE to the bool enum type");
    checkHdf5(H5Tenum_insert(type.id(), "TRUE", &yes), "add TRUE to the bool enum type");
    return type;
}

Hdf5Handle createFile() {
    // Silence HDF5's printing of its error stack: every failure is thrown instead, with its innermost message.
    checkHdf5(H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr), "switch off HDF5's error printing");
    const Hdf5Handle creation = propertyList(H5P_FILE_CREATE);  // also the root group's creation properties
    setDeterministicOrderAndNoTimes(creation.id(), true);
    const Hdf5Handle access = propertyList(H5P_FILE_ACCESS);
    constexpr std::size_t kGrowBy = 1 << 20;  // the in-memory file grows 1 MiB at a time
    checkHdf5(H5Pset_fapl_core(access.id(), kGrowBy, false), "select the in-memory file driver");
    // The name tells the files open in this process apart (several runs may write at once). HDF5 still looks
    // for a file of that name on disk first; under /dev/null, which is no folder, there never is one.
    static std::atomic<unsigned long> serial = 0;
    const std::string name = "/dev/null/dropscope-results-" + std::to_string(serial++) + ".h5";
    return {H5Fcreate(name.c_str(), H5F_ACC_TRUNC, creation.id(), access.id()), H5Fclose, "create an in-memory file"};
}

}  // namespace

void checkHdf5(herr_t status, const std::string& what) {
    if (status >= 0) return;
    const std::string detail = innermostHdf5Error();
    throw std::runtime_error("HDF5: cannot " + what + (detail.empty() ? "" : " (" + detail + ")"));
}

Hdf5Handle::Hdf5Handle(hid_t id, Close close, const std::string& what) : id_(id), close_(close) {
    checkHdf5(id < 0 ? -1 : 0, what);
}

Hdf5Handle::Hdf5Handle(Hdf5Handle&& other) noexcept
    : id_(std::exchange(other.id_, H5I_INVALID_HID)), close_(other.close_) {}

Hdf5Handle& Hdf5Handle::operator=(Hdf5Handle&& other) noexcept {
    if (this != &other) {
        if (id_ >= 0) close_(id_);
        id_ = std::exchange(other.id_, H5I_INVALID_HID);
        close_ = other.close_;
    }
    return *this;
}

Hdf5Handle::~Hdf5Handle() {
    if (id_ >= 0) close_(id_);  // a failing close has nowhere to go: the object is gone either way
}

std::string hdf5Path(hid_t object) {
    const ssize_t length = H5Iget_name(object, nullptr, 0);
    if (length <= 0) return "(an unnamed object)";
    std::string path(static_cast<std::size_t>(length) + 1, '\0');  // with room for the NUL it writes
    H5Iget_name(object, path.data(), path.size());
    path.resize(static_cast<std::size_t>(length));
    return path;
}

Hdf5MemoryFile::Hdf5MemoryFile()
    : groupCreation_(propertyList(H5P_GROUP_CREATE)),
      datasetCreation_(propertyList(H5P_DATASET_CREATE)),
      text_(utf8StringType()),
      flag_(flagType()),
      file_(createFile()) {
    setDeterministicOrderAndNoTimes(groupCreation_.id(), true);
    setDeterministicOrderAndNoTimes(datasetCreation_.id(), false);
}

Hdf5Handle Hdf5MemoryFile::createGroup(hid_t parent, const std::string& name) {
    return {H5Gcreate2(parent, linkName(name, parent).c_str(), H5P_DEFAULT, groupCreation_.id(), H5P_DEFAULT), H5Gclose,
            "create group " + name + " in " + hdf5Path(parent)};
}

void Hdf5MemoryFile::setAttribute(hid_t object, const std::string& name, std::uint64_t value) {
    setAttributeData(object, name, H5T_STD_U64LE, H5T_NATIVE_UINT64, dataspace({}).id(), &value);
}

void Hdf5MemoryFile::setAttribute(hid_t object, const std::string& name, double value) {
    setAttributeData(object, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, dataspace({}).id(), &value);
}

void Hdf5MemoryFile::setAttribute(hid_t object, const std::string& name, bool value) {
    const std::int8_t flag = value ? 1 : 0;
    setAttributeData(object, name, flag_.id(), flag_.id(), dataspace({}).id(), &flag);
}

void Hdf5MemoryFile::setAttribute(hid_t object, const std::string& name, const std::string& value) {
    const std::string text = utf8Text(value);
    const char* data = text.c_str();
    setAttributeData(object, name, text_.id(), text_.id(), dataspace({}).id(), &data);
}

void Hdf5MemoryFile::setAttribute(hid_t object, const std::string& name, const std::vector<std::uint64_t>& values) {
    setAttributeData(object, name, H5T_STD_U64LE, H5T_NATIVE_UINT64, dataspace({values.size()}).id(), values.data());
}

void Hdf5MemoryFile::setAttribute(hid_t object, const std::string& name, const std::vector<std::string>& values) {
    std::vector<std::string> texts;
    for (const std::string& value : values) texts.push_back(utf8Text(value));
    std::vector<const char*> data;
    for (const std::string& text : texts) data.push_back(text.c_str());
    setAttributeData(object, name, text_.id(), text_.id(), dataspace({values.size()}).id(), data.data());
}

void Hdf5MemoryFile::setNullAttribute(hid_t object, const std::string& name) {
    const Hdf5Handle space(H5Screate(H5S_NULL), H5Sclose, "create a null dataspace");
    setAttributeData(object, name, H5T_STD_U8LE, H5T_NATIVE_UINT8, space.id(), nullptr);
}

void Hdf5MemoryFile::setAsciiAttribute(hid_t object, const std::string& name, const std::string& value) {
    const Hdf5Handle type(H5Tcopy(H5T_C_S1), H5Tclose, "copy the string type");
    checkHdf5(H5Tset_size(type.id(), value.size() + 1), "size a fixed-length string type");  // with its NUL
    setAttributeData(object, name, type.id(), type.id(), dataspace({}).id(), value.c_str());
}

Hdf5Handle Hdf5MemoryFile::writeDataset(hid_t parent, const std::string& name, const std::vector<hsize_t>& shape,
                                        const std::vector<std::uint64_t>& values) {
    return writeDatasetData(parent, name, shape, H5T_STD_U64LE, H5T_NATIVE_UINT64, values.data());
}

Hdf5Handle Hdf5MemoryFile::writeDataset(hid_t parent, const std::string& name, const std::vector<hsize_t>& shape,
                                        const std::vector<double>& values) {
    return writeDatasetData(parent, name, shape, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, values.data());
}

Hdf5Handle Hdf5MemoryFile::writeDataset(hid_t parent, const std::string& name, const std::vector<hsize_t>& shape,
                                        const std::vector<std::uint8_t>& values) {
    return writeDatasetData(parent, name, shape, H5T_STD_U8LE, H5T_NATIVE_UINT8, values.data());
}

Hdf5Handle Hdf5MemoryFile::writeDataset(hid_t parent, const std::string& name, const std::vector<hsize_t>& shape,
                                        const std::vector<std::string>& values) {
    std::vector<std::string> texts;
    for (const std::string& value : values) texts.push_back(utf8Text(value));
    std::vector<const char*> data;
    for (const std::string& text : texts) data.push_back(text.c_str());
    return writeDatasetData(parent, name, shape, text_.id(), text_.id(), data.data());
}

std::vector<std::byte> Hdf5MemoryFile::bytes() const {
    checkHdf5(H5Fflush(file_.id(), H5F_SCOPE_GLOBAL), "flush the in-memory file");
    const ssize_t size = H5Fget_file_image(file_.id(), nullptr, 0);
    checkHdf5(size < 0 ? -1 : 0, "size the file image");
    std::vector<std::byte> image(static_cast<std::size_t>(size));
    checkHdf5(H5Fget_file_image(file_.id(), image.data(), image.size()) == size ? 0 : -1, "copy the file image");
    return image;
}

void Hdf5MemoryFile::setAttributeData(hid_t object, const std::string& name, hid_t fileType, hid_t memoryType,
                                      hid_t space, const void* data) {
    const Hdf5Handle attribute(H5Acreate2(object, name.c_str(), fileType, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
                               attributeWhat(name, object));
    if (data) checkHdf5(H5Awrite(attribute.id(), memoryType, data), attributeWhat(name, object));
}

Hdf5Handle Hdf5MemoryFile::writeDatasetData(hid_t parent, const std::string& name, const std::vector<hsize_t>& shape,
                                            hid_t fileType, hid_t memoryType, const void* data) {
    const std::string what = "write dataset " + name + " in " + hdf5Path(parent);
    const Hdf5Handle space = dataspace(shape);
    Hdf5Handle dataset(H5Dcreate2(parent, linkName(name, parent).c_str(), fileType, space.id(), H5P_DEFAULT,
                                  datasetCreation_.id(), H5P_DEFAULT),
                       H5Dclose, what);
    if (H5Sget_simple_extent_npoints(space.id()) > 0) {
        checkHdf5(H5Dwrite(dataset.id(), memoryType, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), what);
    }
    return dataset;
}

}  // namespace dropscope
