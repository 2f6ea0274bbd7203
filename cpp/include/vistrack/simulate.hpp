// The closed loop of section VI: the vehicle (1) steered by (86) around the time-varying
// orbit of an OrbitPlan, integrated by Dormand-Prince 5(4) and restarted at every instant where
// R_dot (the paper's locus), R_ddot (the smooth one) or the POI velocity jumps; optional
// line-of-sight evaluation at every output sample. Uav::dynamics chooses the vehicle: the turn
// rate is (86)'s command at once (Dubins, the paper's), or the roll model (vehicle.hpp) banks towards the coordinated bank of that command (the state gains phi, level at
// the start) and turns at g tan(phi) / v.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "vistrack/geometry.hpp"
#include "vistrack/guidance.hpp"
#include "vistrack/ode.hpp"
#include "vistrack/orbit.hpp"
#include "vistrack/simulate_parameters.hpp"
#include "vistrack/visibility.hpp"

namespace vistrack {

// Whether each segment from[i] -> to[i] is unobstructed (1) or not (0). The visibility area's
// Embree scene provides the real one; anything with this shape can be plugged in.
using LineOfSight = std::function<std::vector<std::uint8_t>(const Points3& from, const Points3& to)>;

struct SimulationResult {
  std::vector<double> t;                 // output times, s
  Points3 state;                         // (n, 3): x, y, psi (psi as integrated, not wrapped)
  std::vector<double> desired_heading;   // psi_d (77), in (-pi, pi]
  std::vector<double> desired_heading_rate;  // dpsi_d/dt along the field (85)
  std::vector<double> radial_error;      // r - R
  std::vector<double> heading_error;     // psi - psi_d wrapped to (-pi, pi]
  std::vector<double> control;           // u_psi commanded by (86) (clamped to +-v / r_min)
  std::vector<double> turn_rate;         // psi_dot flown: u_psi (Dubins) or g tan(phi) / v (roll)
  std::vector<double> bank;              // rad: the roll model's state, or the coordinated bank of u_psi
  std::vector<double> control_unsaturated;  // (86) before the clamp
  Points3 poi;                           // (n, 3) POI position g(t) with the path's z
  std::vector<double> orbit_radius;      // R(t)
  std::vector<double> restart_times;     // where the integrator was restarted (segment ends)
  std::vector<std::uint8_t> visible;     // line of sight at each sample (empty without a scene)
  std::optional<double> visibility_fraction;  // mean of `visible`, when evaluated
  OdeStatistics statistics;
};

// Times where R_dot, R_ddot or g_dot may jump inside the plan's span: the knots of the plan's
// reference (its samples, for the paper's locus) and the POI's path nodes, sorted and unique, from
// the first plan time to the end of the plan (or the path, whichever comes first).
std::vector<double> segment_boundaries(const OrbitPlan& plan);

// The orbit (g, g_dot, R, R_dot, R_ddot) on the segment starting at `segment_start`, evaluated at t.
OrbitState orbit_state(const OrbitPlan& plan, double segment_start, double t);

// Simulates the closed loop from configuration x0 = (x, y, psi) at the plan's first time to its
// end. options.rtol/atol/max_step drive the adaptive steps; fixed_step > 0 switches to fixed
// steps of that size. Samples every options.output_step and at the end. Throws Error for
// invalid inputs, including a plan whose |R_dot| exceeds v - v_g somewhere (Lemma 5). With a
// line_of_sight function, visibility at every sample with the UAV at z = uav.altitude.
SimulationResult simulate(const OrbitPlan& plan, const Uav& uav, const Vec3& x0, const Control& control,
                          const SimulationOptions& options = {}, const LineOfSight& line_of_sight = {},
                          double fixed_step = 0.0);

// The trajectory as CSV text, one sample per line, with the header
// t,x,y,psi,psi_d,psi_d_rate,radial_error,heading_error,u_psi,u_psi_unsaturated,poi_x,poi_y,poi_z,
// orbit_radius,bank[,visible]. Full double precision.
std::string trajectory_csv(const SimulationResult& result);

// The same closed loop with the line of sight of an Embree scene at every sample: the UAV at
// world z = uav.altitude (the altitude the orbit planner slices its VPs at), the POI at g(t)
// lifted onto the surface under it (VisibilityScene::poi_on_surface, as the planner places it).
SimulationResult simulate(const OrbitPlan& plan, const Uav& uav, const Vec3& x0, const Control& control,
                          const SimulationOptions& options, const VisibilityScene& scene, double fixed_step = 0.0);

// Controller tuning (section V.D, Fig. 9): the largest |dpsi_d/dt + u_lyap| over positions
// r in [tau R, r_max] (all polar angles) and all heading errors, for an orbit of radius R and
// rate R_dot about a POI of speed v_g. Compare with the turn-rate limit v / r_min.
struct TuningGrid {
  double tau = 1.0;
  double r_max_factor = 4.0;   // r_max = r_max_factor * R
  int num_radii = 200;
  int num_angles = 360;
  int num_heading_errors = 73;
  void validate() const;
};

struct TuningResult {
  double max_turn_rate = 0.0;  // max |dpsi_d/dt + u_lyap|, rad/s
  double at_r = 0.0;           // where it occurs: distance to the POI
  double at_theta = 0.0;       // polar angle from the POI's direction of motion
  double at_heading_error = 0.0;
  // Maximum over heading errors at each grid position, (num_radii, num_angles), and the axes.
  std::vector<double> radii;
  std::vector<double> angles;
  std::vector<double> map;     // row-major num_radii x num_angles
};

TuningResult tune_turn_rate(double radius, double radius_rate, double speed, double poi_speed, double beta,
                            Circulation direction = Circulation::CounterClockwise,
                            const TuningGrid& grid = {});

}  // namespace vistrack
