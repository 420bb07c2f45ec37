#include "cli/TraceFiles.hpp"

#include "cli/AtomicFile.hpp"

#include <nlohmann/json.hpp>

#include <charconv>
#include <cmath>
#include <numbers>
#include <ostream>

namespace dropscope {

namespace {

using Json = nlohmann::ordered_json;

// Shortest text that reads back as the same double ("nan" for NaN).
std::string shortest(double value) {
    char text[32];
    const auto end = std::to_chars(text, text + sizeof text, value).ptr;
    return {text, end};
}

// A share of the photons traced; NaN (written as null or nan) when none was traced.
double share(std::uint64_t count, std::uint64_t photons) {
    return photons > 0 ? static_cast<double>(count) / static_cast<double>(photons) : std::nan("");
}

double radians(double degrees) { return degrees * (std::numbers::pi / 180.0); }

Json finiteOrNull(double value) { return std::isfinite(value) ? Json(value) : Json(nullptr); }

Json vectorJson(const Eigen::Vector3d& v) {
    return Json::array({finiteOrNull(v.x()), finiteOrNull(v.y()), finiteOrNull(v.z())});
}

Json eventJson(const Event& event, const std::vector<Medium>& media) {
    Json json = {{"type", eventTypeName(event.type)},
                 {"position", vectorJson(event.position)},
                 {"direction", vectorJson(event.direction)},
                 {"shape", event.shape == RayHit::kNone ? Json(nullptr) : Json(event.shape)},
                 {"medium_from", media.at(event.from).name},
                 {"medium_to", media.at(event.to).name},
                 {"R", finiteOrNull(event.reflectance)},
                 {"weight", finiteOrNull(event.weight)}};
    if (event.type == EventType::Lost) json["reason"] = lostReasonName(event.lostReason);
    return json;
}

}  // namespace

std::string_view fresnelModelName(FresnelModel model) { return model == FresnelModel::Schlick ? "schlick" : "exact"; }

void writeTraceSummary(const TraceResult& result, const TraceRunInfo& info, std::ostream& out) {
    const TraceTally& tally = result.tally;
    const std::uint64_t photons = tally.photons;
    Json lostReasons = Json::object();
    for (std::size_t reason = 0; reason < kLostReasonCount; ++reason) {
        lostReasons[std::string(lostReasonName(static_cast<LostReason>(reason)))] = tally.lostReasons[reason];
    }
    const Json summary = {{"photons", photons},
                          {"seed", info.settings.seed},
                          {"threads", result.threads},
                          {"seconds", result.seconds},
                          {"fractions",
                           {{"escaped", finiteOrNull(share(tally.escaped, photons))},
                            {"absorbed", finiteOrNull(share(tally.absorbed, photons))},
                            {"lost", finiteOrNull(share(tally.lost, photons))},
                            {"unscattered", finiteOrNull(share(tally.unscattered, photons))}}},
                          {"events",
                           {{"reflect", tally.events.reflect},
                            {"refract", tally.events.refract},
                            {"tir", tally.events.tir},
                            {"absorb", tally.events.absorb}}},
                          {"photons_requested", result.requested},
                          {"partial", result.partial},
                          {"scene", info.scenePath},
                          {"bins", tally.angular.size()},
                          {"fresnel", fresnelModelName(info.settings.transport.fresnel)},
                          {"max_events", info.settings.transport.maxEvents},
                          {"paths", result.paths.size()},
                          {"counts",
                           {{"escaped", tally.escaped},
                            {"absorbed", tally.absorbed},
                            {"lost", tally.lost},
                            {"unscattered", tally.unscattered}}},
                          {"lost_reasons", lostReasons},
                          {"sources", info.sourceCount}};
    // The scene path comes from argv and need not be UTF-8: replace what is not, rather than throw.
    out << summary.dump(2, ' ', false, Json::error_handler_t::replace) << '\n';
}

void writeAngularCsv(const TraceTally& tally, std::ostream& out) {
    out << "theta_lo_deg,theta_hi_deg,fraction,fraction_per_sr\n";
    const std::size_t bins = tally.angular.size();
    for (std::size_t bin = 0; bin < bins; ++bin) {
        // 180 * bin / bins: the edge correctly rounded, so whole degrees come out whole
        const double lo = 180.0 * static_cast<double>(bin) / static_cast<double>(bins);
        const double hi = 180.0 * static_cast<double>(bin + 1) / static_cast<double>(bins);
        const double fraction = share(tally.angular[bin], tally.photons);
        const double solidAngle = 2.0 * std::numbers::pi * (std::cos(radians(lo)) - std::cos(radians(hi)));
        out << shortest(lo) << ',' << shortest(hi) << ',' << shortest(fraction) << ','
            << shortest(fraction / solidAngle) << '\n';
    }
}

void writePathsJsonl(const std::vector<PhotonPath>& paths, const std::vector<Medium>& media, std::ostream& out) {
    for (const PhotonPath& path : paths) {
        Json events = Json::array();
        for (const Event& event : path.events) events.push_back(eventJson(event, media));
        const Json line = {
            {"photon", path.photon}, {"source", path.source}, {"fate", photonFateName(path.fate)}, {"events", events}};
        out << line.dump() << '\n';
    }
}

void writeTraceFiles(const std::filesystem::path& directory, const TraceResult& result, const TraceRunInfo& info,
                     const std::vector<Medium>& media) {
    // All three or none, so a failed run never leaves new files beside old ones.
    writeFilesAtomically({
        {directory / "angular.csv", [&](std::ostream& out) { writeAngularCsv(result.tally, out); }},
        {directory / "paths.jsonl", [&](std::ostream& out) { writePathsJsonl(result.paths, media, out); }},
        {directory / "summary.json", [&](std::ostream& out) { writeTraceSummary(result, info, out); }},
    });
}

}  // namespace dropscope
