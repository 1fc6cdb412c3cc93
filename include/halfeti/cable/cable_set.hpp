// A set of real cables side by side across the tank's depth, turned into the per-unit-depth cable of the 2D
// model (DESIGN.md, "2D bookkeeping").
#pragma once

#include <string>

#include "halfeti/cable/catenary.hpp"

namespace halfeti::cable {

struct CableSet {
  int count = 1;               // N real cables across the depth
  double area = 0.0;           // A, cross-section of one cable [m^2]
  double modulus = 0.0;        // E [Pa]
  double density = 0.0;        // rho of the cable material [kg/m^3]
  double depth = 1.0;          // B, out-of-plane depth they span [m]
  double fluid_density = 0.0;  // rho_water if submerged (buoyancy), 0 in air [kg/m^3]
  double gravity = 9.81;       // g [m/s^2]
};

// Per unit depth: EA' = N E A / B [N/m], w' = N (rho - rho_fluid) A g / B [N/m^2], area' = N A / B [m].
struct PerDepthCable {
  double axial_stiffness = 0.0;
  double weight_per_length = 0.0;
  double area = 0.0;
};

// Checks the set (user-facing errors) and converts it.
PerDepthCable per_unit_depth(const CableSet& set);

// The tank frame's inertial load on the set per unit depth and unstretched length, -a_g times this mass (the
// buoyant mass N (rho - rho_fluid) A / B: the water around a cable feels the same frame; its weight stays in w').
double tank_frame_load(const CableSet& set, double ground_acceleration);

// The 2D element's properties for a given unstretched length.
CableProperties cable_properties(const CableSet& set, double unstretched_length);

// Tension of one real cable over its area, from a per-depth tension: T' / (N A / B) [Pa].
double tension_stress(const CableSet& set, double tension_per_depth);

// Tension of one real cable [N], from a per-depth tension.
double tension_per_cable(const CableSet& set, double tension_per_depth);

// One block of text for the start-up log: the real set and its per-depth figures.
std::string describe_per_depth(const CableSet& set, const std::string& name = "cable");

}  // namespace halfeti::cable
