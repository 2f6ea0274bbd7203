// DWN's horizon path as PathFollower pieces (beyond the paper: path following for banking vehicles).
#include <cmath>

#include "horizon.hpp"
#include "vistrack/waypoint_nav.hpp"

namespace vistrack {

std::vector<PathPiece> horizon_pieces(const Configuration& pose, const HorizonPath& path, double turn_radius,
                                      double extension) {
  const double d1 = detail::first_direction(path.turn_case), d2 = detail::second_direction(path.turn_case);
  std::vector<PathPiece> pieces;
  Configuration at = pose;
  auto add = [&](double length, double curvature) {
    if (!(length > 1e-9 * turn_radius)) return;
    PathPiece piece{Vec2(at.x, at.y), at.psi, length, curvature};
    pieces.push_back(piece);
    at = piece.at(length);
  };
  add(path.first_arc, d1 / turn_radius);
  add(path.first_straight, 0.0);
  add(path.arc_to_waypoint + path.arc_from_waypoint, d2 / turn_radius);
  add(path.last_straight, 0.0);
  add(extension, 0.0);
  return pieces;
}

}  // namespace vistrack
