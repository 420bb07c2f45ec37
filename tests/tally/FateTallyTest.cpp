// FateTally's first lost photon: the lowest index, whatever order threads and ranks merge in, and through the
// bytes ranks exchange; the warning line names it.
#include "tally/FateTally.hpp"

#include "tally/ScoreBytes.hpp"
#include "transport/PhotonObserver.hpp"

#include <gtest/gtest.h>

namespace dropscope {
namespace {

Event eventOf(EventType type, const Point& at = Point::Zero()) {
    Event event;
    event.type = type;
    event.position = at;
    return event;
}

void scoreLost(FateTally& fates, std::uint64_t photon, LostReason reason, ShapeId shape, const Point& at) {
    const PhotonState state;
    fates.score(eventOf(EventType::Emit), {photon, 0, state});
    Event lost = eventOf(EventType::Lost, at);
    lost.lostReason = reason;
    lost.lostAt = shape;
    fates.score(lost, {photon, 0, state});
}

void scoreEscaped(FateTally& fates, std::uint64_t photon) {
    const PhotonState state;
    fates.score(eventOf(EventType::Emit), {photon, 0, state});
    fates.score(eventOf(EventType::Escape), {photon, 0, state});
}

TEST(FateTally, NothingLostMeansNoWarning) {
    FateTally fates;
    scoreEscaped(fates, 0);
    EXPECT_FALSE(fates.firstLost().has_value());
    EXPECT_FALSE(fates.lossWarning().has_value());
}

TEST(FateTally, TheFirstLostIsTheLowestIndexInAnyMergeOrder) {
    FateTally early;  // a thread that traced photons 7 and 8
    scoreLost(early, 8, LostReason::EventCap, 2, {1, 2, 3});
    scoreEscaped(early, 7);
    FateTally late;  // photons 3 to 5
    scoreEscaped(late, 3);
    scoreLost(late, 5, LostReason::UndefinedNormal, 0, {-1, -1, 0});
    scoreLost(late, 4, LostReason::UndefinedNormal, 0, {-1, -1, 0.5});
    FateTally forwards = early;
    forwards.merge(late);
    FateTally backwards = late;
    backwards.merge(early);
    ASSERT_TRUE(forwards.firstLost().has_value());
    EXPECT_EQ(forwards.firstLost()->photon, 4u);
    EXPECT_EQ(forwards.firstLost()->position, Point(-1, -1, 0.5));
    EXPECT_EQ(forwards, backwards);
    EXPECT_EQ(forwards.mainLostReason(), LostReason::UndefinedNormal);
    EXPECT_EQ(forwards.lossWarning().value_or(""),
              "lost 60 % of the photons (3 of 5), mostly at box edges or vertices, where a surface has no normal "
              "(undefined_normal: 2); the first, photon 4, at shape 0 (-1, -1, 0.5), undefined_normal");
    forwards.nameShapes([](ShapeId id) { return "generators[0]: droplet " + std::to_string(id + 10); });
    EXPECT_EQ(forwards.lossWarning().value_or(""),
              "lost 60 % of the photons (3 of 5), mostly at box edges or vertices, where a surface has no normal "
              "(undefined_normal: 2); the first, photon 4, on generators[0]: droplet 10 at (-1, -1, 0.5), "
              "undefined_normal");
}

TEST(FateTally, TheFirstLostTravelsThroughScoreBytes) {
    FateTally fates;
    scoreLost(fates, 11, LostReason::NoExit, 3, {0.25, -0.5, 1e-300});
    std::vector<std::byte> bytes;
    ScoreWriter out(bytes);
    fates.writeScores(out);
    FateTally read;
    ScoreReader in(bytes);
    read.readScores(in);
    EXPECT_EQ(read, fates);
    ASSERT_TRUE(read.firstLost().has_value());
    EXPECT_EQ(read.firstLost()->shape, 3u);
    EXPECT_EQ(read.firstLost()->position.z(), 1e-300);
}

}  // namespace
}  // namespace dropscope
