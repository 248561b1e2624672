#include "config/world_spec.hpp"

#include <cmath>
#include <cstdio>

#include "config/controller_catalog.hpp"

namespace swarmagg {

double WorldSpec::sensing_radius() const {
  return catalog_entry(controller.type).sensing_radius(*this);
}

double WorldSpec::perception_radius() const {
  return catalog_entry(controller.type).perception_radius(*this);
}

// Rounding in duration / dt (0.3 / 0.1 is 2.9999999999999996, off by a few 1e-16 of the
// quotient) is no reason for a note.
std::string WorldSpec::rounded_duration_note() const {
  const double exact = run.duration / engine.dt;
  if (std::abs(exact - std::round(exact)) <= 1e-12 * std::max(1.0, exact)) return "";
  char text[200];
  std::snprintf(text, sizeof text,
                "run.duration %.10g is %.12g steps of engine.dt %.10g: each replicate runs the "
                "nearest whole number, %lld, %.12g tu",
                run.duration, exact, engine.dt, static_cast<long long>(steps()),
                static_cast<double>(steps()) * engine.dt);
  return text;
}

}  // namespace swarmagg
