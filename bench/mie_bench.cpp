// Time per sphere of the Lorenz-Mie engine (docs/performance.md, "Mie"): coefficients and efficiencies
// alone, and with the 180-bin angular integrals, at x = 100, 1000 and 10000 (water, m = 1.33 + 1e-8 i).
#include "wave/Mie.hpp"

#include <benchmark/benchmark.h>

namespace {

const std::complex<double> kWater{1.33, 1e-8};

void coefficientsAndEfficiencies(benchmark::State& state) {
    const auto x = static_cast<double>(state.range(0));
    for (auto _ : state) {
        const dropscope::MieEfficiencies q = dropscope::mieEfficiencies(dropscope::mieCoefficients(kWater, x));
        benchmark::DoNotOptimize(q);
    }
    state.counters["terms"] = static_cast<double>(dropscope::mieCoefficients(kWater, x).a.size());
}
BENCHMARK(coefficientsAndEfficiencies)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);

void withAngularBins(benchmark::State& state) {
    const auto x = static_cast<double>(state.range(0));
    for (auto _ : state) {
        const dropscope::MieResult result = dropscope::mieSphere(kWater, x, 180);
        benchmark::DoNotOptimize(result);
    }
}
BENCHMARK(withAngularBins)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
