// Traces a scene with the installed engine and prints the photon fates as `dropscope trace` counts them:
// consumer SCENE PHOTONS SEED prints "photons escaped absorbed lost unscattered".
#include "run/TraceRun.hpp"
#include "scene/SceneLoader.hpp"
#include "tally/FateTally.hpp"
#include "tally/StandardTallies.hpp"
#include "transport/OpticalScene.hpp"

#include <cstdio>
#include <cstdlib>
#include <exception>

int main(int argc, char** argv) {
    if (argc != 4) {
        std::fprintf(stderr, "usage: consumer SCENE PHOTONS SEED\n");
        return 2;
    }
    try {
        using namespace dropscope;
        const Scene scene = loadScene(argv[1]);
        TraceSettings settings;
        settings.photons = std::strtoull(argv[2], nullptr, 10);
        settings.seed = std::strtoull(argv[3], nullptr, 10);
        const OpticalScene optical(scene);
        const TraceResult result =
            runTrace(optical, scene.sources, settings, standardTallies(180, settings.transport.polarisation));
        const FateTally& fates = result.tallies.get<FateTally>();
        std::printf("%llu %llu %llu %llu %llu\n", static_cast<unsigned long long>(result.photons),
                    static_cast<unsigned long long>(fates.escaped()), static_cast<unsigned long long>(fates.absorbed()),
                    static_cast<unsigned long long>(fates.lost()),
                    static_cast<unsigned long long>(fates.unscattered()));
    } catch (const std::exception& error) {
        std::fprintf(stderr, "consumer: %s\n", error.what());
        return 1;
    }
    return 0;
}
