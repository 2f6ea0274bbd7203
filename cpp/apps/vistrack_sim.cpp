// vistrack_sim: the closed loop of section VI from an orbit-plan JSON, without Python.
//
//   vistrack_sim --plan plan.json --out trajectory.csv [--speed 20] [--min-turn-radius 50]
//                [--altitude 300] [--beta 0.025] [--k-psi 20] [--direction ccw]
//                [--x0 X,Y,PSI] [--rtol 1e-6] [--atol 1e-8] [--max-step 1] [--output-step 0.1]
//                [--fixed-step 0] [--map city.geojson|mesh.obj [--up y|z]]
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>

#include "vistrack/environment.hpp"
#include "vistrack/error.hpp"
#include "vistrack/orbit.hpp"
#include "vistrack/simulate.hpp"
#include "vistrack/visibility.hpp"

#include "app_arguments.hpp"

namespace {

const char* kUsage =
    "usage: vistrack_sim --plan PLAN.json [--out TRAJECTORY.csv] [--speed V] [--min-turn-radius R]\n"
    "                    [--altitude H] [--beta B] [--k-psi K] [--direction ccw|cw] [--x0 X,Y,PSI]\n"
    "                    [--rtol R] [--atol A] [--max-step S] [--output-step S] [--fixed-step S]\n"
    "                    [--map CITY.geojson|MESH.obj [--up y|z]]\n"
    "Simulates the Dubins UAV steered by the guidance law (86) around the plan's orbits and writes\n"
    "the trajectory CSV (stdout without --out). Defaults: the Uav, Control, SimulationOptions\n"
    "defaults of vistrack; x0 starts on the first orbit, heading north. With --map, the line of\n"
    "sight UAV -> POI (Embree) is added as a column `visible` and its fraction is printed.\n";

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) vistrack::detail::fail_field("--plan", path, "cannot open the file for reading");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

int main(int argc, char** argv) {
  try {
    std::map<std::string, std::string> flags;
    for (int i = 1; i < argc; ++i) {
      const std::string flag = argv[i];
      if (flag == "--help" || flag == "-h") {
        std::cout << kUsage;
        return 0;
      }
      if (flag.rfind("--", 0) != 0 || i + 1 >= argc)
        vistrack::detail::fail_field("argument", flag, "expected --flag VALUE (see --help)");
      flags[flag] = argv[++i];
    }
    const char* known[] = {"--plan", "--out", "--speed", "--min-turn-radius", "--altitude", "--beta", "--k-psi",
                           "--direction", "--x0", "--rtol", "--atol", "--max-step", "--output-step", "--fixed-step",
                           "--map", "--up"};
    for (const auto& [flag, value] : flags) {
      bool ok = false;
      for (const char* k : known) ok = ok || flag == k;
      if (!ok) vistrack::detail::fail_field("argument", flag, "unknown flag (see --help)");
    }
    if (!flags.count("--plan")) {
      std::cerr << kUsage;
      return 2;
    }
    const vistrack::OrbitPlan plan = vistrack::orbit_plan_from_json(read_file(flags["--plan"]));
    vistrack::Uav uav;
    vistrack::Control control;
    vistrack::SimulationOptions options;
    double fixed_step = 0.0;
    auto set = [&](const char* flag, double& target) {
      if (flags.count(flag)) target = vistrack::apps::number(flag, flags[flag]);
    };
    set("--speed", uav.speed);
    set("--min-turn-radius", uav.min_turn_radius);
    set("--altitude", uav.altitude);
    set("--beta", control.beta);
    set("--k-psi", control.k_psi);
    set("--rtol", options.rtol);
    set("--atol", options.atol);
    set("--max-step", options.max_step);
    set("--output-step", options.output_step);
    set("--fixed-step", fixed_step);
    if (flags.count("--direction")) control.direction = vistrack::from_name<vistrack::Circulation>(flags["--direction"], "--direction");

    vistrack::Vec3 x0;
    if (flags.count("--x0")) {
      std::string text = flags["--x0"];
      for (char& c : text)
        if (c == ',') c = ' ';
      std::istringstream in(text);
      std::string a, b, c, extra;
      if (!(in >> a >> b >> c) || (in >> extra))
        vistrack::detail::fail_field("--x0", flags["--x0"], "expected X,Y,PSI");
      x0 = vistrack::Vec3(vistrack::apps::number("--x0", a), vistrack::apps::number("--x0", b), vistrack::apps::number("--x0", c));
    } else {
      const vistrack::Vec3 g = plan.poi.position(plan.times.front());
      x0 = vistrack::Vec3(g.x() + plan.radii.front(), g.y(), vistrack::kPi / 2);
    }

    vistrack::SimulationResult result;
    if (flags.count("--map")) {
      const std::string& map = flags["--map"];
      const std::string extension = std::filesystem::path(map).extension().string();
      const vistrack::Environment env =
          extension == ".geojson" || extension == ".json"
              ? vistrack::Environment::from_geojson(map)
              : vistrack::Environment::from_mesh(map, flags.count("--up") ? flags["--up"] : std::string("y"));
      result = vistrack::simulate(plan, uav, x0, control, options, vistrack::VisibilityScene(env), fixed_step);
    } else {
      result = vistrack::simulate(plan, uav, x0, control, options, vistrack::LineOfSight{}, fixed_step);
    }
    const std::string csv = vistrack::trajectory_csv(result);
    if (flags.count("--out")) {
      std::ofstream out(flags["--out"]);
      if (!out) vistrack::detail::fail_field("--out", flags["--out"], "cannot open the file for writing");
      out << csv;
      if (!out) vistrack::detail::fail_field("--out", flags["--out"], "write failed");
    } else {
      std::cout << csv;
    }
    std::fprintf(stderr, "vistrack_sim: %zu samples, %zu steps, %zu right-hand side evaluations\n", result.t.size(),
                 result.statistics.accepted_steps, result.statistics.rhs_evaluations);
    if (result.visibility_fraction)
      std::fprintf(stderr, "vistrack_sim: POI in line of sight at %.1f%% of the samples\n",
                   100.0 * *result.visibility_fraction);
    return 0;
  } catch (const std::exception& error) {
    std::cerr << "vistrack_sim: error: " << error.what() << "\n";
    return 2;
  }
}
