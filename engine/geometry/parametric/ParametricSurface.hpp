#pragma once

#include "geometry/GeneralShape.hpp"
#include "geometry/Vector.hpp"

#include <Eigen/Core>

#include <string_view>
#include <vector>

namespace dropscope {

// The box [u0, u1] x [v0, v1] a parametric surface is defined on.
struct ParameterDomain {
    double u0 = 0.0;
    double u1 = 1.0;
    double v0 = 0.0;
    double v1 = 1.0;
};

// r and its first partial derivatives at one (u, v).
struct SurfaceJet {
    Point r;
    Eigen::Vector3d ru;
    Eigen::Vector3d rv;
};

// Second partial derivatives of r at one (u, v): component k of ruu, ruv, rvv makes up the Hessian
// H_k = [[ruu_k, ruv_k], [ruv_k, rvv_k]] of coordinate k (seed 000 1.4: H_x, H_y, H_z).
struct SurfaceHessians {
    Eigen::Vector3d ruu;
    Eigen::Vector3d ruv;
    Eigen::Vector3d rvv;
};

// A closed base surface r(u, v) of class C^2 on a box domain (seed 000 1.4): what transformed
// parametric shapes M r(u, v) + r0 share. Derivatives are analytic where a preset overrides them,
// else central differences (parametric/ParametricSurface.cpp documents the steps).
class ParametricSurface {
public:
    virtual ~ParametricSurface() = default;

    virtual ParameterDomain domain() const = 0;
    virtual Point point(double u, double v) const = 0;
    virtual SurfaceJet jet(double u, double v) const;
    virtual SurfaceHessians hessians(double u, double v) const;

    // True when r(u0, v) = r(u1, v) for all v (the surface wraps around in u); likewise in v.
    // Root finders may then continue across that edge of the domain.
    virtual bool periodicInU() const { return false; }
    virtual bool periodicInV() const { return false; }

    // A length typical of the surface (its largest extent): the scale of its tolerances.
    virtual double characteristicLength() const = 0;

    // What a scene file names it and the parameters it was built from.
    virtual std::string_view presetName() const = 0;
    virtual std::vector<PresetParameter> presetParameters() const = 0;
};

}  // namespace dropscope
