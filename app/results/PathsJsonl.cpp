#include "results/PathsJsonl.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <ostream>

namespace dropscope {

namespace {

using Json = nlohmann::ordered_json;

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
    if (event.type == EventType::Detect) json["detector"] = event.detector;
    if (event.polarisation) {
        const StokesVector& s = event.polarisation->stokes;
        json["stokes"] = Json::array({finiteOrNull(s[0]), finiteOrNull(s[1]), finiteOrNull(s[2]), finiteOrNull(s[3])});
        json["stokes_reference"] = vectorJson(event.polarisation->reference);
    }
    return json;
}

}  // namespace

void writePathsJsonl(const std::vector<PhotonPath>& paths, const std::vector<Medium>& media, std::ostream& out) {
    for (const PhotonPath& path : paths) {
        Json events = Json::array();
        for (const Event& event : path.events) events.push_back(eventJson(event, media));
        const Json line = {{"photon", path.photon},
                           {"source", path.source},
                           {"wavelength_nm", path.wavelengthNm},
                           {"fate", photonFateName(path.fate)},
                           {"events", events}};
        out << line.dump() << '\n';
    }
}

}  // namespace dropscope
