// Dubins paths: shortest of the six words, batch lengths, path to a circle, and the optimal
// intercept of a target moving on a circle (Manyam, Casbeer, Von Moll, Fuchs, "Optimal target
// intercept paths for vehicles with turn radius constraints", seeds/target_intercept_on_circle).
//
// Conventions: configurations are (x, y, psi) with psi counter-clockwise from +x; lengths in
// metres; `rho` is the minimum turn radius. Segment lengths are arc lengths in metres.
//
// Snapping tolerance (the only place where the solver rounds on purpose): with
// eps = kDubinsSnap * (1 + max|coordinate of q0, q1| / rho), kDubinsSnap = 1e-11,
//  * an arc whose angle mod 2 pi lies within eps (rad) of 2 pi is taken as 0 (a full loop made
//    by rounding, never a wanted one), and so is a relative heading within eps of 2 pi k;
//  * LSL/RSR circles closer than eps * rho coincide (the goal lies on the start's turning
//    circle): the word is the single arc between start and goal;
//  * LSR/RSL circles overlapping by less than about eps * rho are tangent (straight of 0);
//    CCC words clamp |D / 4 rho| <= 1 + 1e-12.
// Each snap moves the endpoint by at most a few eps * rho. Consequence: a goal within ~eps * rho
// of the start with the same heading is the start (length ~0); a goal just behind the start by
// more than that needs the full loop (~2 pi rho): the Dubins distance is discontinuous there.
// With these, re-planning from any sampled point of a path gives the remaining length.
// Compared with OMPL (DubinsStateSpace: 1e-6 rho / 1e-7 rad tolerances) the lengths agree to
// ~1e-14 relative except inside OMPL's looser snaps (bench/dubins_bench.py lists them).
//
// Speed: one length kernel (src/dubins/kernel.hpp) picks the word for dubins_shortest_path and
// the batch: no atan2 for LSL/RSR, one for LSR/RSL, polynomial sin/cos/atan2 (a few ulp), no
// allocation; the batch runs it four pairs per AVX2 instruction when the CPU has AVX2, bit-
// identical to the scalar kernel.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "vistrack/geometry.hpp"

namespace vistrack {

constexpr double kDubinsSnap = 1e-11;

// A planar configuration: position and heading (rad, counter-clockwise from +x).
struct Configuration {
  double x = 0.0;
  double y = 0.0;
  double psi = 0.0;
};

// The six Dubins words; the order is the one every array of per-word values uses.
enum class DubinsWord : std::uint8_t { LSL = 0, LSR = 1, RSL = 2, RSR = 3, RLR = 4, LRL = 5 };
constexpr int kDubinsWordCount = 6;

enum class DubinsSegment : std::uint8_t { Left = 0, Straight = 1, Right = 2 };

// Travel direction on a circle (the one Circulation of geometry.hpp).
using CircleDirection = Circulation;

template <>
struct EnumNames<DubinsWord> {
  static constexpr const char* field = "word";
  static constexpr EnumName<DubinsWord> names[] = {{"LSL", DubinsWord::LSL}, {"LSR", DubinsWord::LSR},
      {"RSL", DubinsWord::RSL}, {"RSR", DubinsWord::RSR}, {"RLR", DubinsWord::RLR}, {"LRL", DubinsWord::LRL}};
};
std::array<DubinsSegment, 3> segment_types(DubinsWord word);

// One Dubins path: start, goal, turn radius, word and the three segment lengths (m).
struct DubinsPath {
  Configuration start;
  Configuration goal;
  double rho = 1.0;
  DubinsWord word = DubinsWord::LSL;
  std::array<double, 3> segment_lengths{0.0, 0.0, 0.0};
  double length = 0.0;  // sum of segment_lengths

  std::array<DubinsSegment, 3> segment_types() const { return vistrack::segment_types(word); }
  // Configuration after arc length s in [0, length] (s outside is an Error). Headings are not
  // wrapped: they continue from start.psi. At s == length the goal is returned exactly.
  Configuration at(double s) const;
  // Rows (x, y, psi) at s = 0, step, 2 step, ... and the goal exactly as the last row (only
  // the goal when length == 0).
  Points3 sample(double step) const;
  // Rows at the given arc lengths (each in [0, length]).
  Points3 sample_at(const std::vector<double>& arc_lengths) const;
};

// Error naming the field for a configuration outside the ranges of vistrack/limits.hpp (x, y
// within 1e7 m, psi within 1e9 rad) or rho outside [1e-6, 1e7] m. Every function below checks
// its input with it, except the unchecked kernel dubins_shortest_length.
void validate_dubins_problem(const Configuration& q0, const Configuration& q1, double rho);

// Shortest of the six words from q0 to q1 with turn radius rho.
DubinsPath dubins_shortest_path(const Configuration& q0, const Configuration& q1, double rho);
// The path of one given word; Error when that word has no path between q0 and q1 (CCC words
// need the circles within 4 rho).
DubinsPath dubins_path(const Configuration& q0, const Configuration& q1, double rho, DubinsWord word);
// Length of every word (+infinity where the word does not exist), in DubinsWord order.
std::array<double, kDubinsWordCount> dubins_word_lengths(const Configuration& q0,
                                                         const Configuration& q1, double rho);

// Batch: row i of q0s/q1s (n x 3, row-major x, y, psi) -> lengths[i], words[i] (DubinsWord
// values). Multi-threaded with TBB (threads = 0: all cores; otherwise at most that many).
// Allocation-free inner loop.
struct DubinsBatch {
  std::vector<double> lengths;
  std::vector<std::uint8_t> words;
};
void dubins_shortest_lengths(const double* q0s, const double* q1s, std::size_t n, double rho,
                             double* lengths, std::uint8_t* words, int threads = 0);
DubinsBatch dubins_shortest_lengths(const Points3& q0s, const Points3& q1s, double rho, int threads = 0);
// Single-threaded length of the shortest path (the kernel of the batch). Unchecked: the caller
// has validated q0, q1 and rho (validate_dubins_problem).
double dubins_shortest_length(const Configuration& q0, const Configuration& q1, double rho,
                              DubinsWord* word = nullptr);

// --- Path to a circle (paper, Section III) ---------------------------------------------------

// A circle the goal lies on and the travel direction along it.
struct TargetCircle {
  Vec2 center{0.0, 0.0};
  double radius = 1.0;
  CircleDirection direction = CircleDirection::Clockwise;

  // The configuration at angular position `angle` (rad, counter-clockwise from +x about the
  // centre): position on the circle, heading tangent in the travel direction
  // (angle - pi/2 clockwise, angle + pi/2 counter-clockwise, as in Section III).
  Configuration configuration(double angle) const;
  void validate() const;
};

// Shortest Dubins path from q0 to the point at `angle` on the circle, arriving tangent to it.
DubinsPath dubins_path_to_circle(const Configuration& q0, double rho, const TargetCircle& circle,
                                 double angle);
// D(angle): length of that path; the paper's D_CSC(alpha) (eq. 1) when the 4 rho condition
// holds (then the shortest word is CSC). Periodic in angle with period exactly 2 pi.
double dubins_length_to_circle(const Configuration& q0, double rho, const TargetCircle& circle,
                               double angle);
// Same restricted to the four CSC words, D_CSC of the paper, for any geometry.
double dubins_csc_length_to_circle(const Configuration& q0, double rho, const TargetCircle& circle,
                                   double angle);
// Whether every point of the circle is farther than 4 rho from p (the paper's assumption).
bool four_rho_condition(const Vec2& p, double rho, const TargetCircle& circle);

// --- Intercept of a target moving on a circle (paper, Section IV, Algorithm 1) -------------

struct InterceptProblem {
  Configuration pursuer;        // initial pursuer configuration
  double rho = 1.0;             // pursuer minimum turn radius (m)
  double pursuer_speed = 1.0;   // v_p (m/s)
  TargetCircle circle;          // target circle and travel direction
  double target_angle0 = 0.0;   // alpha_i: initial angular position of the target (rad)
  double target_speed = 1.0;    // v_t (m/s)
  double angle_tolerance = 1e-12;  // bisection stops when the bracket is narrower (rad)
  int scan_samples = 2048;      // samples per period to locate minima and the first crossing

  void validate() const;
};

struct InterceptResult {
  double angle = 0.0;         // alpha*: interception angular position (unwrapped: alpha_i + s*swept)
  double swept_angle = 0.0;   // angle the target travels before interception (>= 0)
  double time = 0.0;          // interception time T_t(alpha*) (s)
  double residual = 0.0;      // T_p(alpha*) - T_t(alpha*) at the returned angle (s)
  DubinsPath path;            // pursuer path to the interception point
  bool four_rho_condition = false;  // true: optimal by Proposition 1; false: feasible only
  double period = kTwoPi;     // period of D(alpha) used for the brackets (rad)
  double alpha_min = 0.0;     // argmin of D over one period, in [0, 2 pi)
  int bracket_windows = 0;    // windows Algorithm 1 stepped through before the bracket held
  int bisection_steps = 0;
};

InterceptResult intercept_circle(const InterceptProblem& problem);

// Travel times for plotting (Figure 7a): T_p(alpha) = D(alpha)/v_p and T_t(alpha) for the
// swept angles given (alpha = alpha_i + s*swept, s = +1 ccw, -1 cw).
struct InterceptTimes {
  std::vector<double> angles;
  std::vector<double> pursuer;
  std::vector<double> target;
};
InterceptTimes intercept_travel_times(const InterceptProblem& problem,
                                      const std::vector<double>& swept_angles);

}  // namespace vistrack
