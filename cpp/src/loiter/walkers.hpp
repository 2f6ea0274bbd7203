// The three planners as walkers: each visit(aoi) commits the path up to the arrival at that AOI
// (what it depends on is then known: the next AOI fixes how the current one is left), finish()
// goes to the end point. Walkers are small values: the order search copies them at every branch.
#pragma once

#include <string>
#include <vector>

#include "loiter/path_sink.hpp"
#include "vistrack/loiter.hpp"

namespace vistrack::detail {

// Why a method cannot fly an order (LDLPP's lines too short for its turns).
struct WalkFailure {
  enum class Kind : std::uint8_t { None, StartTooClose, AoisTooClose, EndTooClose };
  Kind kind = Kind::None;
  int from = -1;  // AOI index (AoisTooClose, EndTooClose)
  int to = -1;    // AOI index (StartTooClose, AoisTooClose)
  double distance = 0.0;
  double needed = 0.0;
  explicit operator bool() const { return kind != Kind::None; }
  [[noreturn]] void raise(const LoiterProblem& problem) const;
};

// Shared state: problem, sink, directions (by AOI, when recorded), the AOI visited last.
class WalkerBase {
 public:
  WalkerBase(const LoiterProblem& problem, PathSink sink, std::vector<Circulation>* directions);
  double length() const { return sink_.length(); }
  const WalkFailure& failure() const { return failure_; }

 protected:
  const Vec2& poi(int aoi) const { return problem_->aois[static_cast<std::size_t>(aoi)]; }
  void record_direction(int aoi, Circulation d) const {
    if (directions_) (*directions_)[static_cast<std::size_t>(aoi)] = d;
  }
  // The loiter direction whose exit heading needs the smaller heading change to point at `next`
  // (section 3.1: "determining if exiting the loiter path in a CW or CCW is in the direction of
  // the next AOI"); ties go counter-clockwise.
  static Circulation towards(const Vec2& exit_ccw, double heading_ccw, const Vec2& exit_cw, double heading_cw,
                             const Vec2& next);

  const LoiterProblem* problem_;
  PathSink sink_;
  std::vector<Circulation>* directions_;
  double r_, R_, loiter_sweep_;  // turn radius, AOI radius, 2 pi turns
  int pending_ = -1;             // the AOI flown to last, not yet left
  Vec2 position_;
  WalkFailure failure_;
};

class FlyThroughWalker : public WalkerBase {
 public:
  FlyThroughWalker(const LoiterProblem& problem, PathSink sink, std::vector<Circulation>* directions = nullptr);
  bool visit(int aoi);
  bool finish();
  // Length every AOI adds besides transit: the entry (3/4 turn and line when R = r) and the loiters.
  static double per_aoi_minimum(const LoiterProblem& problem);

 private:
  void loiter_and_leave(const Vec2& next);
  void go_to(const Vec2& target);

  double heading_;  // NaN at the start: free
};

class TlppWalker : public WalkerBase {
 public:
  TlppWalker(const LoiterProblem& problem, PathSink sink, std::vector<Circulation>* directions = nullptr);
  // The first AOI's direction given instead of the printed rule (TlppBest tries both).
  TlppWalker(const LoiterProblem& problem, PathSink sink, std::vector<Circulation>* directions,
             Circulation first_direction);
  bool visit(int aoi);
  bool finish();
  static double per_aoi_minimum(const LoiterProblem& problem);

 private:
  void enter_first(const Vec2& next);
  void loiter_until(const Vec2& departure);

  bool first_ = true;  // the pending AOI is the first: its entry waits for the direction
  Vec2 entry_;         // where the pending AOI's loiter starts
  Circulation direction_ = Circulation::CounterClockwise;
  bool forced_ = false;  // first_direction_ given
  Circulation first_direction_ = Circulation::CounterClockwise;
};

// TlppBest in the order search: both first directions walked side by side, without a path; the
// shorter counts (the plan itself is the shorter of the two TlppWalker plans).
class TlppBothWalker {
 public:
  explicit TlppBothWalker(const LoiterProblem& problem, PathSink sink = PathSink());
  bool visit(int aoi) { return ccw_.visit(aoi) && cw_.visit(aoi); }
  bool finish() { return ccw_.finish() && cw_.finish(); }
  double length() const;
  const WalkFailure& failure() const { return ccw_.failure(); }
  static double per_aoi_minimum(const LoiterProblem& problem) { return TlppWalker::per_aoi_minimum(problem); }

 private:
  TlppWalker ccw_, cw_;
};

class LdlppWalker : public WalkerBase {
 public:
  // choose_direction: each AOI loitered in the direction that loiters less (LdlppBest); else
  // counter-clockwise, as printed.
  LdlppWalker(const LoiterProblem& problem, PathSink sink, std::vector<Circulation>* directions = nullptr,
              bool choose_direction = false);
  bool visit(int aoi);
  bool finish();
  static double per_aoi_minimum(const LoiterProblem& problem);

 private:
  // The entry and exit turns, loiter and exit point at the pending AOI for a loiter direction.
  struct Visit {
    Vec2 entry_center, entry, exit, exit_center;
    double sweep;
  };
  Visit plan_visit(const Vec2& along_out, Circulation direction) const;
  void enter(int aoi, const Vec2& along);
  void leave(const Vec2& along);

  double entry_distance_, turn_angle_;
  bool choose_direction_;
  Vec2 along_in_;  // the line the pending AOI is entered along (its entry turn is drawn on leaving)
};

// LdlppBest for the order search (the walkers are built from (problem, sink)).
class LdlppBestWalker : public LdlppWalker {
 public:
  explicit LdlppBestWalker(const LoiterProblem& problem, PathSink sink = PathSink(),
                           std::vector<Circulation>* directions = nullptr)
      : LdlppWalker(problem, sink, directions, true) {}
};

}  // namespace vistrack::detail
