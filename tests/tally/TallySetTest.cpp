// Tallies and their set: scores merged from any split equal the scores of one pass; reports in no
// file format, their key and table rules.
#include "tally/AngularTally.hpp"
#include "tally/FateTally.hpp"
#include "tally/StandardTallies.hpp"
#include "tally/TallySet.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

namespace dropscope {
namespace {

// A made-up stream of photons: each emitted along +z, then a few interface events, then an end.
struct ScoredPhoton {
    PhotonState state;
    std::vector<Event> events;
};

std::vector<ScoredPhoton> photons(std::size_t count) {
    std::mt19937_64 random(3);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<ScoredPhoton> all;
    for (std::size_t i = 0; i < count; ++i) {
        ScoredPhoton photon{{{Point::Zero(), Direction(0, 0, 1)}}, {}};
        photon.events.emplace_back();  // the emission (Event's default type); no copy from an initializer list,
                                       // which GCC 12 at -O1 warns may read the empty optional's storage
        const int interfaces = static_cast<int>(4 * unit(random));
        for (int k = 0; k < interfaces; ++k) {
            Event event;
            event.type = k % 3 == 0 ? EventType::Refract : k % 3 == 1 ? EventType::Reflect : EventType::Tir;
            photon.events.push_back(event);
        }
        photon.state.metSurface = interfaces > 0;
        Event end;
        const double u = unit(random);
        end.type = u < 0.7 ? EventType::Escape : u < 0.9 ? EventType::Absorb : EventType::Lost;
        end.lostReason = static_cast<LostReason>(i % kLostReasonCount);
        const double theta = std::acos(2.0 * unit(random) - 1.0);
        end.direction = Direction(std::sin(theta), 0.0, std::cos(theta));
        // Partly polarised light in a frame turned by a random angle about the escape direction, so the
        // Stokes sums see other values than the counts do.
        const double turn = 2.0 * std::numbers::pi * unit(random);
        const Eigen::Vector3d reference = std::cos(turn) * Eigen::Vector3d::UnitY() +
                                          std::sin(turn) * Eigen::Vector3d::UnitY().cross(end.direction.vector());
        end.polarisation =
            Polarisation{StokesVector(1.0, unit(random) - 0.5, unit(random) - 0.5, unit(random) - 0.5), reference};
        photon.events.push_back(end);
        all.push_back(photon);
    }
    return all;
}

void scoreAll(TallySet& tallies, const std::vector<ScoredPhoton>& all, std::size_t first, std::size_t last) {
    for (std::size_t i = first; i < last; ++i) {
        for (const Event& event : all[i].events) tallies.score(event, {i, 0, all[i].state});
    }
}

TEST(TallySet, ScoresMergedFromAnySplitEqualOnePass) {
    const std::vector<ScoredPhoton> all = photons(3000);
    const TallySet prototype = standardTallies(36, PolarisationModel::Stokes);
    TallySet whole = prototype.emptyCopy();
    scoreAll(whole, all, 0, all.size());
    TallySet merged = prototype.emptyCopy();
    for (std::size_t first : {2000, 0, 1000}) {  // three "threads", merged out of order
        TallySet part = prototype.emptyCopy();
        scoreAll(part, all, first, first + 1000);
        merged.merge(part);
    }
    EXPECT_EQ(merged.get<FateTally>(), whole.get<FateTally>());
    EXPECT_EQ(merged.get<AngularTally>(), whole.get<AngularTally>());  // the Stokes sums too, bit for bit
    ASSERT_TRUE(whole.get<AngularTally>().stokes());
    const FateTally& fates = whole.get<FateTally>();
    EXPECT_EQ(fates.photons(), 3000U);
    EXPECT_EQ(fates.escaped() + fates.absorbed() + fates.lost(), fates.photons());
    EXPECT_EQ(fates.events().absorb, fates.absorbed());
    std::uint64_t binned = 0;
    for (std::uint64_t count : whole.get<AngularTally>().escapes()) binned += count;
    EXPECT_EQ(binned, fates.escaped());
}

TEST(TallySet, CopiesAreDeepAndEmptyCopiesEmpty) {
    TallySet tallies = standardTallies(4, PolarisationModel::Stokes);
    scoreAll(tallies, photons(10), 0, 10);
    const TallySet copy = tallies;
    scoreAll(tallies, photons(10), 0, 10);
    EXPECT_EQ(copy.get<FateTally>().photons(), 10U);
    EXPECT_EQ(tallies.get<FateTally>().photons(), 20U);
    EXPECT_EQ(tallies.emptyCopy().get<FateTally>(), FateTally());
    EXPECT_EQ(tallies.emptyCopy().get<AngularTally>().bins(), 4);
}

TEST(TallySet, RefusesTwoTalliesOfOneNameAndMergesOfOtherTallies) {
    TallySet tallies;
    tallies.add(std::make_unique<FateTally>());
    EXPECT_THROW(tallies.add(std::make_unique<FateTally>()), std::invalid_argument);
    FateTally fates;
    EXPECT_THROW(fates.merge(AngularTally(3)), std::logic_error);
    AngularTally angular(3);
    EXPECT_THROW(angular.merge(AngularTally(4)), std::logic_error);
    EXPECT_THROW(tallies.get<AngularTally>(), std::logic_error);
    EXPECT_EQ(tallies.find<AngularTally>(), nullptr);
}

TEST(ResultReport, KeepsTheOrderSetAndRefusesKeysSetTwiceClashesAndRaggedTables) {
    ResultReport report;
    report.set({"b"}, std::uint64_t{1});
    report.set({"a", "x"}, 0.5);
    report.set({"a", "y"}, std::string("two"));
    ASSERT_EQ(report.summary().size(), 3U);
    EXPECT_EQ(report.summary()[0].path, std::vector<std::string>{"b"});
    EXPECT_EQ(std::get<std::string>(*report.find({"a", "y"})), "two");
    EXPECT_THROW(report.set({"b"}, std::uint64_t{2}), std::invalid_argument);  // two tallies, one key
    EXPECT_EQ(std::get<std::uint64_t>(*report.find({"b"})), 1U);
    EXPECT_THROW(report.set({"a"}, true), std::invalid_argument);       // a is a group
    EXPECT_THROW(report.set({"b", "y"}, true), std::invalid_argument);  // b is a value
    EXPECT_THROW(report.addTable({"t", {{"c1", std::vector<double>{1, 2}}, {"c2", std::vector<double>{1}}}}),
                 std::invalid_argument);
    report.addTable({"t", {{"c1", std::vector<double>{1, 2}}, {"c2", std::vector<std::uint64_t>{3, 4}}}});
    EXPECT_THROW(report.addTable({"t", {}}), std::invalid_argument);
    EXPECT_EQ(report.table("t")->rows(), 2U);
}

}  // namespace
}  // namespace dropscope
