#pragma once

#include "scene/Detector.hpp"
#include "tally/FixedPointSum.hpp"
#include "tally/Tally.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace dropscope {

// One hit a detector records ("record": K): MCX's "detected photons".
struct DetectorHit {
    std::uint64_t photon = 0;
    std::uint64_t sequence = 0;  // the hit's number among this photon's hits on the detector
    Point position = Point::Zero();
    Eigen::Vector3d direction = Eigen::Vector3d::Zero();
    double weight = 1.0;
    double wavelengthNm = 0.0;
    StokesVector stokes = unpolarisedStokes();  // in the detector's frame (docs/detectors.md)
    std::uint64_t events = 0;                   // interface events before the hit
    double pathLength = 0.0;                    // flown from the emission to the hit
};

// The first `capacity` hits of a run by (photon, sequence): the same hits for any thread count, since each
// thread keeps its own first ones and a merge keeps the first of both.
class HitRecords {
public:
    explicit HitRecords(std::uint64_t capacity = 0) : capacity_(capacity) {}
    std::uint64_t capacity() const { return capacity_; }
    bool wants(std::uint64_t photon) const;
    void offer(const DetectorHit& hit);
    void merge(const HitRecords& other);
    void writeScores(ScoreWriter& out) const;
    void readScores(ScoreReader& in);
    const std::vector<DetectorHit>& hits() const { return hits_; }
    // Table `name`: photon, x, y, z, dx, dy, dz, weight, wavelength_nm, [stokes_i, stokes_q, stokes_u,
    // stokes_v,] events, path_length.
    ResultTable table(const std::string& name, bool stokes) const;

private:
    std::uint64_t capacity_;
    std::vector<DetectorHit> hits_;  // sorted by (photon, sequence), at most capacity_
};

// "detector-NAME": the name of the detector's tally, of its table and image, and of its files.
std::string detectorTableName(const Detector& detector);

// Shared by the three detector tallies: the detector, its index in the scene, its records and the photon
// being scored (to number its hits).
class DetectorTally : public Tally {
public:
    DetectorTally(Detector detector, std::size_t index, bool stokes);
    std::string_view name() const override { return tableName_; }
    const Detector& detector() const { return detector_; }
    std::size_t index() const { return index_; }
    bool stokes() const { return stokes_; }
    std::uint64_t photons() const { return photons_; }
    std::uint64_t hits() const { return hits_; }
    const HitRecords& records() const { return records_; }

protected:
    // Counts the emission (every tally sees it) and starts numbering the photon's hits.
    void startPhoton(const Event& event, const TallyContext& photon);
    void countHit(const TallyContext& photon, const Point& position, const Eigen::Vector3d& direction,
                  const StokesVector& stokes, double pathLength);
    void mergeCommon(const DetectorTally& other);
    void writeCommonScores(ScoreWriter& out) const;
    void readCommonScores(ScoreReader& in);
    // The summary's detectors.NAME values and the records table, if any.
    void reportCommon(ResultReport& report) const;
    double share(double count) const;

private:
    Detector detector_;
    std::size_t index_;
    bool stokes_;
    std::string tableName_;
    std::uint64_t photons_ = 0;
    std::uint64_t hits_ = 0;
    std::uint64_t sequence_ = 0;
    HitRecords records_;
};

// A plane detector's image: every crossing of a photon path through each pixel on the sides it counts (an
// absorbing plane: every photon it ended). Table "detector-NAME": ix, iy, u, v, fraction (of the emitted power),
// irradiance (fraction per unit area, scene units), and with Stokes stokes_q, stokes_u, stokes_v (shares like
// fraction; parallel axis u).
class PlaneDetectorTally final : public DetectorTally {
public:
    PlaneDetectorTally(Detector detector, std::size_t index, bool stokes);
    std::unique_ptr<Tally> emptyCopy() const override;
    std::unique_ptr<Tally> clone() const override { return std::make_unique<PlaneDetectorTally>(*this); }
    void score(const Event& event, const TallyContext& photon) override;
    void scoreFlight(const Flight& flight, const TallyContext& photon) override;
    bool scoresFlights() const override { return !detector().absorbing; }
    void merge(const Tally& other) override;
    void writeScores(ScoreWriter& out) const override;
    void readScores(ScoreReader& in) override;
    void report(ResultReport& report) const override;
    const std::vector<std::uint64_t>& counts() const { return counts_; }

private:
    void add(const PlaneCrossing& crossing, const Point& origin, const Direction& direction, const Polarisation* light,
             const TallyContext& photon, double pathLength);

    PlaneFrame frame_;
    std::vector<std::uint64_t> counts_;
    std::vector<FixedPointSum> stokesQ_, stokesU_, stokesV_;
};

// A far-field camera: each escaping photon in the pixel that views the direction it came from (-d). Table
// "detector-NAME": ix, iy, theta_deg, azimuth_deg (of the pixel centre's viewing direction), fraction,
// radiance (fraction per steradian), [stokes_q, stokes_u, stokes_v,] cie_x, cie_y, cie_z (the CIE XYZ of the
// radiance: the sum of each photon's colour-matching values over emitted photons and the pixel's solid angle);
// image "detector-NAME" in true colour (docs/detectors.md, "Exposure").
class FarFieldTally final : public DetectorTally {
public:
    FarFieldTally(Detector detector, std::size_t index, bool stokes);
    std::unique_ptr<Tally> emptyCopy() const override;
    std::unique_ptr<Tally> clone() const override { return std::make_unique<FarFieldTally>(*this); }
    void score(const Event& event, const TallyContext& photon) override;
    void merge(const Tally& other) override;
    void writeScores(ScoreWriter& out) const override;
    void readScores(ScoreReader& in) override;
    void report(ResultReport& report) const override;
    const std::vector<std::uint64_t>& counts() const { return counts_; }
    const FarFieldCamera& camera() const { return camera_; }

private:
    FarFieldCamera camera_;
    std::vector<std::uint64_t> counts_;
    std::vector<FixedPointSum> stokesQ_, stokesU_, stokesV_;
    std::vector<FixedPointSum> cieX_, cieY_, cieZ_;
};

// The power absorbed in each shape. Table "detector-NAME": shape, name (empty for unnamed and generated
// shapes), medium, fraction (of the emitted power); light absorbed in the ambient medium is in no row (the
// summary's detectors.NAME.ambient).
class ShapeAbsorptionTally final : public DetectorTally {
public:
    ShapeAbsorptionTally(Detector detector, std::size_t index, std::vector<std::string> shapeNames,
                         std::vector<std::string> shapeMedia);
    std::unique_ptr<Tally> emptyCopy() const override;
    std::unique_ptr<Tally> clone() const override { return std::make_unique<ShapeAbsorptionTally>(*this); }
    void score(const Event& event, const TallyContext& photon) override;
    void merge(const Tally& other) override;
    void writeScores(ScoreWriter& out) const override;
    void readScores(ScoreReader& in) override;
    void report(ResultReport& report) const override;
    const std::vector<std::uint64_t>& absorbed() const { return absorbed_; }
    std::uint64_t ambient() const { return ambient_; }

private:
    std::vector<std::string> shapeNames_, shapeMedia_;
    std::vector<std::uint64_t> absorbed_;
    std::uint64_t ambient_ = 0;
};

}  // namespace dropscope
