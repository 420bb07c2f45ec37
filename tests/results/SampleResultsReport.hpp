#pragma once

// A report made by hand with one of everything results.h5 holds: nested summary keys of every value kind,
// a plain table, a detector's grid table with units and a text column, an empty table and an image. Shared
// by ResultsHdf5Test.cpp and sample/WriteSampleResultsHdf5.cpp, whose file read_results_h5.py reads.
#include "tally/ResultReport.hpp"

#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace dropscope::test {

inline ResultReport sampleResultsReport() {
    ResultReport report;
    report.set({"photons"}, std::uint64_t{1000});
    report.set({"seed"}, std::uint64_t{7});
    report.set({"threads"}, std::uint64_t{2});  // left out of results.h5 by default, as is seconds
    report.set({"seconds"}, 0.5);
    report.set({"partial"}, false);
    report.set({"scene"}, std::string("scenes/caf\xC3\xA9.json"));
    report.set({"fractions", "escaped"}, 0.75);
    report.set({"fractions", "absorbed"}, std::numeric_limits<double>::quiet_NaN());
    report.set({"spectra", "0", "spectrum"}, std::string("sun"));
    report.set({"spectra", "0", "lo_nm"}, 380.0);
    report.set({"polarised"}, true);
    report.set({"wavelength_nm"}, nullptr);
    // More than 8 attributes (and below, columns) in one group: HDF5 keeps those in its dense storage.
    for (const char* key : {"bins", "max_events", "paths", "sources"}) report.set({key}, std::uint64_t{180});
    report.addTable({"angular",
                     {{"theta_lo_deg", std::vector<double>{0.0, 90.0}, "deg"},
                      {"theta_hi_deg", std::vector<double>{90.0, 180.0}, "deg"},
                      {"count", std::vector<std::uint64_t>{1, 3}},
                      {"fraction", std::vector<double>{0.25, 0.75}}}});
    // Two rows of three pixels, iy outer and ix inner; more than 8 columns, as a far-field detector has.
    ResultTable sky{"detector-sky",
                    {{"ix", std::vector<std::uint64_t>{0, 1, 2, 0, 1, 2}},
                     {"iy", std::vector<std::uint64_t>{0, 0, 0, 1, 1, 1}},
                     {"fraction", std::vector<double>{0.0, 0.1, 0.2, 0.3, 0.4, 0.5}},
                     {"radiance", std::vector<double>{0.0, 1.5, 3.0, 4.5, 6.0, 7.5}, "1/sr"},
                     {"label", std::vector<std::string>{"a", "b", "c", "d", "e", "f"}}},
                    {2, 3}};
    for (const char* name : {"stokes_q", "stokes_u", "stokes_v", "cie_x", "cie_y", "cie_z"}) {
        sky.columns.push_back({name, std::vector<double>(6, 0.125)});
    }
    report.addTable(std::move(sky));
    report.addTable({"detector-sky-records",
                     {{"shape", std::vector<std::string>{"sphere 0", "box, 1"}},
                      {"x", std::vector<double>{-0.5, 2.0}, "scene unit"}}});
    report.addTable({"empty", {{"value", std::vector<double>{}, "nm"}}});
    std::vector<std::uint8_t> rgb;
    for (std::uint8_t value = 0; value < 18; ++value) rgb.push_back(value);
    report.addImage({"detector-sky", 3, 2, rgb});
    return report;
}

inline constexpr const char* kSampleSceneJson = R"({"format": 1, "shapes": []})";

}  // namespace dropscope::test
