// write_sample_results_h5 FILE: writes the sample report (SampleResultsReport.hpp) as results.h5 to FILE,
// through the atomic writer as `dropscope trace` does, for read_results_h5.py.
#include "results/AtomicFile.hpp"
#include "results/ResultsHdf5.hpp"
#include "results/SampleResultsReport.hpp"
#include "results/Version.hpp"

#include <exception>
#include <iostream>
#include <string>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: write_sample_results_h5 FILE\n";
        return 2;
    }
    try {
        const dropscope::ResultReport report = dropscope::test::sampleResultsReport();
        const dropscope::ResultsFileInfo info{std::string(dropscope::dropscopeVersion()),
                                              dropscope::test::kSampleSceneJson};
        dropscope::writeFileAtomically(argv[1], [&](std::ostream& out) { writeResultsHdf5(report, info, out); });
    } catch (const std::exception& error) {
        std::cerr << "write_sample_results_h5: " << error.what() << '\n';
        return 1;
    }
    return 0;
}
