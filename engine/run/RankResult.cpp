#include "run/RankResult.hpp"

#include <algorithm>

namespace dropscope {

namespace {

void writeVector(ScoreWriter& out, const Eigen::Vector3d& v) {
    for (int i = 0; i < 3; ++i) out.real(v[i]);
}

Eigen::Vector3d readVector(ScoreReader& in) {
    Eigen::Vector3d v;
    for (int i = 0; i < 3; ++i) v[i] = in.real();
    return v;
}

void writeEvent(ScoreWriter& out, const Event& event) {
    out.word(static_cast<std::uint64_t>(event.type));
    writeVector(out, event.position);
    writeVector(out, event.direction.vector());
    out.word(event.shape);
    out.word(event.from);
    out.word(event.to);
    out.real(event.reflectance);
    out.real(event.weight);
    out.word(static_cast<std::uint64_t>(event.lostReason));
    out.word(event.detector);
    out.word(event.polarisation ? 1 : 0);
    if (event.polarisation) {
        for (int i = 0; i < 4; ++i) out.real(event.polarisation->stokes[i]);
        writeVector(out, event.polarisation->reference);
    }
}

Event readEvent(ScoreReader& in) {
    Event event;
    event.type = static_cast<EventType>(in.word());
    event.position = readVector(in);
    event.direction = Direction::restored(readVector(in));
    event.shape = static_cast<ShapeId>(in.word());
    event.from = static_cast<MediumId>(in.word());
    event.to = static_cast<MediumId>(in.word());
    event.reflectance = in.real();
    event.weight = in.real();
    event.lostReason = static_cast<LostReason>(in.word());
    event.detector = static_cast<std::size_t>(in.word());
    if (in.word() != 0) {
        Polarisation polarisation;
        for (int i = 0; i < 4; ++i) polarisation.stokes[i] = in.real();
        polarisation.reference = readVector(in);
        event.polarisation = polarisation;
    }
    return event;
}

}  // namespace

std::vector<std::byte> packRankResult(const TraceResult& result) {
    std::vector<std::byte> bytes;
    ScoreWriter out(bytes);
    out.word(result.photons);
    result.tallies.writeScores(out);
    out.word(result.paths.size());
    for (const PhotonPath& path : result.paths) {
        out.word(path.photon);
        out.word(path.source);
        out.real(path.wavelengthNm);
        out.word(static_cast<std::uint64_t>(path.fate));
        out.word(path.events.size());
        for (const Event& event : path.events) writeEvent(out, event);
    }
    return bytes;
}

void mergeRankResult(TraceResult& into, std::span<const std::byte> bytes) {
    ScoreReader in(bytes);
    const std::uint64_t photons = in.word();
    TallySet tallies = into.tallies.emptyCopy();
    tallies.readScores(in);
    // The least a path and an event take: five words, and an event's fifteen.
    std::vector<PhotonPath> paths(in.count(5 * sizeof(std::uint64_t)));
    for (PhotonPath& path : paths) {
        path.photon = in.word();
        path.source = static_cast<std::size_t>(in.word());
        path.wavelengthNm = in.real();
        path.fate = static_cast<PhotonFate>(in.word());
        path.events.resize(in.count(15 * sizeof(std::uint64_t)));
        for (Event& event : path.events) event = readEvent(in);
    }
    if (!in.atEnd()) throw std::runtime_error("trace result: bytes left over (another run's result)");

    into.photons += photons;
    into.tallies.merge(tallies);
    into.paths.insert(into.paths.end(), std::make_move_iterator(paths.begin()), std::make_move_iterator(paths.end()));
    std::stable_sort(into.paths.begin(), into.paths.end(),
                     [](const PhotonPath& a, const PhotonPath& b) { return a.photon < b.photon; });
}

}  // namespace dropscope
