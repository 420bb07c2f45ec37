#include "tally/DetectorTallies.hpp"

#include "spectrum/Colour.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <tuple>

namespace dropscope {

namespace {

constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;

bool before(const DetectorHit& a, const DetectorHit& b) {
    return std::tie(a.photon, a.sequence) < std::tie(b.photon, b.sequence);
}

// A detector's parallel axis closer than this sine to the light's direction is too short to fix a frame once
// made perpendicular to it (its direction would be mostly rounding): the other axis of the detector is used.
constexpr double kParallelAxisSine = 1e-6;

// The light's Stokes vector with parallel axis `axis` (made perpendicular to the direction), or with
// `fallback` when the direction is (nearly) along `axis`; unpolarised light of unit power without polarisation.
StokesVector stokesAlong(const Polarisation* light, const Direction& direction, const Eigen::Vector3d& axis,
                         const Eigen::Vector3d& fallback) {
    if (!light) return unpolarisedStokes();
    Eigen::Vector3d reference = axis - axis.dot(direction.vector()) * direction.vector();
    if (reference.norm() < kParallelAxisSine)
        reference = fallback - fallback.dot(direction.vector()) * direction.vector();
    return stokesInFrame(*light, direction, reference.normalized());
}

std::vector<FixedPointSum> sums(bool wanted, std::size_t count) {
    return wanted ? std::vector<FixedPointSum>(count) : std::vector<FixedPointSum>{};
}

void addAll(std::vector<FixedPointSum>& into, const std::vector<FixedPointSum>& from) {
    for (std::size_t i = 0; i < into.size(); ++i) into[i] += from[i];
}

void addAll(std::vector<std::uint64_t>& into, const std::vector<std::uint64_t>& from) {
    for (std::size_t i = 0; i < into.size(); ++i) into[i] += from[i];
}

// The pixel columns every image table starts with.
void addPixelIndices(ResultTable& table, const PixelGrid& grid) {
    std::vector<std::uint64_t> ix, iy;
    for (int y = 0; y < grid.ny; ++y) {
        for (int x = 0; x < grid.nx; ++x) {
            ix.push_back(static_cast<std::uint64_t>(x));
            iy.push_back(static_cast<std::uint64_t>(y));
        }
    }
    table.columns.push_back({"ix", std::move(ix)});
    table.columns.push_back({"iy", std::move(iy)});
    table.grid = {static_cast<std::size_t>(grid.ny), static_cast<std::size_t>(grid.nx)};
}

}  // namespace

bool HitRecords::wants(std::uint64_t photon) const {
    return hits_.size() < capacity_ || (!hits_.empty() && photon <= hits_.back().photon);
}

void HitRecords::offer(const DetectorHit& hit) {
    if (capacity_ == 0) return;
    if (hits_.size() == capacity_ && !before(hit, hits_.back())) return;
    hits_.insert(std::upper_bound(hits_.begin(), hits_.end(), hit, before), hit);
    if (hits_.size() > capacity_) hits_.pop_back();
}

void HitRecords::merge(const HitRecords& other) {
    std::vector<DetectorHit> merged;
    std::merge(hits_.begin(), hits_.end(), other.hits_.begin(), other.hits_.end(), std::back_inserter(merged), before);
    if (merged.size() > capacity_) merged.resize(capacity_);
    hits_ = std::move(merged);
}

void HitRecords::writeScores(ScoreWriter& out) const {
    out.word(hits_.size());
    for (const DetectorHit& hit : hits_) {
        out.word(hit.photon);
        out.word(hit.sequence);
        for (int i = 0; i < 3; ++i) out.real(hit.position[i]);
        for (int i = 0; i < 3; ++i) out.real(hit.direction[i]);
        out.real(hit.weight);
        out.real(hit.wavelengthNm);
        for (int i = 0; i < 4; ++i) out.real(hit.stokes[i]);
        out.word(hit.events);
        out.real(hit.pathLength);
    }
}

void HitRecords::readScores(ScoreReader& in) {
    const std::uint64_t count = in.count(16 * sizeof(std::uint64_t));  // a hit is 16 numbers
    if (count > capacity_) throw std::runtime_error("tally scores: more detector records than the detector keeps");
    hits_.assign(count, DetectorHit{});
    for (DetectorHit& hit : hits_) {
        hit.photon = in.word();
        hit.sequence = in.word();
        for (int i = 0; i < 3; ++i) hit.position[i] = in.real();
        for (int i = 0; i < 3; ++i) hit.direction[i] = in.real();
        hit.weight = in.real();
        hit.wavelengthNm = in.real();
        for (int i = 0; i < 4; ++i) hit.stokes[i] = in.real();
        hit.events = in.word();
        hit.pathLength = in.real();
    }
}

ResultTable HitRecords::table(const std::string& name, bool stokes) const {
    std::vector<std::uint64_t> photon, events;
    std::vector<double> x, y, z, dx, dy, dz, weight, wavelength, pathLength;
    std::vector<double> s[4];
    for (const DetectorHit& hit : hits_) {
        photon.push_back(hit.photon);
        x.push_back(hit.position.x());
        y.push_back(hit.position.y());
        z.push_back(hit.position.z());
        dx.push_back(hit.direction.x());
        dy.push_back(hit.direction.y());
        dz.push_back(hit.direction.z());
        weight.push_back(hit.weight);
        wavelength.push_back(hit.wavelengthNm);
        for (Eigen::Index k = 0; k < 4; ++k) s[k].push_back(hit.stokes[k]);
        events.push_back(hit.events);
        pathLength.push_back(hit.pathLength);
    }
    ResultTable table{name, {}};
    table.columns.push_back({"photon", std::move(photon)});
    table.columns.push_back({"x", std::move(x), "scene unit"});
    table.columns.push_back({"y", std::move(y), "scene unit"});
    table.columns.push_back({"z", std::move(z), "scene unit"});
    table.columns.push_back({"dx", std::move(dx)});
    table.columns.push_back({"dy", std::move(dy)});
    table.columns.push_back({"dz", std::move(dz)});
    table.columns.push_back({"weight", std::move(weight)});
    table.columns.push_back({"wavelength_nm", std::move(wavelength), "nm"});
    if (stokes) {
        table.columns.push_back({"stokes_i", std::move(s[0])});
        table.columns.push_back({"stokes_q", std::move(s[1])});
        table.columns.push_back({"stokes_u", std::move(s[2])});
        table.columns.push_back({"stokes_v", std::move(s[3])});
    }
    table.columns.push_back({"events", std::move(events)});
    table.columns.push_back({"path_length", std::move(pathLength), "scene unit"});
    return table;
}

std::string detectorTableName(const Detector& detector) { return "detector-" + detector.name; }

DetectorTally::DetectorTally(Detector detector, std::size_t index, bool stokes)
    : detector_(std::move(detector)),
      index_(index),
      stokes_(stokes),
      tableName_(detectorTableName(detector_)),
      records_(detector_.record) {
    checkDetector(detector_);
}

void DetectorTally::startPhoton(const Event& event, const TallyContext&) {
    if (event.type != EventType::Emit) return;
    ++photons_;
    sequence_ = 0;
}

void DetectorTally::countHit(const TallyContext& photon, const Point& position, const Eigen::Vector3d& direction,
                             const StokesVector& stokes, double pathLength) {
    ++hits_;
    const std::uint64_t sequence = sequence_++;
    if (!records_.wants(photon.photon)) return;
    records_.offer({photon.photon, sequence, position, direction, 1.0, photon.state.wavelengthNm, stokes,
                    photon.state.interfaceEvents, pathLength});
}

void DetectorTally::mergeCommon(const DetectorTally& other) {
    if (other.detector_.name != detector_.name || other.stokes_ != stokes_) {
        throw std::logic_error("merging tallies of different detectors");
    }
    photons_ += other.photons_;
    hits_ += other.hits_;
    records_.merge(other.records_);
}

void DetectorTally::writeCommonScores(ScoreWriter& out) const {
    out.word(photons_);
    out.word(hits_);
    records_.writeScores(out);
}

void DetectorTally::readCommonScores(ScoreReader& in) {
    photons_ = in.word();
    hits_ = in.word();
    records_.readScores(in);
}

double DetectorTally::share(double count) const {
    return photons_ > 0 ? count / static_cast<double>(photons_) : std::nan("");
}

void DetectorTally::reportCommon(ResultReport& report) const {
    const std::string& name = detector_.name;
    report.set({"detectors", name, "type"}, std::string(detectorTypeName(detector_.type)));
    report.set({"detectors", name, "hits"}, hits_);
    report.set({"detectors", name, "fraction"}, share(static_cast<double>(hits_)));
    if (records_.capacity() > 0) {
        report.set({"detectors", name, "records"}, static_cast<std::uint64_t>(records_.hits().size()));
        // Absorbed light has no frame of its own to state a Stokes vector in: no Stokes columns for it.
        const bool stokesColumns = stokes_ && detector_.type != DetectorType::ShapeAbsorption;
        report.addTable(records_.table(tableName_ + "-records", stokesColumns));
    }
}

// --- plane

PlaneDetectorTally::PlaneDetectorTally(Detector detector, std::size_t index, bool stokes)
    : DetectorTally(std::move(detector), index, stokes),
      frame_(planeFrame(this->detector())),
      counts_(this->detector().pixels.count(), 0),
      stokesQ_(sums(stokes, counts_.size())),
      stokesU_(sums(stokes, counts_.size())),
      stokesV_(sums(stokes, counts_.size())) {
    if (this->detector().type != DetectorType::Plane) throw std::invalid_argument("not a plane detector");
}

std::unique_ptr<Tally> PlaneDetectorTally::emptyCopy() const {
    return std::make_unique<PlaneDetectorTally>(detector(), index(), stokes());
}

void PlaneDetectorTally::add(const PlaneCrossing& crossing, const Point& origin, const Direction& direction,
                             const Polarisation* light, const TallyContext& photon, double pathLength) {
    if (stokes() && !light) throw std::logic_error("a Stokes detector tally was given an unpolarised photon");
    ++counts_[crossing.pixel];
    const StokesVector s = stokesAlong(light, direction, frame_.u, frame_.v);
    if (stokes()) {
        stokesQ_[crossing.pixel].add(s[1]);
        stokesU_[crossing.pixel].add(s[2]);
        stokesV_[crossing.pixel].add(s[3]);
    }
    countHit(photon, origin + crossing.distance * direction.vector(), direction.vector(), s,
             pathLength + crossing.distance);
}

void PlaneDetectorTally::score(const Event& event, const TallyContext& photon) {
    startPhoton(event, photon);
    if (event.type != EventType::Detect || event.detector != index()) return;
    // The photon ended on this (absorbing) plane: the crossing is where it stopped.
    const Eigen::Vector3d offset = event.position - detector().center;
    PlaneCrossing crossing{0.0, offset.dot(frame_.u), offset.dot(frame_.v), 0};
    crossing.pixel = planePixel(detector(), crossing.u, crossing.v);
    const Polarisation* light = event.polarisation ? &*event.polarisation : nullptr;
    add(crossing, event.position, event.direction, light, photon, photon.state.pathLength);
}

void PlaneDetectorTally::scoreFlight(const Flight& flight, const TallyContext& photon) {
    const auto crossing = crossPlane(detector(), frame_, flight.origin, flight.direction, flight.length);
    if (crossing) add(*crossing, flight.origin, flight.direction, flight.polarisation, photon, photon.state.pathLength);
}

void PlaneDetectorTally::merge(const Tally& other) {
    const PlaneDetectorTally& more = sameTally(*this, other);
    mergeCommon(more);
    addAll(counts_, more.counts_);
    addAll(stokesQ_, more.stokesQ_);
    addAll(stokesU_, more.stokesU_);
    addAll(stokesV_, more.stokesV_);
}

void PlaneDetectorTally::writeScores(ScoreWriter& out) const {
    writeCommonScores(out);
    out.words(counts_);
    for (const auto* column : {&stokesQ_, &stokesU_, &stokesV_}) out.sums(*column);
}

void PlaneDetectorTally::readScores(ScoreReader& in) {
    readCommonScores(in);
    in.words(counts_);
    for (auto* column : {&stokesQ_, &stokesU_, &stokesV_}) in.sums(*column);
}

void PlaneDetectorTally::report(ResultReport& report) const {
    reportCommon(report);
    const Detector& plane = detector();
    ResultTable table{std::string(name()), {}};
    addPixelIndices(table, plane.pixels);
    std::vector<double> u, v, fraction, irradiance, q, uu, vv;
    const double area = planePixelArea(plane);
    for (int iy = 0; iy < plane.pixels.ny; ++iy) {
        for (int ix = 0; ix < plane.pixels.nx; ++ix) {
            const std::size_t pixel = plane.pixels.index(ix, iy);
            const auto centre = planePixelCentre(plane, ix, iy);
            u.push_back(centre[0]);
            v.push_back(centre[1]);
            const double f = share(static_cast<double>(counts_[pixel]));
            fraction.push_back(f);
            irradiance.push_back(f / area);
            if (!stokes()) continue;
            q.push_back(share(stokesQ_[pixel].value()));
            uu.push_back(share(stokesU_[pixel].value()));
            vv.push_back(share(stokesV_[pixel].value()));
        }
    }
    table.columns.push_back({"u", std::move(u), "scene unit"});
    table.columns.push_back({"v", std::move(v), "scene unit"});
    table.columns.push_back({"fraction", std::move(fraction)});
    table.columns.push_back({"irradiance", std::move(irradiance), "1/scene unit^2"});
    if (stokes()) {
        table.columns.push_back({"stokes_q", std::move(q)});
        table.columns.push_back({"stokes_u", std::move(uu)});
        table.columns.push_back({"stokes_v", std::move(vv)});
    }
    report.addTable(std::move(table));
}

// --- far field

FarFieldTally::FarFieldTally(Detector detector, std::size_t index, bool stokes)
    : DetectorTally(std::move(detector), index, stokes),
      camera_(this->detector()),
      counts_(this->detector().pixels.count(), 0),
      stokesQ_(sums(stokes, counts_.size())),
      stokesU_(sums(stokes, counts_.size())),
      stokesV_(sums(stokes, counts_.size())),
      cieX_(counts_.size()),
      cieY_(counts_.size()),
      cieZ_(counts_.size()) {
    if (this->detector().type != DetectorType::FarField) throw std::invalid_argument("not a far-field detector");
}

std::unique_ptr<Tally> FarFieldTally::emptyCopy() const {
    return std::make_unique<FarFieldTally>(detector(), index(), stokes());
}

void FarFieldTally::score(const Event& event, const TallyContext& photon) {
    startPhoton(event, photon);
    if (event.type != EventType::Escape) return;
    const auto pixel = camera_.pixelOf(-event.direction.vector());
    if (!pixel) return;
    if (stokes() && !event.polarisation)
        throw std::logic_error("a Stokes detector tally was given an unpolarised photon");
    ++counts_[*pixel];
    const Polarisation* light = event.polarisation ? &*event.polarisation : nullptr;
    const StokesVector s = stokesAlong(light, event.direction, camera_.right(), camera_.upAxis());
    if (stokes()) {
        stokesQ_[*pixel].add(s[1]);
        stokesU_[*pixel].add(s[2]);
        stokesV_[*pixel].add(s[3]);
    }
    const Xyz colour = cieColourMatching(photon.state.wavelengthNm);
    cieX_[*pixel].add(colour.x);
    cieY_[*pixel].add(colour.y);
    cieZ_[*pixel].add(colour.z);
    countHit(photon, event.position, event.direction.vector(), s, photon.state.pathLength);
}

void FarFieldTally::merge(const Tally& other) {
    const FarFieldTally& more = sameTally(*this, other);
    mergeCommon(more);
    addAll(counts_, more.counts_);
    addAll(stokesQ_, more.stokesQ_);
    addAll(stokesU_, more.stokesU_);
    addAll(stokesV_, more.stokesV_);
    addAll(cieX_, more.cieX_);
    addAll(cieY_, more.cieY_);
    addAll(cieZ_, more.cieZ_);
}

void FarFieldTally::writeScores(ScoreWriter& out) const {
    writeCommonScores(out);
    out.words(counts_);
    for (const auto* column : {&stokesQ_, &stokesU_, &stokesV_, &cieX_, &cieY_, &cieZ_}) out.sums(*column);
}

void FarFieldTally::readScores(ScoreReader& in) {
    readCommonScores(in);
    in.words(counts_);
    for (auto* column : {&stokesQ_, &stokesU_, &stokesV_, &cieX_, &cieY_, &cieZ_}) in.sums(*column);
}

void FarFieldTally::report(ResultReport& report) const {
    reportCommon(report);
    const PixelGrid& grid = detector().pixels;
    ResultTable table{std::string(name()), {}};
    addPixelIndices(table, grid);
    std::vector<double> theta, azimuth, fraction, radiance, q, u, v, x, y, z;
    for (int iy = 0; iy < grid.ny; ++iy) {
        for (int ix = 0; ix < grid.nx; ++ix) {
            const std::size_t pixel = grid.index(ix, iy);
            const auto viewing = camera_.viewingDirection(ix, iy);
            const double solidAngle = camera_.pixelSolidAngle(ix, iy);
            if (viewing) {
                theta.push_back(std::acos(std::clamp(viewing->dot(camera_.look()), -1.0, 1.0)) * kDegreesPerRadian);
                double phi = std::atan2(viewing->dot(camera_.upAxis()), viewing->dot(camera_.right()));
                if (phi < 0.0) phi += 2.0 * std::numbers::pi;
                azimuth.push_back(phi * kDegreesPerRadian);
            } else {
                theta.push_back(std::nan(""));
                azimuth.push_back(std::nan(""));
            }
            const double f = share(static_cast<double>(counts_[pixel]));
            fraction.push_back(f);
            // A pixel beyond the projection's domain sees nothing: no radiance there (NaN, empty in the image).
            const double perSr = solidAngle > 0.0 ? 1.0 / solidAngle : std::nan("");
            radiance.push_back(f * perSr);
            x.push_back(share(cieX_[pixel].value()) * perSr);
            y.push_back(share(cieY_[pixel].value()) * perSr);
            z.push_back(share(cieZ_[pixel].value()) * perSr);
            if (!stokes()) continue;
            q.push_back(share(stokesQ_[pixel].value()));
            u.push_back(share(stokesU_[pixel].value()));
            v.push_back(share(stokesV_[pixel].value()));
        }
    }
    // Exposure: the 99th percentile of the lit pixels' luminance Y is white (docs/detectors.md, "Exposure").
    std::vector<double> lit;
    for (std::size_t pixel = 0; pixel < counts_.size(); ++pixel) {
        if (counts_[pixel] > 0 && std::isfinite(y[pixel]) && y[pixel] > 0.0) lit.push_back(y[pixel]);
    }
    double exposure = 0.0;
    if (!lit.empty()) {
        const auto rank = static_cast<std::size_t>(0.99 * static_cast<double>(lit.size() - 1));
        std::nth_element(lit.begin(), lit.begin() + static_cast<std::ptrdiff_t>(rank), lit.end());
        exposure = 1.0 / lit[rank];
    }
    ResultImage image{std::string(name()), grid.nx, grid.ny, {}};
    image.rgb.reserve(3 * grid.count());
    for (int iy = grid.ny - 1; iy >= 0; --iy) {
        for (int ix = 0; ix < grid.nx; ++ix) {
            const std::size_t pixel = grid.index(ix, iy);
            const bool seen = std::isfinite(x[pixel]);
            const Rgb rgb = seen ? exposedSrgb({x[pixel], y[pixel], z[pixel]}, exposure) : Rgb{0.0, 0.0, 0.0};
            for (double c : rgb) image.rgb.push_back(static_cast<std::uint8_t>(std::lround(255.0 * c)));
        }
    }
    report.set({"detectors", detector().name, "exposure"}, exposure);
    table.columns.push_back({"theta_deg", std::move(theta), "deg"});
    table.columns.push_back({"azimuth_deg", std::move(azimuth), "deg"});
    table.columns.push_back({"fraction", std::move(fraction)});
    table.columns.push_back({"radiance", std::move(radiance), "1/sr"});
    if (stokes()) {
        table.columns.push_back({"stokes_q", std::move(q)});
        table.columns.push_back({"stokes_u", std::move(u)});
        table.columns.push_back({"stokes_v", std::move(v)});
    }
    table.columns.push_back({"cie_x", std::move(x), "1/sr"});
    table.columns.push_back({"cie_y", std::move(y), "1/sr"});
    table.columns.push_back({"cie_z", std::move(z), "1/sr"});
    report.addTable(std::move(table));
    report.addImage(std::move(image));
}

// --- shape absorption

ShapeAbsorptionTally::ShapeAbsorptionTally(Detector detector, std::size_t index, std::vector<std::string> shapeNames,
                                           std::vector<std::string> shapeMedia)
    : DetectorTally(std::move(detector), index, false),
      shapeNames_(std::move(shapeNames)),
      shapeMedia_(std::move(shapeMedia)),
      absorbed_(shapeNames_.size(), 0) {
    if (this->detector().type != DetectorType::ShapeAbsorption) {
        throw std::invalid_argument("not a shape absorption detector");
    }
    if (shapeMedia_.size() != shapeNames_.size()) throw std::invalid_argument("one medium name per shape");
}

std::unique_ptr<Tally> ShapeAbsorptionTally::emptyCopy() const {
    return std::make_unique<ShapeAbsorptionTally>(detector(), index(), shapeNames_, shapeMedia_);
}

void ShapeAbsorptionTally::score(const Event& event, const TallyContext& photon) {
    startPhoton(event, photon);
    if (event.type != EventType::Absorb) return;
    const ShapeId region = photon.state.region;
    if (region == RayHit::kNone) {
        ++ambient_;
        return;
    }
    if (region >= absorbed_.size()) throw std::logic_error("absorbed in a shape the tally does not know");
    ++absorbed_[region];
    countHit(photon, event.position, event.direction.vector(), unpolarisedStokes(), photon.state.pathLength);
}

void ShapeAbsorptionTally::merge(const Tally& other) {
    const ShapeAbsorptionTally& more = sameTally(*this, other);
    if (more.absorbed_.size() != absorbed_.size()) throw std::logic_error("merging absorption of different scenes");
    mergeCommon(more);
    addAll(absorbed_, more.absorbed_);
    ambient_ += more.ambient_;
}

void ShapeAbsorptionTally::writeScores(ScoreWriter& out) const {
    writeCommonScores(out);
    out.words(absorbed_);
    out.word(ambient_);
}

void ShapeAbsorptionTally::readScores(ScoreReader& in) {
    readCommonScores(in);
    in.words(absorbed_);
    ambient_ = in.word();
}

void ShapeAbsorptionTally::report(ResultReport& report) const {
    reportCommon(report);
    report.set({"detectors", detector().name, "ambient"}, share(static_cast<double>(ambient_)));
    std::vector<std::uint64_t> shape;
    std::vector<double> fraction;
    for (std::size_t id = 0; id < absorbed_.size(); ++id) {
        shape.push_back(id);
        fraction.push_back(share(static_cast<double>(absorbed_[id])));
    }
    ResultTable table{std::string(name()), {}};
    table.columns.push_back({"shape", std::move(shape)});
    table.columns.push_back({"name", shapeNames_});
    table.columns.push_back({"medium", shapeMedia_});
    table.columns.push_back({"fraction", std::move(fraction)});
    report.addTable(std::move(table));
}

}  // namespace dropscope
