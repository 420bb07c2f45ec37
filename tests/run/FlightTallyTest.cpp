// A tally of flights, the hook detectors use: the track length a run's photons spend in a medium,
// summed with FixedPointSum, against the closed form of a slab, and the same bits on 1 and 2 threads.
#include "tally/FixedPointSum.hpp"
#include "transport/TallyExpectations.hpp"
#include "transport/TransportFixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace dropscope {
namespace {

// Track length per photon in one medium, and (to check the flights chain) the escape flights.
class TrackLengthTally final : public Tally {
public:
    explicit TrackLengthTally(MediumId medium) : medium_(medium) {}
    std::string_view name() const override { return "track_length"; }
    std::unique_ptr<Tally> emptyCopy() const override { return std::make_unique<TrackLengthTally>(medium_); }
    std::unique_ptr<Tally> clone() const override { return std::make_unique<TrackLengthTally>(*this); }
    void score(const Event& event, const TallyContext&) override { photons_ += event.type == EventType::Emit; }
    bool scoresFlights() const override { return true; }
    void scoreFlight(const Flight& flight, const TallyContext&) override {
        if (std::isinf(flight.length)) ++escapeFlights_;
        if (flight.medium == medium_) length_.add(flight.length);
    }
    void merge(const Tally& other) override {
        const auto& more = sameTally(*this, other);
        photons_ += more.photons_;
        escapeFlights_ += more.escapeFlights_;
        length_ += more.length_;
    }
    void writeScores(ScoreWriter& out) const override {
        out.word(photons_);
        out.word(escapeFlights_);
        out.sum(length_);
    }
    void readScores(ScoreReader& in) override {
        photons_ = in.word();
        escapeFlights_ = in.word();
        length_ = in.sum();
    }
    void report(ResultReport& report) const override { report.set({"track_length"}, length_.value()); }

    std::uint64_t photons() const { return photons_; }
    std::uint64_t escapeFlights() const { return escapeFlights_; }
    const FixedPointSum& length() const { return length_; }

private:
    MediumId medium_;
    std::uint64_t photons_ = 0;
    std::uint64_t escapeFlights_ = 0;
    FixedPointSum length_;
};

constexpr double kThickness = 2.0;

Scene glassSlab() {
    // A pencil at normal incidence on a slab much wider than the beam, n = 1.5, no absorption.
    return testing::sceneFromJson(R"("air": {"n": 1}, "glass": {"n": 1.5})",
                                  R"({"type": "box", "min": [-50, -50, 0], "max": [50, 50, 2], "medium": "glass"})",
                                  R"({"type": "ray", "origin": [0.25, -0.5, -1], "direction": [0, 0, 1]})");
}

TraceResult traceTrackLength(const Scene& scene, std::uint64_t photons, int threads) {
    TallySet tallies = standardTallies(180, PolarisationModel::Stokes);
    tallies.add(std::make_unique<TrackLengthTally>(1));  // glass
    TraceSettings settings;
    settings.photons = photons;
    settings.threads = threads;
    settings.seed = 9;
    return runTrace(OpticalScene(scene), scene.sources, settings, tallies);
}

TEST(FlightTally, MeanTrackLengthInASlabIsItsThickness) {
    // A photon enters with 1 - R and then crosses k >= 1 times with probability R^(k-1) (1 - R), so its
    // mean track length in the glass is (1 - R) L / (1 - R) = L whatever R is. The per-photon length is
    // 0 or k L: variance L^2 (1 + R) / (1 - R) - L^2 = L^2 2R / (1 - R).
    constexpr std::uint64_t kPhotons = 200000;
    const TraceResult result = traceTrackLength(glassSlab(), kPhotons, 2);
    const auto& tally = result.tallies.get<TrackLengthTally>();
    const double reflectance = 0.04;  // ((1.5 - 1) / (1.5 + 1))^2
    const double sigma = kThickness * std::sqrt(2.0 * reflectance / (1.0 - reflectance) / kPhotons);
    EXPECT_EQ(tally.photons(), kPhotons);
    EXPECT_NEAR(tally.length().value() / kPhotons, kThickness, 5.0 * sigma);
    EXPECT_EQ(tally.escapeFlights(), test::fates(result).escaped());  // one infinite flight per escape
}

TEST(FlightTally, WeightedSumsAreTheSameBitsOnOneAndTwoThreads) {
    const Scene scene = glassSlab();
    const TraceResult one = traceTrackLength(scene, 30000, 1);
    const TraceResult two = traceTrackLength(scene, 30000, 2);
    EXPECT_EQ(one.tallies.get<TrackLengthTally>().length(), two.tallies.get<TrackLengthTally>().length());
    test::expectSameTally(one, two);
}

TEST(FlightTally, CopiedAndMovedSetsScoreFlightsIntoTheirOwnTallies) {
    TallySet original;
    original.add(std::make_unique<TrackLengthTally>(0));
    TallySet copy = original;
    TallySet moved = std::move(copy);
    ASSERT_TRUE(moved.scoresFlights());
    const PhotonState state;
    moved.scoreFlight({Point::Zero(), Direction(0, 0, 1), 2.5, 0}, {0, 0, state});
    EXPECT_EQ(moved.get<TrackLengthTally>().length().value(), 2.5);
    EXPECT_EQ(original.get<TrackLengthTally>().length().value(), 0.0);
    TallySet assigned;
    assigned = moved;
    assigned.scoreFlight({Point::Zero(), Direction(0, 0, 1), 1.0, 0}, {0, 0, state});
    EXPECT_EQ(assigned.get<TrackLengthTally>().length().value(), 3.5);
    EXPECT_EQ(moved.get<TrackLengthTally>().length().value(), 2.5);
}

// Flights chain: each starts where the one before ended, the first at the emission; each is in the
// medium the events before it left the photon in; only an escaped photon's last flight is infinite.
class FlightChain final : public PhotonObserver {
public:
    void event(const Event& event, const PhotonState&) override {
        events_.push_back(event);
        medium_ = event.type == EventType::Reflect || event.type == EventType::Tir ? event.from : event.to;
    }
    void flight(const Flight& flight, const PhotonState&) override {
        flights_.push_back(flight);
        expectedMedia_.push_back(medium_);
    }
    bool wantsFlights() const override { return true; }
    std::vector<Event> events_;
    std::vector<Flight> flights_;
    std::vector<MediumId> expectedMedia_;

private:
    MediumId medium_ = 0;
};

// Where one flight ends, computed here, against where the tracer put the next start: coordinates below
// 30 moved by one multiply and add, a few ulps (~1e-14) whether or not this code is contracted to FMA.
constexpr double kChainRounding = 1e-12;

TEST(FlightTally, FlightsChainFromTheEmissionToTheEnd) {
    const Scene scene =
        testing::sceneFromJson(R"("air": {"n": 1}, "water": {"n": 1.3337, "sigma": 0.3})",
                               R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "medium": "water"})",
                               R"({"type": "beam", "origin": [0, 0, -30], "direction": [0, 0, 1], "radius": 1})");
    const OpticalScene optical(scene);
    int escaped = 0, absorbed = 0;
    for (std::uint64_t photon = 0; photon < 300; ++photon) {
        PhotonRandom random(4, photon);
        const Ray emitted = emitPhoton(scene.sources[0], random);
        FlightChain chain;
        const PhotonOutcome outcome = tracePhoton(optical, emitted, random, TransportSettings{}, &chain);
        ASSERT_FALSE(chain.flights_.empty());
        EXPECT_EQ(chain.flights_.front().origin, emitted.origin);
        for (std::size_t k = 1; k < chain.flights_.size(); ++k) {
            const Flight& before = chain.flights_[k - 1];
            ASSERT_TRUE(std::isfinite(before.length));
            EXPECT_LT((before.origin + before.length * before.direction.vector() - chain.flights_[k].origin).norm(),
                      kChainRounding);
        }
        for (std::size_t k = 0; k < chain.flights_.size(); ++k)
            EXPECT_EQ(chain.flights_[k].medium, chain.expectedMedia_[k]);
        const Flight& last = chain.flights_.back();
        EXPECT_EQ(std::isinf(last.length), outcome.fate == PhotonFate::Escaped);
        if (outcome.fate == PhotonFate::Absorbed) {
            ++absorbed;
            EXPECT_LT((last.origin + last.length * last.direction.vector() - chain.events_.back().position).norm(),
                      kChainRounding);
            EXPECT_EQ(last.medium, 1U);  // only the water absorbs
        }
        escaped += outcome.fate == PhotonFate::Escaped;
    }
    EXPECT_GT(escaped, 100);
    EXPECT_GT(absorbed, 20);
}

}  // namespace
}  // namespace dropscope
