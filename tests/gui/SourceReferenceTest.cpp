// A polarised source's reference kept perpendicular to its direction (gui/SourceReference.hpp): projected
// across a new direction, replaced when it lies along it, left alone when it is perpendicular already or
// the source is unpolarised.
#include "gui/SourceReference.hpp"
#include "optics/OpticsTolerance.hpp"

#include <gtest/gtest.h>

#include <random>

namespace dropscope::gui {
namespace {

constexpr double kRounding = 1e-12;

Source linearSource(const Direction& direction, const Eigen::Vector3d& reference) {
    Source source;
    source.direction = direction;
    source.polarisation.kind = PolarisationKind::Linear;
    source.polarisation.linearDeg = 30.0;
    source.polarisation.reference = reference;
    return source;
}

TEST(SourceReference, APerpendicularReferenceIsTheAxisLeastAlongTheDirection) {
    EXPECT_EQ(perpendicularReference(Direction(0, 0, 1)), Eigen::Vector3d::UnitX());
    EXPECT_EQ(perpendicularReference(Direction(0, 0, -1)), Eigen::Vector3d::UnitX());
    EXPECT_EQ(perpendicularReference(Direction(1, 0, 0)), Eigen::Vector3d::UnitY());
    std::mt19937_64 random(5);
    std::normal_distribution<double> normal;
    for (int k = 0; k < 100; ++k) {
        const Direction direction(normal(random), normal(random), normal(random));
        const Eigen::Vector3d reference = perpendicularReference(direction);
        EXPECT_NEAR(reference.norm(), 1.0, kRounding) << "case " << k;
        EXPECT_NEAR(reference.dot(direction.vector()), 0.0, kRounding) << "case " << k;
    }
}

TEST(SourceReference, AimingProjectsTheReferenceAcrossTheNewDirection) {
    Source source = linearSource(Direction(0, 0, 1), Eigen::Vector3d::UnitX());
    const std::string note = aimSource(source, Direction(1, 0, 1));
    EXPECT_NE(note.find("projected"), std::string::npos) << note;
    EXPECT_NEAR((source.polarisation.reference - Eigen::Vector3d(1, 0, -1).normalized()).norm(), 0.0, kRounding);
    EXPECT_NO_THROW(checkPolarisation(source));
    EXPECT_EQ(source.polarisation.linearDeg, 30.0) << "the state itself is kept";
}

TEST(SourceReference, AReferenceAlongTheNewDirectionIsReplaced) {
    Source source = linearSource(Direction(0, 0, 1), Eigen::Vector3d::UnitX());
    const std::string note = aimSource(source, Direction(1, 0, 0));
    EXPECT_NE(note.find("perpendicular"), std::string::npos) << note;
    EXPECT_EQ(source.polarisation.reference, perpendicularReference(Direction(1, 0, 0)));
    EXPECT_NO_THROW(checkPolarisation(source));
}

TEST(SourceReference, APerpendicularReferenceOrAnUnpolarisedSourceIsLeftAlone) {
    Source source = linearSource(Direction(0, 0, 1), Eigen::Vector3d(0, 2, 0));
    EXPECT_EQ(aimSource(source, Direction(1, 0, 0)), "");
    EXPECT_EQ(source.polarisation.reference, Eigen::Vector3d(0, 2, 0)) << "as given, not even normalised";

    Source unpolarised;
    unpolarised.direction = Direction(0, 0, 1);
    EXPECT_EQ(aimSource(unpolarised, Direction(1, 0, 0)), "");
    EXPECT_EQ(unpolarised.polarisation.reference, Eigen::Vector3d::Zero());
}

TEST(SourceReference, AZeroReferenceOfAPolarisedSourceIsSet) {
    Source source = linearSource(Direction(0, 1, 0), Eigen::Vector3d::Zero());
    EXPECT_NE(keepReferencePerpendicular(source), "");
    EXPECT_EQ(source.polarisation.reference, Eigen::Vector3d::UnitX());
    EXPECT_NO_THROW(checkPolarisation(source));
}

}  // namespace
}  // namespace dropscope::gui
