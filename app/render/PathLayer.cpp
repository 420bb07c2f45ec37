#include "render/PathLayer.hpp"

#include "render/Colour.hpp"
#include "spectrum/Colour.hpp"

namespace dropscope::render {

namespace {

// Paths traced without polarisation have no degree of polarisation to show.
constexpr Colour kNoPolarisationColour{0.55f, 0.55f, 0.55f};

Colour wavelengthColour(double wavelengthNm) {
    // Line colours reach the image as they are (the renderer applies no transfer curve): sRGB-encoded.
    const Rgb rgb = displayColourOfWavelength(wavelengthNm);
    return {static_cast<float>(rgb[0]), static_cast<float>(rgb[1]), static_cast<float>(rgb[2]), 1.0f};
}

Colour segmentColour(const Event& start, PathColouring colouring) {
    switch (colouring) {
    case PathColouring::Wavelength: break;  // one colour per path (addPhotonPaths)
    case PathColouring::Weight: return viridis(start.weight);
    case PathColouring::Event: return eventColour(start.type);
    case PathColouring::Dolp:
        return start.polarisation ? viridis(degreeOfLinearPolarisation(start.polarisation->stokes))
                                  : kNoPolarisationColour;
    }
    return eventColour(start.type);
}

}  // namespace

void addPhotonPaths(LineBatch& lines, const std::vector<PhotonPath>& paths, double escapeLength,
                    PathColouring colouring, const ChordSplit* chords) {
    for (const PhotonPath& path : paths) {
        if (path.events.empty()) continue;
        const bool byWavelength = colouring == PathColouring::Wavelength;
        const Colour pathColour = byWavelength ? wavelengthColour(path.wavelengthNm) : Colour{};
        const auto colourFrom = [&](const Event& start) {
            return byWavelength ? pathColour : segmentColour(start, colouring);
        };
        for (std::size_t k = 0; k + 1 < path.events.size(); ++k) {
            const Event& from = path.events[k];
            const Event& to = path.events[k + 1];
            LineBatch& into = chords && isChord(from, to, chords->octree, chords->slotOfShape) ? chords->batch : lines;
            into.add(from.position, to.position, colourFrom(from));
        }
        const Event& last = path.events.back();
        if (last.type == EventType::Escape) {
            const Point end = last.position + escapeLength * last.direction.vector();
            lines.add(last.position, end, colourFrom(last));
        }
    }
}

void addEventMarkers(std::vector<ShapeInstance>& markers, const std::vector<PhotonPath>& paths, double radius,
                     const Anchor& anchor) {
    for (const PhotonPath& path : paths) {
        for (const Event& event : path.events) {
            markers.push_back(sphereInstance(event.position, radius, anchor, eventColour(event.type)));
        }
    }
}

void addEventMarkers(std::vector<ShapeInstance>& markers, const RayTree& tree, double radius, const Anchor& anchor) {
    for (const RayTreeNode& node : tree.nodes) {
        markers.push_back(sphereInstance(node.event.position, radius, anchor, eventColour(node.event.type)));
    }
}

}  // namespace dropscope::render
