#pragma once

// Every layer the renderer draws besides the shapes, and the one function that builds them all from a
// LayerOptions (docs/rendering.md).
#include "render/DetectorGlyphs.hpp"
#include "render/Guides.hpp"
#include "render/OctreeLayer.hpp"
#include "render/PathLayer.hpp"
#include "render/PolarisationEllipse.hpp"
#include "render/RayTreeLayer.hpp"
#include "render/SceneLayers.hpp"
#include "render/SourceGlyphs.hpp"
