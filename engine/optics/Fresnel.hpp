#pragma once

namespace dropscope {

// Power reflectances at an interface from real index n1 into n2, for the cosine of the angle of
// incidence (0 < cosIncidence <= 1). Past the critical angle every polarisation reflects fully.
struct FresnelReflectance {
    double s;  // perpendicular (TE) polarisation
    double p;  // parallel (TM) polarisation
    double unpolarised() const { return 0.5 * (s + p); }
};

// The exact Fresnel equations for real indices (Born and Wolf, Principles of Optics, 1.5; docs/optics.md).
FresnelReflectance fresnelReflectance(double cosIncidence, double n1, double n2);

// Schlick's approximation R0 + (1 - R0)(1 - cos)^5, with the cosine taken on the optically thinner
// side, for comparison only.
double schlickReflectance(double cosIncidence, double n1, double n2);

}  // namespace dropscope
