// results.h5 read back through the HDF5 C API: every value, type, unit and shape docs/results-format.md
// gives, and the same bytes for the same report.
#include "results/Hdf5Writer.hpp"
#include "results/ResultsHdf5.hpp"
#include "results/SampleResultsReport.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace dropscope {
namespace {

using test::kSampleSceneJson;
using test::sampleResultsReport;

const ResultsFileInfo kInfo{"9.8.7", kSampleSceneJson};

// An HDF5 file opened read-only from its bytes in memory.
Hdf5Handle openImage(const std::vector<std::byte>& bytes) {
    const Hdf5Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "create a property list");
    checkHdf5(H5Pset_fapl_core(access.id(), 1 << 16, false), "select the core driver");
    checkHdf5(H5Pset_file_image(access.id(), const_cast<std::byte*>(bytes.data()), bytes.size()), "set the image");
    static int serial = 0;  // in-memory files are told apart by name
    const std::string name = "read-back-" + std::to_string(serial++) + ".h5";
    return {H5Fopen(name.c_str(), H5F_ACC_RDONLY, access.id()), H5Fclose, "open the image"};
}

Hdf5Handle openObject(hid_t file, const std::string& path) {
    return {H5Oopen(file, path.c_str(), H5P_DEFAULT), H5Oclose, "open " + path};
}

Hdf5Handle openAttribute(hid_t file, const std::string& path, const std::string& name) {
    const Hdf5Handle object = openObject(file, path);
    return {H5Aopen(object.id(), name.c_str(), H5P_DEFAULT), H5Aclose, "open attribute " + name + " of " + path};
}

bool hasAttribute(hid_t file, const std::string& path, const std::string& name) {
    return H5Aexists_by_name(file, path.c_str(), name.c_str(), H5P_DEFAULT) > 0;
}

// The file type of an attribute or dataset is exactly `expected` (H5T_STD_U64LE, ...).
bool typeIs(hid_t attributeOrDataset, hid_t expected) {
    const bool attribute = H5Iget_type(attributeOrDataset) == H5I_ATTR;
    const Hdf5Handle type(attribute ? H5Aget_type(attributeOrDataset) : H5Dget_type(attributeOrDataset), H5Tclose,
                          "get a type");
    return H5Tequal(type.id(), expected) > 0;
}

template <typename T>
T scalarAttribute(hid_t file, const std::string& path, const std::string& name, hid_t memoryType) {
    const Hdf5Handle attribute = openAttribute(file, path, name);
    T value{};
    checkHdf5(H5Aread(attribute.id(), memoryType, &value), "read attribute " + name);
    return value;
}

std::uint64_t countAttribute(hid_t file, const std::string& path, const std::string& name) {
    EXPECT_TRUE(typeIs(openAttribute(file, path, name).id(), H5T_STD_U64LE)) << path << " " << name;
    return scalarAttribute<std::uint64_t>(file, path, name, H5T_NATIVE_UINT64);
}

double numberAttribute(hid_t file, const std::string& path, const std::string& name) {
    EXPECT_TRUE(typeIs(openAttribute(file, path, name).id(), H5T_IEEE_F64LE)) << path << " " << name;
    return scalarAttribute<double>(file, path, name, H5T_NATIVE_DOUBLE);
}

// Variable-length UTF-8 strings, as one or many.
Hdf5Handle textType() {
    Hdf5Handle type(H5Tcopy(H5T_C_S1), H5Tclose, "copy a type");
    checkHdf5(H5Tset_size(type.id(), H5T_VARIABLE), "size a type");
    checkHdf5(H5Tset_cset(type.id(), H5T_CSET_UTF8), "set a character set");
    return type;
}

std::vector<std::string> texts(hid_t attributeOrDataset) {
    const bool attribute = H5Iget_type(attributeOrDataset) == H5I_ATTR;
    const Hdf5Handle space(attribute ? H5Aget_space(attributeOrDataset) : H5Dget_space(attributeOrDataset), H5Sclose,
                           "get a dataspace");
    const Hdf5Handle type = textType();
    EXPECT_TRUE(typeIs(attributeOrDataset, type.id()));
    std::vector<char*> data(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space.id())));
    if (data.empty()) return {};
    checkHdf5(attribute ? H5Aread(attributeOrDataset, type.id(), data.data())
                        : H5Dread(attributeOrDataset, type.id(), H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()),
              "read texts");
    const std::vector<std::string> values(data.begin(), data.end());
    checkHdf5(H5Dvlen_reclaim(type.id(), space.id(), H5P_DEFAULT, data.data()), "free texts");
    return values;
}

std::string textAttribute(hid_t file, const std::string& path, const std::string& name) {
    const std::vector<std::string> values = texts(openAttribute(file, path, name).id());
    return values.size() == 1 ? values.front() : "(not one text)";
}

std::vector<hsize_t> shape(hid_t dataset) {
    const Hdf5Handle space(H5Dget_space(dataset), H5Sclose, "get a dataspace");
    std::vector<hsize_t> dimensions(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space.id())));
    H5Sget_simple_extent_dims(space.id(), dimensions.data(), nullptr);
    return dimensions;
}

template <typename T>
std::vector<T> numbers(hid_t dataset, hid_t memoryType) {
    const Hdf5Handle space(H5Dget_space(dataset), H5Sclose, "get a dataspace");
    std::vector<T> values(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space.id())));
    if (!values.empty()) {
        checkHdf5(H5Dread(dataset, memoryType, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), "read numbers");
    }
    return values;
}

// Names of a group's links or an object's attributes in creation order, the order h5py lists them in.
herr_t appendLinkName(hid_t, const char* name, const H5L_info_t*, void* names) {
    static_cast<std::vector<std::string>*>(names)->push_back(name);
    return 0;
}

herr_t appendAttributeName(hid_t, const char* name, const H5A_info_t*, void* names) {
    static_cast<std::vector<std::string>*>(names)->push_back(name);
    return 0;
}

std::vector<std::string> linkNames(hid_t file, const std::string& path) {
    const Hdf5Handle group = openObject(file, path);
    std::vector<std::string> names;
    checkHdf5(H5Literate(group.id(), H5_INDEX_CRT_ORDER, H5_ITER_INC, nullptr, appendLinkName, &names), "list links");
    return names;
}

std::vector<std::string> attributeNames(hid_t file, const std::string& path) {
    const Hdf5Handle object = openObject(file, path);
    std::vector<std::string> names;
    checkHdf5(H5Aiterate2(object.id(), H5_INDEX_CRT_ORDER, H5_ITER_INC, nullptr, appendAttributeName, &names),
              "list attributes");
    return names;
}

class ResultsHdf5 : public ::testing::Test {
protected:
    ResultsHdf5() : bytes_(resultsHdf5Bytes(sampleResultsReport(), kInfo)), file_(openImage(bytes_)) {}
    hid_t file() const { return file_.id(); }
    Hdf5Handle dataset(const std::string& path) const { return openObject(file(), path); }

    std::vector<std::byte> bytes_;
    Hdf5Handle file_;
};

TEST_F(ResultsHdf5, RootHoldsFormatVersionSeedAndPhotons) {
    EXPECT_EQ(textAttribute(file(), "/", "format"), "dropscope results");
    EXPECT_EQ(countAttribute(file(), "/", "format_version"), 1u);
    EXPECT_EQ(textAttribute(file(), "/", "dropscope_version"), "9.8.7");
    EXPECT_EQ(countAttribute(file(), "/", "seed"), 7u);
    EXPECT_EQ(countAttribute(file(), "/", "photons"), 1000u);
    EXPECT_EQ(linkNames(file(), "/"), (std::vector<std::string>{"scene_json", "summary", "tables", "images"}));
    const Hdf5Handle scene = dataset("/scene_json");
    EXPECT_TRUE(shape(scene.id()).empty());  // a scalar
    EXPECT_EQ(texts(scene.id()), std::vector<std::string>{kSampleSceneJson});
}

TEST_F(ResultsHdf5, SummaryKeysAreGroupsAndTheirValuesAttributes) {
    EXPECT_EQ(attributeNames(file(), "/summary"),
              (std::vector<std::string>{"photons", "seed", "partial", "scene", "polarised", "wavelength_nm", "bins",
                                        "max_events", "paths", "sources"}));
    EXPECT_EQ(countAttribute(file(), "/summary", "photons"), 1000u);
    EXPECT_EQ(textAttribute(file(), "/summary", "scene"), "scenes/caf\xC3\xA9.json");
    EXPECT_EQ(numberAttribute(file(), "/summary/fractions", "escaped"), 0.75);
    EXPECT_TRUE(std::isnan(numberAttribute(file(), "/summary/fractions", "absorbed")));
    EXPECT_EQ(textAttribute(file(), "/summary/spectra/0", "spectrum"), "sun");
    EXPECT_EQ(numberAttribute(file(), "/summary/spectra/0", "lo_nm"), 380.0);
    // Booleans: the enum {FALSE = 0, TRUE = 1} on int8 that h5py reads as numpy.bool_.
    const Hdf5Handle partial = openAttribute(file(), "/summary", "partial");
    const Hdf5Handle flagType(H5Aget_type(partial.id()), H5Tclose, "get a type");
    EXPECT_EQ(H5Tget_class(flagType.id()), H5T_ENUM);
    EXPECT_EQ(H5Tget_size(flagType.id()), 1u);
    EXPECT_EQ((scalarAttribute<std::int8_t>(file(), "/summary", "partial", flagType.id())), 0);
    EXPECT_EQ((scalarAttribute<std::int8_t>(file(), "/summary", "polarised", flagType.id())), 1);
    // Null: an attribute with an empty (null) dataspace.
    const Hdf5Handle null = openAttribute(file(), "/summary", "wavelength_nm");
    const Hdf5Handle nullSpace(H5Aget_space(null.id()), H5Sclose, "get a dataspace");
    EXPECT_EQ(H5Sget_simple_extent_type(nullSpace.id()), H5S_NULL);
}

TEST_F(ResultsHdf5, RunDependentSummaryKeysAreLeftOutUnlessAsked) {
    EXPECT_FALSE(hasAttribute(file(), "/summary", "seconds"));
    EXPECT_FALSE(hasAttribute(file(), "/summary", "threads"));
    ResultsFileInfo everything = kInfo;
    everything.omittedSummaryKeys = {{"fractions"}};
    const Hdf5Handle all = openImage(resultsHdf5Bytes(sampleResultsReport(), everything));
    EXPECT_EQ(numberAttribute(all.id(), "/summary", "seconds"), 0.5);
    EXPECT_EQ(countAttribute(all.id(), "/summary", "threads"), 2u);
    EXPECT_LT(H5Lexists(all.id(), "/summary/fractions", H5P_DEFAULT), 1);
}

TEST_F(ResultsHdf5, TableColumnsAreDatasetsInOrderWithTheirUnits) {
    const std::vector<std::string> columns{"theta_lo_deg", "theta_hi_deg", "count", "fraction"};
    EXPECT_EQ(linkNames(file(), "/tables"),
              (std::vector<std::string>{"angular", "detector-sky", "detector-sky-records", "empty"}));
    EXPECT_EQ(linkNames(file(), "/tables/angular"), columns);
    EXPECT_EQ(texts(openAttribute(file(), "/tables/angular", "columns").id()), columns);
    EXPECT_EQ(countAttribute(file(), "/tables/angular", "rows"), 2u);
    EXPECT_FALSE(hasAttribute(file(), "/tables/angular", "grid"));
    const Hdf5Handle theta = dataset("/tables/angular/theta_lo_deg");
    EXPECT_TRUE(typeIs(theta.id(), H5T_IEEE_F64LE));
    EXPECT_EQ(shape(theta.id()), std::vector<hsize_t>{2});
    EXPECT_EQ(numbers<double>(theta.id(), H5T_NATIVE_DOUBLE), (std::vector<double>{0.0, 90.0}));
    EXPECT_EQ(textAttribute(file(), "/tables/angular/theta_lo_deg", "unit"), "deg");
    const Hdf5Handle count = dataset("/tables/angular/count");
    EXPECT_TRUE(typeIs(count.id(), H5T_STD_U64LE));
    EXPECT_EQ(numbers<std::uint64_t>(count.id(), H5T_NATIVE_UINT64), (std::vector<std::uint64_t>{1, 3}));
    EXPECT_EQ(textAttribute(file(), "/tables/angular/count", "unit"), "");
    const Hdf5Handle shapes = dataset("/tables/detector-sky-records/shape");
    EXPECT_EQ(texts(shapes.id()), (std::vector<std::string>{"sphere 0", "box, 1"}));
    EXPECT_EQ(textAttribute(file(), "/tables/detector-sky-records/x", "unit"), "scene unit");
}

TEST_F(ResultsHdf5, GridTableColumnsAreImagesOfTheirPixels) {
    const Hdf5Handle grid = openAttribute(file(), "/tables/detector-sky", "grid");
    std::vector<std::uint64_t> nyNx(2);
    checkHdf5(H5Aread(grid.id(), H5T_NATIVE_UINT64, nyNx.data()), "read grid");
    EXPECT_EQ(nyNx, (std::vector<std::uint64_t>{2, 3}));
    EXPECT_EQ(linkNames(file(), "/tables/detector-sky"),
              (std::vector<std::string>{"ix", "iy", "fraction", "radiance", "label", "stokes_q", "stokes_u", "stokes_v",
                                        "cie_x", "cie_y", "cie_z"}));
    for (const char* column : {"ix", "iy", "fraction", "radiance", "label", "cie_z"}) {
        EXPECT_EQ(shape(dataset(std::string("/tables/detector-sky/") + column).id()), (std::vector<hsize_t>{2, 3}))
            << column;
    }
    // Row-major: [iy][ix], the table's rows in order.
    EXPECT_EQ(numbers<double>(dataset("/tables/detector-sky/fraction").id(), H5T_NATIVE_DOUBLE),
              (std::vector<double>{0.0, 0.1, 0.2, 0.3, 0.4, 0.5}));
    EXPECT_EQ(textAttribute(file(), "/tables/detector-sky/radiance", "unit"), "1/sr");
    EXPECT_EQ(texts(dataset("/tables/detector-sky/label").id()),
              (std::vector<std::string>{"a", "b", "c", "d", "e", "f"}));
    const Hdf5Handle empty = dataset("/tables/empty/value");
    EXPECT_EQ(shape(empty.id()), std::vector<hsize_t>{0});
    EXPECT_EQ(textAttribute(file(), "/tables/empty/value", "unit"), "nm");
}

TEST_F(ResultsHdf5, ImagesAreHeightByWidthByThreeBytes) {
    const Hdf5Handle image = dataset("/images/detector-sky");
    EXPECT_TRUE(typeIs(image.id(), H5T_STD_U8LE));
    EXPECT_EQ(shape(image.id()), (std::vector<hsize_t>{2, 3, 3}));
    const std::vector<std::uint8_t> rgb = numbers<std::uint8_t>(image.id(), H5T_NATIVE_UINT8);
    EXPECT_EQ(rgb, sampleResultsReport().images().front().rgb);
    EXPECT_EQ(attributeNames(file(), "/images/detector-sky"),
              (std::vector<std::string>{"CLASS", "IMAGE_VERSION", "IMAGE_SUBCLASS", "INTERLACE_MODE"}));
}

// What makes two runs' files equal: no object records a time, and nothing else in the file depends on when or
// after what it was written.
TEST_F(ResultsHdf5, NoObjectRecordsATime) {
    std::vector<std::string> timed;
    checkHdf5(H5Ovisit(
                  file(), H5_INDEX_CRT_ORDER, H5_ITER_INC,
                  [](hid_t, const char* name, const H5O_info_t* info, void* out) {
                      if (info->atime || info->mtime || info->ctime || info->btime) {
                          static_cast<std::vector<std::string>*>(out)->push_back(name);
                      }
                      return herr_t{0};
                  },
                  &timed),
              "visit the objects");
    EXPECT_EQ(timed, std::vector<std::string>{});
}

TEST_F(ResultsHdf5, TheSameReportGivesTheSameBytes) {
    // In between, a larger file of other texts and numbers, so that memory HDF5 reuses holds other bytes.
    ResultReport other = sampleResultsReport();
    other.addTable({"noise",
                    {{"text", std::vector<std::string>(5000, std::string(37, '#'))},
                     {"number", std::vector<double>(5000, -1.25)}}});
    for (int k = 0; k < 40; ++k) other.set({"noise", "key" + std::to_string(k)}, std::string(100 + k, 'x'));
    EXPECT_NE(resultsHdf5Bytes(other, {"0.0.0", std::string(9000, '@')}), bytes_);
    EXPECT_EQ(resultsHdf5Bytes(sampleResultsReport(), kInfo), bytes_);
    std::ostringstream out;
    writeResultsHdf5(sampleResultsReport(), kInfo, out);
    EXPECT_EQ(out.str(), std::string(reinterpret_cast<const char*>(bytes_.data()), bytes_.size()));
}

TEST(ResultsHdf5Errors, AFailingCallIsNamedWithHdf5sReason) {
    ResultReport report;
    report.addTable({"twice", {{"x", std::vector<double>{1.0}}, {"x", std::vector<double>{2.0}}}});
    try {
        resultsHdf5Bytes(report, kInfo);
        FAIL() << "no exception";
    } catch (const std::runtime_error& error) {
        EXPECT_EQ(std::string(error.what()).rfind("HDF5: cannot write dataset x in /tables/twice (", 0), 0u)
            << error.what();
    }
}

TEST(ResultsHdf5Errors, AnEmptyNameIsRefused) {
    ResultReport report;
    report.addTable({"", {}});
    EXPECT_THROW(
        {
            try {
                resultsHdf5Bytes(report, kInfo);
            } catch (const std::runtime_error& error) {
                EXPECT_STREQ(error.what(), "HDF5: \"\" cannot name an object in /tables");
                throw;
            }
        },
        std::runtime_error);
}

// A medium may be named "salt/water" or "."; HDF5 names cannot hold those, so '%', '/' and "." are percent-encoded.
TEST(ResultsHdf5Names, SlashPercentAndDotArePercentEncoded) {
    ResultReport report;
    report.set({"by_medium", "salt/water", "share"}, 0.5);
    report.set({"by_medium", ".", "share"}, 0.25);
    report.set({"by_medium", "100%", "share"}, 0.125);
    report.set({"by_medium", "..", "share"}, 0.0625);
    report.addTable({"a/b", {{"x/y", std::vector<double>{1.0}}}});
    const Hdf5Handle file = openImage(resultsHdf5Bytes(report, kInfo));
    EXPECT_EQ(linkNames(file.id(), "/summary/by_medium"),
              (std::vector<std::string>{"salt%2Fwater", "%2E", "100%25", ".."}));
    EXPECT_EQ(numberAttribute(file.id(), "/summary/by_medium/salt%2Fwater", "share"), 0.5);
    EXPECT_EQ(linkNames(file.id(), "/tables/a%2Fb"), std::vector<std::string>{"x%2Fy"});
    EXPECT_EQ(texts(openAttribute(file.id(), "/tables/a%2Fb", "columns").id()), std::vector<std::string>{"x%2Fy"});
}

}  // namespace
}  // namespace dropscope
