// Real cables across the depth -> per-unit-depth cable of the 2D model (DESIGN.md, "2D bookkeeping").
#include "halfeti/cable/cable_set.hpp"

#include <sstream>

#include "halfeti/core/error.hpp"

namespace halfeti::cable {

PerDepthCable per_unit_depth(const CableSet& set) {
  if (set.count < 1) HALFETI_USER_ERROR("cable count must be at least 1, got " << set.count);
  if (!(set.area > 0.0)) HALFETI_USER_ERROR("cable area must be positive, got " << set.area << " m^2");
  if (!(set.modulus > 0.0))
    HALFETI_USER_ERROR("cable modulus must be positive, got " << set.modulus << " Pa");
  if (!(set.density >= 0.0))
    HALFETI_USER_ERROR("cable density must be >= 0, got " << set.density << " kg/m^3");
  if (!(set.depth > 0.0)) HALFETI_USER_ERROR("cable depth must be positive, got " << set.depth << " m");
  if (!(set.fluid_density >= 0.0))
    HALFETI_USER_ERROR("fluid density must be >= 0, got " << set.fluid_density << " kg/m^3");
  PerDepthCable c;
  const double per_depth = set.count / set.depth;
  c.area = per_depth * set.area;
  c.axial_stiffness = per_depth * set.modulus * set.area;
  c.weight_per_length = per_depth * (set.density - set.fluid_density) * set.area * set.gravity;
  return c;
}

CableProperties cable_properties(const CableSet& set, double unstretched_length) {
  if (!(unstretched_length > 0.0))
    HALFETI_USER_ERROR("cable unstretched length must be positive, got " << unstretched_length << " m");
  const PerDepthCable c = per_unit_depth(set);
  CableProperties p;
  p.unstretched_length = unstretched_length;
  p.axial_stiffness = c.axial_stiffness;
  p.weight_per_length = c.weight_per_length;
  return p;
}

double tension_stress(const CableSet& set, double tension_per_depth) {
  return tension_per_depth / per_unit_depth(set).area;
}

double tension_per_cable(const CableSet& set, double tension_per_depth) {
  return tension_per_depth * set.depth / set.count;
}

double tank_frame_load(const CableSet& set, double ground_acceleration) {
  return -set.count * (set.density - set.fluid_density) * set.area / set.depth * ground_acceleration;
}

std::string describe_per_depth(const CableSet& set, const std::string& name) {
  const PerDepthCable c = per_unit_depth(set);
  std::ostringstream out;
  out << name << ": " << set.count << " real cable(s) of A = " << set.area << " m^2, E = " << set.modulus
      << " Pa, rho = " << set.density << " kg/m^3 across B = " << set.depth << " m";
  if (set.fluid_density > 0.0) out << ", submerged in rho = " << set.fluid_density << " kg/m^3";
  out << "\n  per unit depth: EA' = " << c.axial_stiffness << " N/m, w' = " << c.weight_per_length
      << " N/m^2, A' = " << c.area << " m (stress = T' / A')";
  return out.str();
}

}  // namespace halfeti::cable
