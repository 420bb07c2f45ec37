#pragma once

// Helpers shared by the ParametricSurface tests (presets, Bezier).
#include "geometry/parametric/ParametricSurface.hpp"

#include <string_view>
#include <vector>

namespace dropscope::testing {

// The same surface with ParametricSurface's numeric jet and hessians instead of the analytic ones.
class NumericDerivatives final : public ParametricSurface {
public:
    explicit NumericDerivatives(const ParametricSurface& s) : s_(s) {}
    ParameterDomain domain() const override { return s_.domain(); }
    Point point(double u, double v) const override { return s_.point(u, v); }
    bool periodicInU() const override { return s_.periodicInU(); }
    bool periodicInV() const override { return s_.periodicInV(); }
    double characteristicLength() const override { return s_.characteristicLength(); }
    std::string_view presetName() const override { return s_.presetName(); }
    std::vector<PresetParameter> presetParameters() const override { return s_.presetParameters(); }

private:
    const ParametricSurface& s_;
};

}  // namespace dropscope::testing
