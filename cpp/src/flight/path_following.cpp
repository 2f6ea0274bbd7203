// PathFollower: cross-track and heading feedback with curvature feed-forward (flight.hpp, Path following).
#include "vistrack/flight.hpp"

#include <algorithm>
#include <cmath>

#include "vistrack/error.hpp"

namespace vistrack {

namespace {

Vec2 direction(double angle) { return {std::cos(angle), std::sin(angle)}; }

// How far the progress may move from one accepted state to the next: the projection is searched
// near the previous one, so a path that crosses itself (a transit over a loiter circle) is not
// mistaken for its other part.
constexpr double kAheadRadii = 2.0;
constexpr double kBehindRadii = 0.5;

}  // namespace

Configuration PathPiece::at(double s) const {
  if (curvature == 0.0) {
    const Vec2 p = start + s * direction(heading);
    return {p.x(), p.y(), heading};
  }
  // Chord form: exact for arcs and well conditioned for short ones.
  const double turn = curvature * s;
  const double chord = 2.0 * std::sin(0.5 * turn) / curvature;
  const Vec2 p = start + chord * direction(heading + 0.5 * turn);
  return {p.x(), p.y(), heading + turn};
}

PathFollower::PathFollower(std::vector<PathPiece> pieces, double speed, double turn_radius,
                           const PathFollowingGains& gains)
    : pieces_(std::move(pieces)), speed_(speed), turn_radius_(turn_radius), gains_(gains) {
  require_positive(speed, "speed");
  require_positive(turn_radius, "turn_radius");
  gains.validate();
  if (pieces_.empty()) throw Error("pieces: the path to follow is empty");
  for (std::size_t k = 0; k < pieces_.size(); ++k) {
    const PathPiece& p = pieces_[k];
    const std::string field = "pieces[" + std::to_string(k) + "]";
    require_finite(p.start.x(), field + ".start[0]");
    require_finite(p.start.y(), field + ".start[1]");
    require_finite(p.heading, field + ".heading");
    require_positive(p.length, field + ".length");
    require_finite(p.curvature, field + ".curvature");
    if (std::abs(p.curvature) * turn_radius > 1.0 + 1e-9)
      detail::fail_field(field + ".curvature", p.curvature,
                         "turns tighter than the vehicle can (1 / turn_radius = " + detail::computed_text(1.0 / turn_radius) + ")");
    if (k > 0) {
      const Configuration end = pieces_[k - 1].at(pieces_[k - 1].length);
      const double gap = (Vec2(end.x, end.y) - p.start).norm();
      if (gap > 1e-6 * (1.0 + p.start.cwiseAbs().maxCoeff()))
        detail::fail_field(field + ".start", detail::to_text(p.start.x()) + ", " + detail::to_text(p.start.y()),
                           "does not continue the piece before (gap " + detail::computed_text(gap) + ")");
    }
    offsets_.push_back(length_);
    length_ += p.length;
  }
}

std::size_t PathFollower::piece_at(double s) const {
  const auto it = std::upper_bound(offsets_.begin(), offsets_.end(), s);
  return static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, (it - offsets_.begin()) - 1));
}

PathFollower::Tracking PathFollower::track(const Configuration& state) const {
  const Vec2 p(state.x, state.y);
  const double lo = std::max(0.0, progress_ - kBehindRadii * turn_radius_);
  const double hi = std::min(length_, progress_ + kAheadRadii * turn_radius_);
  // Newton steps on the progress: move along by the along-track offset, corrected for curvature.
  double s = progress_;
  for (int iteration = 0; iteration < 8; ++iteration) {
    const PathPiece& piece = pieces_[piece_at(s)];
    const Configuration q = piece.at(s - offsets_[piece_at(s)]);
    const Vec2 tangent = direction(q.psi), normal(-tangent.y(), tangent.x());
    const Vec2 d = p - Vec2(q.x, q.y);
    const double next = std::clamp(s + d.dot(tangent) / std::max(0.2, 1.0 - piece.curvature * d.dot(normal)), lo, hi);
    const bool converged = std::abs(next - s) < 1e-9 * (1.0 + length_);
    s = next;
    if (converged) break;
  }
  Tracking out;
  out.s = s;
  out.piece = piece_at(s);
  const Configuration q = pieces_[out.piece].at(s - offsets_[out.piece]);
  const Vec2 tangent = direction(q.psi), normal(-tangent.y(), tangent.x());
  const Vec2 d = p - Vec2(q.x, q.y);
  out.cross_track = d.dot(normal);
  out.heading_error = wrap_to_pi(state.psi - q.psi);
  out.along = s >= length_ ? d.dot(tangent) : 0.0;
  return out;
}

double PathFollower::switching_function(const Configuration& state, double /*t*/) const {
  // The next piece boundary ahead of the progress: crossing it changes the curvature feed-forward.
  // With anticipation the feed-forward changes that far before the boundary.
  const std::size_t k = piece_at(progress_);
  const Tracking tr = track(state);
  if (k + 1 == pieces_.size()) return tr.along < 0.0 || tr.s < length_ ? 1.0 : -1.0;
  const double boundary = offsets_[k + 1];
  const double lead = gains_.anticipation * speed_;
  return tr.s < boundary - lead ? boundary - lead - tr.s : boundary - tr.s;
}

void PathFollower::start(const Configuration& state, double /*t*/) {
  progress_ = 0.0;
  done_ = false;
  progress_ = track(state).s;
  touch();
}

GuidanceCommand PathFollower::command(const Configuration& state, double /*t*/) const {
  const Tracking tr = track(state);
  const PathPiece& piece = pieces_[tr.piece];
  const double path_heading = state.psi - tr.heading_error;
  const double lookahead = gains_.lookahead_radii * turn_radius_;
  const double desired = path_heading - std::atan(tr.cross_track / lookahead);
  const double curvature = gains_.anticipation > 0.0
                               ? pieces_[piece_at(std::min(tr.s + gains_.anticipation * speed_, length_))].curvature
                               : piece.curvature;
  const double feed_forward = speed_ * curvature * std::cos(tr.heading_error) /
                              std::max(0.2, 1.0 - curvature * tr.cross_track);
  const double feedback = gains_.heading_gain * speed_ / turn_radius_ * wrap_to_pi(desired - state.psi);
  GuidanceCommand c;
  c.turn_rate = feed_forward + feedback;
  const Configuration on_path = piece.at(tr.s - offsets_[tr.piece]);
  c.target = Vec2(on_path.x, on_path.y);
  c.target_index = static_cast<int>(tr.piece);
  return c;
}

void PathFollower::advance(const Configuration& state, double /*t*/) {
  const Tracking tr = track(state);
  const std::size_t before = piece_at(progress_);
  progress_ = std::max(progress_, tr.s);
  // Done once the projection sits on the end and the vehicle is level with it or past it.
  if (progress_ >= length_ && tr.along >= 0.0) done_ = true;
  if (piece_at(progress_) != before || done_) touch();
}

}  // namespace vistrack
