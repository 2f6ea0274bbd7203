#include "loiter/path_sink.hpp"

#include <algorithm>
#include <cmath>

#include "loiter/tangents.hpp"

namespace vistrack::detail {

namespace {
// Pieces shorter than this (m) are rounding left-overs (a Dubins arc of 1e-14 rad): dropped.
constexpr double kNegligible = 1e-10;
}  // namespace

double PathSink::continue_heading(double heading) const {
  return std::isnan(heading_) ? heading : heading_ + wrap_to_pi(heading - heading_);
}

void PathSink::line(const Vec2& a, const Vec2& b, SegmentRole role, int aoi) {
  const double length = (b - a).norm();
  if (!(length > kNegligible)) return;
  length_ += length;
  if (!segments_) return;
  LoiterSegment s;
  s.kind = SegmentKind::Line;
  s.role = role;
  s.start = a;
  s.end = b;
  s.start_heading = s.end_heading = continue_heading(heading_of(b - a));
  s.length = length;
  s.aoi = aoi;
  heading_ = s.end_heading;
  segments_->push_back(s);
}

void PathSink::arc(const Vec2& center, double radius, Circulation d, const Vec2& from, double sweep,
                   SegmentRole role, int aoi) {
  if (!(radius * sweep > kNegligible)) return;
  length_ += radius * sweep;
  if (!segments_) return;
  const double turn = static_cast<double>(sign(d));
  const double start_angle = heading_of(from - center);
  LoiterSegment s;
  s.kind = SegmentKind::Arc;
  s.role = role;
  s.start = from;
  s.end = center + radius * unit_at(start_angle + turn * sweep);
  s.start_heading = continue_heading(start_angle + turn * 0.5 * kPi);
  s.end_heading = s.start_heading + turn * sweep;
  s.center = center;
  s.radius = radius;
  s.direction = d;
  s.sweep = sweep;
  s.length = radius * sweep;
  s.aoi = aoi;
  heading_ = s.end_heading;
  segments_->push_back(s);
}

void PathSink::dubins(const DubinsPath& path, SegmentRole role, int aoi) {
  if (!segments_) {
    length_ += path.length;
    return;
  }
  Configuration q = path.start;
  const auto types = path.segment_types();
  double travelled = 0.0;
  for (std::size_t k = 0; k < 3; ++k) {
    const double piece = path.segment_lengths[k];
    if (!(piece > 0.0)) continue;
    const Vec2 from(q.x, q.y);
    travelled += piece;
    const Configuration next = path.at(std::min(travelled, path.length));
    if (types[k] == DubinsSegment::Straight) {
      line(from, Vec2(next.x, next.y), role, aoi);
    } else {
      const Circulation d = types[k] == DubinsSegment::Left ? Circulation::CounterClockwise : Circulation::Clockwise;
      const Vec2 center = from + path.rho * static_cast<double>(sign(d)) * left_of(unit_at(q.psi));
      arc(center, path.rho, d, from, piece / path.rho, role, aoi);
    }
    q = next;
  }
}

}  // namespace vistrack::detail
