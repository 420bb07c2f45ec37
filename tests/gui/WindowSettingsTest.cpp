#include "gui/window/GlfwInput.hpp"
#include "gui/window/WindowSettings.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

namespace dropscope::gui {
namespace {

std::filesystem::path scratch(const std::string& name) {
    const auto directory = std::filesystem::temp_directory_path() / ("dropscope-window-" + name);
    std::filesystem::remove_all(directory);
    return directory;
}

TEST(WindowSettings, TheSizeIsRememberedThroughAFileItsFolderIncluded) {
    const auto directory = scratch("size");
    const auto file = directory / "nested" / "window.txt";
    writeWindowSize(file, {900, 600});
    const auto size = readWindowSize(file);
    ASSERT_TRUE(size.has_value());
    EXPECT_EQ(size->width, 900);
    EXPECT_EQ(size->height, 600);
    std::filesystem::remove_all(directory);
}

TEST(WindowSettings, AGarbledOrMissingFileIsIgnoredAndAnAbsurdSizeClamped) {
    const auto directory = scratch("garbled");
    std::filesystem::create_directories(directory);
    EXPECT_FALSE(readWindowSize(directory / "missing.txt").has_value());
    std::ofstream(directory / "bad.txt") << "wide tall";
    EXPECT_FALSE(readWindowSize(directory / "bad.txt").has_value());
    std::ofstream(directory / "huge.txt") << "99999 10";
    const auto clamped = readWindowSize(directory / "huge.txt");
    ASSERT_TRUE(clamped.has_value());
    EXPECT_EQ(clamped->width, kMaximumWindowSide);
    EXPECT_EQ(clamped->height, kMinimumWindowSide);
    std::filesystem::remove_all(directory);
}

TEST(WindowSettings, TheSettingsLiveUnderTheXdgConfigHomeElseUnderHome) {
    const char* home = std::getenv("HOME");
    const char* xdg = std::getenv("XDG_CONFIG_HOME");
    const std::string savedHome = home ? home : "";
    const std::string savedXdg = xdg ? xdg : "";
    ::setenv("HOME", "/home/someone", 1);
    ::setenv("XDG_CONFIG_HOME", "/config", 1);
    EXPECT_EQ(defaultSettingsDirectory(), std::filesystem::path("/config/dropscope"));
    ::setenv("XDG_CONFIG_HOME", "relative", 1);  // not absolute: ignored, as the XDG specification says
    EXPECT_EQ(defaultSettingsDirectory(), std::filesystem::path("/home/someone/.config/dropscope"));
    ::unsetenv("XDG_CONFIG_HOME");
    ::unsetenv("HOME");
    EXPECT_TRUE(defaultSettingsDirectory().empty());
    if (home) ::setenv("HOME", savedHome.c_str(), 1);
    if (xdg) ::setenv("XDG_CONFIG_HOME", savedXdg.c_str(), 1);
}

TEST(GlfwKeys, PrintableKeysAreTheirAsciiCodesAndNamedKeysOurs) {
    EXPECT_EQ(keyFromGlfw(GLFW_KEY_Q), std::optional<Key>(static_cast<Key>('Q')));
    EXPECT_EQ(keyFromGlfw(GLFW_KEY_LEFT_BRACKET), std::optional<Key>(static_cast<Key>('[')));
    EXPECT_EQ(keyFromGlfw(GLFW_KEY_SPACE), std::optional<Key>(kKeySpace));
    EXPECT_EQ(keyFromGlfw(GLFW_KEY_F12), std::optional<Key>(kKeyF12));
    EXPECT_EQ(keyFromGlfw(GLFW_KEY_ESCAPE), std::optional<Key>(kKeyEscape));
    EXPECT_EQ(keyFromGlfw(GLFW_KEY_LEFT), std::optional<Key>(kKeyLeft));
    EXPECT_FALSE(keyFromGlfw(GLFW_KEY_LEFT_CONTROL).has_value());  // modifiers arrive as flags
}

}  // namespace
}  // namespace dropscope::gui
