// The valid range of every numeric input, decided from the physics and from what doubles (and
// Embree's floats) resolve, in one place. Each range is checked once, where input enters the API
// (parameter structs' validate(), loaders, the public functions of each area), and the error says
// the range. docs/limits.md is generated from this comment and the constants below.
//
//   coordinates (x, y, z of POIs, waypoints, vertices, footprints, centres, starts)  |v| <= 1e7 m
//   lengths (rho, r_min, radii, d_max, spacings, steps, heights)                   [1e-6, 1e7] m
//   speeds (v, v_g, pursuer, target)                                               [1e-6, 1e4] m/s
//   angles (headings, polar angles; unwrapped headings allowed)                    |a| <= 1e9 rad
//   a georeference's origin altitude (metres above mean sea level)                 |alt| <= 1e5 m
//   times                                                                         finite
//   time steps and periods (loiter dt, follow.period)                              (0, 3600] s
//   volumes (d_cutoff)                                                            (0, 1e21] m^3
//   threads                                                                        [0, 1024]
//   guidance gains: beta (vector field, 1/m)                                       [1e-9, 1e3]
//                   k_psi (heading, 1/s)                                           [1e-9, 1e6]
//   ODE tolerances: rtol                                                          [1e-13, 1]
//                   atol (m, rad)                                                 [1e-15, 1e6]
//   a Dubins problem's coordinates relative to its turn radius                     max|x, y| <= 1e6 rho
//   roll model: time constant tau                                                  [1e-3, 60] s
//               maximum roll rate                                                  [1e-3, 1e4] deg/s
//   input files (meshes, maps, routes, scenarios, plans; regular files only)        <= 1 GiB
//   input documents (JSON, YAML): nesting depth                                    <= 100 levels
//   YAML documents: values, each alias counted as what it expands to               <= 1e6
//
// Why: 1e7 m is a local frame of 10,000 km (any city, any flight); beyond it float32 ray tracing
// and the orbit planner's metre-scale steps lose their meaning. A length below 1e-6 m (1 µm) or
// a speed below 1 µm/s is below anything a vehicle or a sensor resolves, and keeps every ratio
// (coordinate / rho, length / speed) far inside the doubles' range, so no result overflows to inf
// or NaN. 1e4 m/s is thirty times the speed of sound. An unwrapped heading of 1e9 rad is still
// resolved to 1e-7 rad. The Dubins solver snaps within eps = 1e-11 (1 + max|coordinate| / rho)
// (dubins.hpp): the rounding of coordinates far from the origin, seen on the scale of rho; at most
// 1e6 rho from the origin keeps eps <= 1e-5, beyond it the snaps decide the word (a 8 µm turn radius
// 2,600 km from the origin picked a path 6 % longer than another word's). A gain below 1e-9 steers
// nothing within any flight; beta 1e3 /m turns the field over within a millimetre and k_psi 1e6 /s
// over a microsecond, both far past what a step of the integrator resolves. Below rtol 1e-13 a
// double-precision step's error estimate is rounding noise (scipy's floor is 100 eps); below atol
// 1e-15 the scaled error norm overflows near a zero state; an atol above 1e6 m accepts any state.
// A roll time constant of a millisecond is an instant roll (the Dubins model), one of a minute no
// aircraft that can still turn; 1e4 deg/s is beyond any airframe and keeps the rate limit finite.
// An origin 100 km above or below sea level is past the edge of space; beyond it the tangent plane
// about it no longer describes the ground (an origin at 1e20 m put every waypoint at lat/lon 1e-18).
// A step or a period of an hour is longer than any loiter or follow flight's feature (a larger
// dt skipped the whole flight: coverage 0; a follow period of 1e300 s flew a straight line).
// Work is estimated in bytes before it starts: 2 GB is the most one planned piece of work (the VVs
// a plan holds, a batch of VVs, a loiter coverage matrix) may allocate, what a 3 GB machine can
// hold beside the libraries (400 VVs at 1 degree: 1.9 GB; the examples' plans need at most 75 MB);
// beyond it the error names the knob that lowers the cost.
// 1 GiB of input is generous for a city mesh (the Charlotte OBJ is 0.7 MB) and a scenario,
// route or plan is kilobytes; a larger file (or /dev/zero, a FIFO) is refused before it is read.
// A GeoJSON MultiPolygon's points are 8 levels deep, a scenario's values 4; a value nested 100,000 deep overflowed the C stack of the code that quoted it. A
// scenario of 10,000 AOIs is 1e5 nodes; a YAML alias expands where it is used, so a "billion
// laughs" file of a kilobyte is 1e9 nodes to whatever walks it, and is refused while it is read.
#pragma once

#include <cstddef>
#include <string>

#include "vistrack/error.hpp"

namespace vistrack::limits {

inline constexpr double kMaxCoordinate = 1e7;  // m
inline constexpr double kMinLength = 1e-6;     // m
inline constexpr double kMaxLength = 1e7;      // m
inline constexpr double kMinSpeed = 1e-6;      // m/s
inline constexpr double kMaxSpeed = 1e4;       // m/s
inline constexpr double kMaxAngle = 1e9;       // rad
inline constexpr double kMaxAltitude = 1e5;    // m (a georeference's origin)
inline constexpr double kMaxVolume = 1e21;     // m^3 (kMaxLength cubed)
inline constexpr int kMaxThreads = 1024;
inline constexpr double kMaxCoordinateOverRho = 1e6;
inline constexpr double kMinGain = 1e-9;               // beta (1/m) and k_psi (1/s)
inline constexpr double kMaxBeta = 1e3;                // 1/m
inline constexpr double kMaxHeadingGain = 1e6;         // 1/s
inline constexpr double kMinRelativeTolerance = 1e-13;
inline constexpr double kMaxRelativeTolerance = 1.0;
inline constexpr double kMinAbsoluteTolerance = 1e-15;
inline constexpr double kMaxAbsoluteTolerance = 1e6;
inline constexpr double kMinRollTimeConstant = 1e-3;  // s
inline constexpr double kMaxRollTimeConstant = 60.0;  // s
inline constexpr double kMinRollRate = 1e-3;          // deg/s
inline constexpr double kMaxRollRate = 1e4;           // deg/s
inline constexpr double kMaxTimeStep = 3600.0;        // s (loiter dt, follow.period)
inline constexpr int kMaxInputFileBytes = 1073741824;  // bytes (1 GiB)
inline constexpr int kMaxDocumentDepth = 100;          // levels of nested lists and mappings
inline constexpr int kMaxDocumentNodes = 1000000;      // values in a YAML document, aliases expanded
inline constexpr double kMaxWorkBytes = 2e9;           // bytes (2 GB): one planned piece of work

// "1.234 GB": bytes to 4 significant digits, for messages.
std::string bytes_text(double bytes);

// "[1e-06, 1e+07] m" style text of a range, for messages.
std::string range_text(double low, double high, const std::string& unit);

}  // namespace vistrack::limits

namespace vistrack {

// Each throws Error "field = value: must be a finite number in [low, high] unit".
void require_in_range(double value, double low, double high, const std::string& unit, const std::string& field);
void require_coordinate(double value, const std::string& field);  // |v| <= 1e7 m
void require_length(double value, const std::string& field);      // [1e-6, 1e7] m
void require_speed(double value, const std::string& field);       // [1e-6, 1e4] m/s
void require_angle(double value, const std::string& field);       // |a| <= 1e9 rad
void require_time_step(double value, const std::string& field);   // (0, 3600] s
void require_threads(int value, const std::string& field);        // [0, 1024]
void require_beta(double value, const std::string& field);          // [1e-9, 1e3] 1/m
void require_heading_gain(double value, const std::string& field);  // [1e-9, 1e6] 1/s
// rtol in [1e-13, 1] and atol in [1e-15, 1e6]; the fields are prefix + "rtol" / "atol".
void require_tolerances(double rtol, double atol, const std::string& prefix);

// Error "field = value: <work> would hold about X GB, above the 2 GB (kMaxWorkBytes) one planned
// piece of work may take: <remedy>" when `bytes` exceeds kMaxWorkBytes (checked before the work).
void require_work_bytes(double bytes, const std::string& field, const std::string& value, const std::string& work,
                        const std::string& remedy);

// Every loader opens its file through this: Error "field = path: ..." for a missing path, a
// symlink loop, a folder (opens as an empty stream on POSIX, read as "the file is empty"),
// anything else that is not a regular file (a FIFO blocks, /dev/zero never ends) or a file above
// kMaxInputFileBytes.
void require_regular_file(const std::string& path, const std::string& field, const std::string& kind);

namespace detail {
// Text taken from an input file, fit to quote in a message: at most `longest` characters (then
// "..."; in single quotes unless `quote` is false), bytes outside printable ASCII as \xNN
// (messages stay valid UTF-8 whatever the file holds).
std::string printable(const std::string& text, bool quote = true, std::size_t longest = 40);
}  // namespace detail

}  // namespace vistrack
