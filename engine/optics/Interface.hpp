#pragma once

#include "geometry/Vector.hpp"

namespace dropscope {

// What a ray does at an interface between media of real indices n1 (incident side) and n2.
enum class InterfaceOutcome { Refracted, TotalInternalReflection, Tangent };

struct Refraction {
    InterfaceOutcome outcome;
    Direction transmitted;  // valid only when outcome == Refracted
};

// Seed 000 eq. 4.7 (Snell's law in vector form): with c = (n1/n2)(i x n),
//   t = |c| (n x c^) + sgn(i.n) sqrt(1 - |c|^2) n,
// where n is the outward normal and i the incident direction. |c| > 1 is total internal reflection;
// i.n = 0 is a tangent ray, which neither enters nor leaves (seed 000 chapter 4).
Refraction refract(const Direction& incident, const Direction& outwardNormal, double n1, double n2);

// Mirror reflection R = V - 2 (V.N) N (seed 003 2.2.3); N may face either way.
Direction reflect(const Direction& incident, const Direction& normal);

}  // namespace dropscope
