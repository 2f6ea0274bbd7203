#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <sstream>

#include "vistrack/environment.hpp"
#include "vistrack/error.hpp"
#include "vistrack/limits.hpp"

namespace vistrack {

PoiPath::PoiPath(const Eigen::MatrixXd& waypoints, double speed) : speed_(speed) {
  require_speed(speed, "speed");
  if (waypoints.cols() != 2 && waypoints.cols() != 3)
    detail::fail_field("waypoints.shape[1]", waypoints.cols(), "waypoints must be (n, 2) or (n, 3)");
  std::vector<Vec3> kept;
  for (Eigen::Index i = 0; i < waypoints.rows(); ++i) {
    Vec3 p(waypoints(i, 0), waypoints(i, 1), waypoints.cols() == 3 ? waypoints(i, 2) : 0.0);
    for (int k = 0; k < 3; ++k)
      require_coordinate(p[k], "waypoints[" + std::to_string(i) + "][" + std::to_string(k) + "]");
    // Consecutive repeats add no motion and would make a zero-length segment.
    if (!kept.empty() && (p.head<2>() - kept.back().head<2>()).norm() == 0.0) continue;
    kept.push_back(p);
  }
  if (kept.size() < 2)
    detail::fail_field("waypoints", kept.size(),
                       "a path needs at least two distinct points (count of distinct points given)");
  waypoints_.resize(static_cast<Eigen::Index>(kept.size()), 3);
  node_times_.assign(1, 0.0);
  for (std::size_t i = 0; i < kept.size(); ++i) {
    waypoints_.row(static_cast<Eigen::Index>(i)) = kept[i].transpose();
    if (i > 0) node_times_.push_back(node_times_.back() + (kept[i] - kept[i - 1]).head<2>().norm() / speed);
  }
}

PoiPath PoiPath::from_csv(const std::string& path, double speed) {
  require_regular_file(path, "path", "CSV");
  std::ifstream in(path, std::ios::binary);
  if (!in) detail::fail_field("path", path, "cannot open the CSV file for reading");
  std::vector<std::array<double, 3>> rows;
  int columns = 0;
  std::string line;
  int line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    if (line.find_first_not_of(" \t\r") == std::string::npos || line[0] == '#') continue;
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream fields(line);
    std::array<double, 3> row{0.0, 0.0, 0.0};
    int count = 0;
    std::string token;
    while (fields >> token) {
      if (count == 3)
        detail::fail_field(path + ":" + std::to_string(line_number), detail::printable(token),
                           "expected 2 or 3 columns x,y[,z]");
      try {
        std::size_t used = 0;
        row[count] = std::stod(token, &used);
        if (used != token.size()) throw std::invalid_argument(token);
      } catch (const std::exception&) {
        // A header ("x,y,z") is a first line whose first field is not a number; a number in the
        // first field makes the line data, so "0,0,0.5abc" is an error, not a header.
        if (rows.empty() && line_number == 1 && count == 0) { count = -1; break; }
        detail::fail_field(path + ":" + std::to_string(line_number), detail::printable(token), "not a number");
      }
      ++count;
    }
    if (count == -1) continue;
    if (count < 2)
      detail::fail_field(path + ":" + std::to_string(line_number), detail::printable(line), "expected columns x,y[,z]");
    columns = std::max(columns, count);
    rows.push_back(row);
  }
  if (rows.empty()) detail::fail_field("path", path, "the CSV file has no waypoints");
  Eigen::MatrixXd waypoints(static_cast<Eigen::Index>(rows.size()), columns);
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (int k = 0; k < columns; ++k) waypoints(static_cast<Eigen::Index>(i), k) = rows[i][k];
  return PoiPath(waypoints, speed);
}

PoiPath PoiPath::from_nodes(const RoadNetwork& roads, const std::vector<int>& nodes, double speed) {
  if (nodes.size() < 2) detail::fail_field("nodes", nodes.size(), "a road path needs at least two nodes");
  Eigen::MatrixXd waypoints(static_cast<Eigen::Index>(nodes.size()), 2);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const int node = nodes[i];
    if (node < 0 || node >= static_cast<int>(roads.nodes.size()))
      detail::fail_field("nodes[" + std::to_string(i) + "]", node, "no such road node");
    if (i > 0) {
      const int previous = nodes[i - 1];
      bool joined = false, against = false;
      for (std::size_t e = 0; e < roads.edges.size(); ++e) {
        const auto& edge = roads.edges[e];
        if (edge.first == previous && edge.second == node) joined = true;
        if (edge.first == node && edge.second == previous) (roads.is_oneway(e) ? against : joined) = true;
      }
      if (!joined)
        detail::fail_field("nodes[" + std::to_string(i) + "]", node,
                           against ? "the only road edge from the previous node " + std::to_string(previous) +
                                         " is one-way the other way"
                                   : "no road edge joins it to the previous node " + std::to_string(previous));
    }
    waypoints.row(static_cast<Eigen::Index>(i)) = roads.nodes[static_cast<std::size_t>(node)].transpose();
  }
  return PoiPath(waypoints, speed);
}

namespace {
std::size_t segment_at(const std::vector<double>& node_times, double t) {
  // Right-continuous: at a node time the next segment applies (the last one at the end).
  auto it = std::upper_bound(node_times.begin(), node_times.end(), t);
  std::size_t index = it == node_times.begin() ? 0 : static_cast<std::size_t>(it - node_times.begin()) - 1;
  return std::min(index, node_times.size() - 2);
}
}  // namespace

Vec3 PoiPath::position(double t) const {
  require_finite(t, "t");
  t = std::clamp(t, 0.0, duration());
  const std::size_t i = segment_at(node_times_, t);
  const double span = node_times_[i + 1] - node_times_[i];
  const double s = span > 0.0 ? (t - node_times_[i]) / span : 0.0;
  const auto row = static_cast<Eigen::Index>(i);
  return ((1.0 - s) * waypoints_.row(row) + s * waypoints_.row(row + 1)).transpose();
}

Vec2 PoiPath::velocity(double t) const {
  require_finite(t, "t");
  const std::size_t i = segment_at(node_times_, std::clamp(t, 0.0, duration()));
  const auto row = static_cast<Eigen::Index>(i);
  const Vec2 delta = (waypoints_.row(row + 1) - waypoints_.row(row)).head<2>().transpose();
  return speed_ * delta / delta.norm();
}

double PoiPath::heading(double t) const {
  const Vec2 v = velocity(t);
  return std::atan2(v.y(), v.x());
}

}  // namespace vistrack
