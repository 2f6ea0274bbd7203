// The smooth locus (beyond the paper). The paper assumes the POI stays visible between the sampled
// orbits (sections IV.C, VI); on real maps MaxRadius dips between samples, so the check measures
// MaxRadius along the whole path (by line of sight, visible_disk_radius, or through VVs and the
// slicer), bounds it between check points, refines where R(t) touches the bound, and puts the
// smooth R(t) under it.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <sstream>

#include <tbb/parallel_for.h>

#include "locus.hpp"
#include "vistrack/error.hpp"

namespace vistrack::detail {
namespace {

// Between two check points MaxRadius is assumed to change by at most L m per m of POI travel, L
// kSlopeSafety times the largest slope of this and the neighbouring intervals but at least
// kMinSlope: it then stays above the straight line between them less (L^2 - slope^2) ds / (2 L),
// the deepest such a profile can dip below it. (The safety factor: a stretch whose own slope is the
// largest may still bend; on paper_small a 10 m interval sagged 1.7 m below its chord.) (Off cliffs MaxRadius moves about 0.4 m per m on Charlotte at 300 m, 0.1 m per
// m on the campus.) Where it changes by more than kJump between two check points and at least
// kKink times as steeply as on both neighbouring intervals (a cliff, located no better than the
// interval), the smaller value holds on the whole interval instead.
constexpr double kMinSlope = 0.1;
constexpr double kSlopeSafety = 2.0;
constexpr double kJump = 1.0;
constexpr double kKink = 2.0;
// An interval binds when R(t) comes within kActive of its ceiling (m); it is halved when that
// could raise the ceiling by more than kGain (m) and its halves stay check_min_spacing long.
// (kGain keeps flat stretches where R rides the ceiling from being halved down to centimetres:
// there the slope rule costs at most kGain.)
constexpr double kActive = 0.1;
constexpr double kGain = 0.25;
constexpr int kMaxRounds = 16;

struct CheckPoint {
  double s;
  double max_radius;
};

// Every `spacing` m from the start of each path edge, plus every node (as the VV samples are laid).
std::vector<double> grid_arc_lengths(const PoiPath& poi, double spacing) {
  std::vector<double> nodes;
  for (double t : poi.node_times()) nodes.push_back(t * poi.speed());
  std::vector<double> out;
  for (std::size_t e = 0; e + 1 < nodes.size(); ++e) {
    const auto steps = static_cast<long long>(std::ceil((nodes[e + 1] - nodes[e]) / spacing - 1e-9));
    for (long long k = 0; k < steps; ++k) out.push_back(nodes[e] + static_cast<double>(k) * spacing);
  }
  out.push_back(nodes.back());
  return out;
}

// The largest R(t) - ceiling(t) on [a, b], where the ceiling is linear: at the ends, the knots
// inside and the stationary points of R minus the line on each quadratic piece.
double max_excess(const RadiusProfile& profile, double a, double b, double start, double end) {
  const double slope = (end - start) / (b - a);
  auto excess = [&](double t) { return profile.radius(t) - (start + slope * (t - a)); };
  double best = std::max(excess(a), excess(b));
  const std::size_t k0 = profile.segment(a), k1 = profile.segment(b);
  for (std::size_t k = k0; k <= k1 && k + 1 < profile.times.size(); ++k) {
    if (profile.times[k] > a && profile.times[k] < b) best = std::max(best, excess(profile.times[k]));
    const double r0 = profile.smooth() ? profile.rates[k] - slope : 0.0;
    const double r1 = profile.smooth() ? profile.rates[k + 1] - slope : 0.0;
    if (r0 > 0.0 && r1 < 0.0) {
      const double t = profile.times[k] + r0 * (profile.times[k + 1] - profile.times[k]) / (r0 - r1);
      if (t > a && t < b) best = std::max(best, excess(t));
    }
  }
  return best;
}

}  // namespace

void smooth_locus(VisibilityOrbitPlan& plan, const CheckProbe& probe) {
  const PoiPath& poi = plan.poi;
  const Planning& planning = plan.planning;
  const Uav& uav = plan.uav;
  const double v_g = poi.speed();
  const Discretization& samples = plan.samples;
  const std::size_t n_samples = samples.times.size();
  LocusCheck& check = plan.check;
  check = LocusCheck{};

  // Without a probe between the samples, or when a sample already fails, the samples alone bound R.
  const bool refine = static_cast<bool>(probe.max_radius) && plan.orbits.feasible && n_samples > 1;
  std::atomic<std::size_t> computed{0};
  auto probe_at = [&](const std::vector<double>& arcs) {
    std::vector<double> out(arcs.size());
    tbb::parallel_for(std::size_t{0}, arcs.size(), [&](std::size_t i) {
      bool was_computed = false;
      out[i] = probe.max_radius(poi.position(arcs[i] / v_g), was_computed);
      if (was_computed) ++computed;
    });
    return out;
  };
  std::vector<CheckPoint> points;
  for (std::size_t k = 0; k < n_samples; ++k) points.push_back({samples.times[k] * v_g, plan.max_radii[k]});
  if (refine && probe.at_samples) {
    std::vector<double> arcs;
    for (const CheckPoint& p : points) arcs.push_back(p.s);
    const std::vector<double> probed = probe_at(arcs);
    for (std::size_t k = 0; k < n_samples; ++k) points[k].max_radius = std::min(points[k].max_radius, probed[k]);
  }
  // MaxRadius at new arc lengths, merged into `points` (kept sorted).
  auto measure = [&](const std::vector<double>& arcs) {
    const std::vector<double> probed = probe_at(arcs);
    for (std::size_t i = 0; i < arcs.size(); ++i) points.push_back({arcs[i], probed[i]});
    std::sort(points.begin(), points.end(), [](const CheckPoint& a, const CheckPoint& b) { return a.s < b.s; });
  };
  if (refine) {
    std::vector<double> grid;
    for (double s : grid_arc_lengths(poi, planning.check_spacing)) {
      const auto near = std::lower_bound(points.begin(), points.end(), s - 1e-6,
                                         [](const CheckPoint& p, double x) { return p.s < x; });
      if (near == points.end() || near->s > s + 1e-6) grid.push_back(s);
    }
    measure(grid);
  }

  SmoothRadiusLimits limits;
  limits.uav_speed = uav.speed;
  limits.poi_speed = v_g;
  limits.min_turn_radius = uav.min_turn_radius;
  limits.max_rate = (1.0 - planning.rate_margin) * (uav.speed - v_g);
  limits.turn_share = planning.turn_share;

  RadiusProfile profile;
  Ceiling ceiling;
  std::vector<double> slopes, gains;
  for (int round = 0;; ++round) {
    const std::size_t n = points.size();
    std::vector<double> slope(n - 1);
    for (std::size_t j = 0; j + 1 < n; ++j)
      slope[j] = std::abs(points[j + 1].max_radius - points[j].max_radius) / (points[j + 1].s - points[j].s);
    ceiling = Ceiling{};
    slopes.assign(n - 1, 0.0);
    gains.assign(n - 1, 0.0);
    for (const CheckPoint& p : points) ceiling.breaks.push_back(p.s / v_g);
    for (std::size_t j = 0; j + 1 < n; ++j) {
      const double m_a = points[j].max_radius, m_b = points[j + 1].max_radius;
      const double ds = points[j + 1].s - points[j].s;
      const double left = j > 0 ? slope[j - 1] : 0.0, right = j + 2 < n ? slope[j + 1] : 0.0;
      const double bound = std::max(kMinSlope, kSlopeSafety * std::max({slope[j], left, right}));
      slopes[j] = bound;
      if (std::abs(m_b - m_a) > kJump && slope[j] >= kKink * std::max({kMinSlope, left, right})) {
        const double low = std::min(m_a, m_b) - planning.tracking_margin;
        ceiling.starts.push_back(low);
        ceiling.ends.push_back(low);
        gains[j] = std::abs(m_b - m_a);  // locating the cliff could raise part of the interval this much
      } else {
        const double dip = (bound * bound - slope[j] * slope[j]) * ds / (2.0 * bound);
        ceiling.starts.push_back(m_a - dip - planning.tracking_margin);
        ceiling.ends.push_back(m_b - dip - planning.tracking_margin);
        gains[j] = dip;
      }
    }
    // One pass while refining; the last round adds the pass with the larger d2R/dt2 budgets.
    profile = smooth_radius(ceiling, limits, 0.0, 1, planning.radius_smoothing);
    check.rounds = round;
    if (!refine || round >= kMaxRounds) break;
    std::vector<double> middles;
    for (std::size_t j = 0; j + 1 < n; ++j) {
      const double ds = points[j + 1].s - points[j].s;
      if (ds >= 2.0 * planning.check_min_spacing * (1.0 - 1e-9) && gains[j] > kGain &&
          max_excess(profile, ceiling.breaks[j], ceiling.breaks[j + 1], ceiling.starts[j], ceiling.ends[j]) >= -kActive)
        middles.push_back(0.5 * (points[j].s + points[j + 1].s));
    }
    if (middles.empty()) break;
    measure(middles);
  }
  profile = smooth_radius(ceiling, limits, 0.0, 2, planning.radius_smoothing);

  // The check's record.
  const RadiusProfile paper{samples.times, plan.orbits.radii, {}};
  for (const CheckPoint& p : points) {
    const double t = p.s / v_g;
    check.arc_lengths.push_back(p.s);
    check.times.push_back(t);
    check.max_radii.push_back(p.max_radius);
    const double r = profile.radius(t);
    const double over = paper.radius(t) - p.max_radius;
    if (over > 1e-9) {
      ++check.paper_violations;
      check.paper_max_violation = std::max(check.paper_max_violation, over);
    }
    check.lowering.push_back(paper.radius(t) - r);
    if (check.lowering.back() > check.max_lowering || check.lowering.size() == 1) {
      check.max_lowering = check.lowering.back();
      check.max_lowering_time = t;
    }
    const double clearance = p.max_radius - r;
    check.min_clearance = check.lowering.size() == 1 ? clearance : std::min(check.min_clearance, clearance);
  }
  check.ceiling = ceiling;
  check.slope_bounds = slopes;
  check.volumes_computed = computed.load();

  // The reference and its feasibility: Algorithm 1's verdict on the samples first, then Lemma 6 on
  // the whole smooth R(t).
  const double lowest = profile.min_radius();
  if (lowest < 0.0) {
    // A ceiling under 0 (MaxRadius within tracking_margin of 0 somewhere, or a lowered slope
    // bound) gives no orbit at all: the plan keeps Algorithm 1's piecewise-linear R(t), which stays
    // a valid (if infeasible) reference, and says why.
    std::ostringstream why;
    why.precision(6);
    why << "the smooth R(t) would fall to " << lowest << " m (tracking_margin = " << planning.tracking_margin
        << " m inside MaxRadius between the samples): no orbit there; the plan keeps Algorithm 1's radii";
    plan.feasible = false;
    plan.infeasibility = plan.orbits.feasible ? why.str() : plan.orbits.infeasibility + "; " + why.str();
    return;
  }
  plan.reference = profile;
  plan.radii.clear();
  for (double t : samples.times) plan.radii.push_back(profile.radius(t));
  plan.feasible = plan.orbits.feasible;
  plan.infeasibility = plan.orbits.infeasibility;
  if (plan.feasible && lowest < plan.orbits.min_feasible_radius) {
    double at = profile.times.front();
    for (std::size_t k = 0; k < profile.times.size(); ++k)
      if (profile.radii[k] <= profile.radius(at)) at = profile.times[k];
    std::ostringstream why;
    why.precision(6);
    why << "smooth R(t) falls to " << lowest << " m near t = " << at << " s (it stays tracking_margin = "
        << planning.tracking_margin << " m inside MaxRadius between the samples, with bounded d2R/dt2) < r_min (1 + v_g/v)^2 = "
        << plan.orbits.min_feasible_radius << " m: the orbit's curvature exceeds 1/r_min there (Lemma 6)";
    plan.feasible = false;
    plan.infeasibility = why.str();
  }
  if (plan.feasible) {
    const std::string broken = smooth_radius_violation(profile, limits);
    if (!broken.empty()) {
      plan.feasible = false;
      plan.infeasibility = "smooth R(t): " + broken;
    }
  }
}

}  // namespace vistrack::detail
