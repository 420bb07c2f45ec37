// Which scenes Lorenz-Mie theory describes (one sphere, a cloud of spheres of one medium) and with which m and x.
#include "scene/SceneLoader.hpp"
#include "wave/SceneMie.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <variant>

namespace dropscope {
namespace {

Scene sceneOf(const std::string& shapes, const std::string& generators = "[]", const std::string& host = "1.2") {
    return parseScene(R"({"dropscope": 1, "unit": "um", "wavelength_nm": 500, "ambient": "host",
      "media": {"host": {"n": )" +
                          host + R"(}, "water": {"n": 1.3337, "kappa": 1e-3}, "glass": {"n": 1.5}},
      "shapes": )" + shapes +
                          R"(, "generators": )" + generators + "}",
                      "mie-target.json");
}

TEST(SphereSceneMie, OneSphereIsItsSizeParameterAndRelativeIndex) {
    const auto found =
        sphereSceneMie(sceneOf(R"([{"type": "sphere", "center": [0, 0, 0], "radius": 2, "medium": "water"}])"));
    ASSERT_TRUE(std::holds_alternative<SphereSceneMie>(found)) << std::get<std::string>(found);
    const SphereSceneMie& spheres = std::get<SphereSceneMie>(found);
    EXPECT_EQ(spheres.spheres, 1u);
    ASSERT_EQ(spheres.sizes.size(), 1u);
    EXPECT_NEAR(spheres.sizes[0], 2.0 * std::numbers::pi * 2.0 * 1.2 / 0.5, 1e-12);
    EXPECT_NEAR(spheres.m.real(), 1.3337 / 1.2, 1e-15);
    EXPECT_NEAR(spheres.m.imag(), 1e-3 / 1.2, 1e-15);
    EXPECT_EQ(spheres.medium, "water");
}

TEST(SphereSceneMie, ACloudIsEveryDropletsSizeAscending) {
    const auto found = sphereSceneMie(sceneOf("[]", R"([{"type": "droplet_cloud", "region": {"min": [0, 0, 0],
        "max": [100, 100, 100]}, "count": 50, "radius": {"distribution": "uniform", "min": 1, "max": 2},
        "medium": "water", "seed": 4}])"));
    ASSERT_TRUE(std::holds_alternative<SphereSceneMie>(found)) << std::get<std::string>(found);
    const SphereSceneMie& spheres = std::get<SphereSceneMie>(found);
    EXPECT_EQ(spheres.spheres, 50u);
    ASSERT_EQ(spheres.sizes.size(), 50u);
    EXPECT_TRUE(std::is_sorted(spheres.sizes.begin(), spheres.sizes.end()));
    const double k = 2.0 * std::numbers::pi * 1.2 / 0.5;
    EXPECT_GE(spheres.sizes.front(), k * 1.0);
    EXPECT_LE(spheres.sizes.back(), k * 2.0);
    // A sample of 5 at probability midpoints: the 10th, 30th, ... percentiles.
    const std::vector<double> sample = sizeSample(spheres.sizes, 5);
    ASSERT_EQ(sample.size(), 5u);
    EXPECT_EQ(sample[0], spheres.sizes[5]);
    EXPECT_EQ(sample[4], spheres.sizes[45]);
    EXPECT_EQ(sizeSample(spheres.sizes, 80), spheres.sizes);
}

TEST(SphereSceneMie, OtherScenesSayWhyNot) {
    const auto reason = [](const Scene& scene) {
        const auto found = sphereSceneMie(scene);
        return std::holds_alternative<std::string>(found) ? std::get<std::string>(found) : std::string("found");
    };
    EXPECT_EQ(reason(sceneOf("[]")), "the scene has no shapes");
    EXPECT_EQ(reason(sceneOf(R"([{"type": "box", "min": [0, 0, 0], "max": [1, 1, 1], "medium": "water"}])")),
              "shape 0 is a box: Mie theory is for spheres");
    EXPECT_EQ(reason(sceneOf(R"([{"type": "sphere", "center": [0, 0, 0], "radius": 1, "medium": "water"},
                                 {"type": "sphere", "center": [5, 0, 0], "radius": 1, "medium": "glass"}])")),
              "the spheres are of different media");
    EXPECT_NE(reason(sceneOf(R"([{"type": "sphere", "center": [0, 0, 0], "radius": 1e4, "medium": "water"}])"))
                  .find("outside 1e-3..2e4"),
              std::string::npos);
    EXPECT_NE(reason(sceneOf(R"([{"type": "sphere", "center": [0, 0, 0], "radius": 1, "medium": "glass"}])", "[]",
                             R"(1.0, "kappa": 0.01)"))
                  .find("absorbs"),
              std::string::npos);
}

}  // namespace
}  // namespace dropscope
