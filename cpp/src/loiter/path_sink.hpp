// Where the planners put their segments: the total length always, the segments when asked (the
// order search only needs lengths).
#pragma once

#include <limits>
#include <vector>

#include "vistrack/dubins.hpp"
#include "vistrack/loiter.hpp"

namespace vistrack::detail {

class PathSink {
 public:
  explicit PathSink(std::vector<LoiterSegment>* segments = nullptr) : segments_(segments) {}

  // A straight line from a to b (nothing when they coincide).
  void line(const Vec2& a, const Vec2& b, SegmentRole role, int aoi);
  // An arc about centre from `from`, turning `sweep` rad in direction d (nothing when sweep is 0).
  void arc(const Vec2& center, double radius, Circulation d, const Vec2& from, double sweep, SegmentRole role,
           int aoi);
  // The three pieces of a Dubins path.
  void dubins(const DubinsPath& path, SegmentRole role, int aoi);

  double length() const { return length_; }
  bool recording() const { return segments_ != nullptr; }

 private:
  // A heading continuous with the previous segment's end.
  double continue_heading(double heading) const;

  std::vector<LoiterSegment>* segments_;
  double length_ = 0.0;
  double heading_ = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace vistrack::detail
