// The app survives every scene file it is given: opening one either shows it (and the next frames draw it) or
// refuses it with the reason in the status line, and never ends the app. The files: every JSON file of assets/
// and tests/data, the fuzzers' regression inputs (tests/fuzz/regressions/scene), a few hostile ones written here,
// and, when DROPSCOPE_FUZZ_CORPUS names a folder, every file in it (the fuzz build points it at what fuzz_scene
// found, docs/fuzzing.md).
#include "AppHarness.hpp"
#include "UiTestScenes.hpp"

#include "gui/Actions.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace dropscope::gui::testing {
namespace {

namespace fs = std::filesystem;

void addFiles(std::vector<fs::path>& files, const fs::path& folder, bool recursive, const std::string& extension) {
    if (!fs::is_directory(folder)) return;
    const auto add = [&](const fs::directory_entry& entry) {
        if (entry.is_regular_file() && (extension.empty() || entry.path().extension() == extension))
            files.push_back(entry.path());
    };
    if (recursive) {
        for (const auto& entry : fs::recursive_directory_iterator(folder)) add(entry);
    } else {
        for (const auto& entry : fs::directory_iterator(folder)) add(entry);
    }
}

// Files no scene writer makes, each refused for its own reason.
std::vector<fs::path> writeHostileFiles(const fs::path& folder) {
    fs::create_directories(folder);
    const std::string scene =
        R"({"dropscope": 1, "ambient": "air", "media": {"air": {"n": 1}, "water": {"n": 1.33}}, )";
    const std::vector<std::pair<std::string, std::string>> contents = {
        {"empty.json", ""},
        {"byte-order-mark.json", "\xEF\xBB\xBF{\"dropscope\": 1}"},
        {"deep.json", std::string(100000, '[')},
        {"nul.json", std::string("{\"dropscope\": 1\0}", 17)},
        {"invalid-utf8.json", scene + "\"shapes\": [], \"\xFF\xFE\": 1}"},
        {"number-out-of-range.json", R"({"dropscope": 1e999})"},
        {"nan.json", R"({"dropscope": NaN})"},
        {"duplicate-key.json", R"({"dropscope": 1, "dropscope": 1})"},
        {"truncated.json", scene.substr(0, scene.size() - 7)},
        {"patches-names-this-scene.json",
         scene + R"("shapes": [{"type": "parametric", "preset": "bezier", "patches": "patches-names-this-scene.json",
                    "medium": "water"}]})"},
        {"patches-name-a-folder.json",
         scene + R"("shapes": [{"type": "parametric", "preset": "bezier", "patches": ".", "medium": "water"}]})"},
        {"too-many-droplets.json",
         scene + R"("generators": [{"type": "droplet_cloud", "region": {"min": [0, 0, 0], "max": [1, 1, 1]},
                    "count": 10000001, "radius": {"distribution": "fixed", "value": 0.001}, "medium": "water"}]})"},
    };
    std::vector<fs::path> files;
    for (const auto& [name, text] : contents) {
        files.push_back(folder / name);
        std::ofstream(files.back(), std::ios::binary) << text;
    }
    files.push_back(folder);                        // a folder
    files.push_back(folder / "no-such-file.json");  // nothing
    files.push_back("/dev/null");                   // a file that is empty and not a regular file
    return files;
}

TEST(OpenFuzzedScenesUi, EveryFileIsShownOrRefusedWithItsReason) {
    const fs::path source(DROPSCOPE_SOURCE_DIR);
    std::vector<fs::path> files;
    addFiles(files, source / "assets", true, ".json");
    addFiles(files, source / "tests" / "data", true, ".json");
    addFiles(files, source / "tests" / "fuzz" / "regressions" / "scene", false, "");
    const fs::path hostile =
        fs::temp_directory_path() /
        ("dropscope-hostile-scenes-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
    for (const fs::path& file : writeHostileFiles(hostile)) files.push_back(file);
    if (const char* corpus = std::getenv("DROPSCOPE_FUZZ_CORPUS")) addFiles(files, corpus, false, "");

    AppHarness harness(kAxisScene, 320, 200);  // small: every shown scene is drawn
    const StatusLine& status = harness.state().ui.status;
    std::size_t shown = 0;
    for (const fs::path& file : files) {
        SCOPED_TRACE(file.string());
        if (openScene(harness.state(), file)) {
            EXPECT_FALSE(status.error()) << status.text();
            EXPECT_TRUE(status.text().starts_with("opened ")) << status.text();
            harness.frames(2);
            ++shown;
        } else {
            EXPECT_TRUE(status.error());
            EXPECT_TRUE(status.text().starts_with("could not open: ")) << status.text();
            EXPECT_GT(status.text().size(), std::string("could not open: ").size());
        }
    }
    EXPECT_GT(shown, 10u) << "the scenes of assets/ and tests/data open";
    EXPECT_LT(shown, files.size()) << "the hostile files are refused";
    fs::remove_all(hostile);
}

}  // namespace
}  // namespace dropscope::gui::testing
