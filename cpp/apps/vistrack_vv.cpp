// vistrack_vv: visibility volumes, visibility polygons and MaxRadius without Python.
//
//   vistrack_vv --map city.geojson|mesh.obj [--up y] (--path poi.csv [--spacing 20] | --points "x,y[,z];...")
//               [--d-max 400] [--altitude 300] [--band H_LO H_HI] [--resolution 1] [--out DIR]
//               [--no-meshes] [--check]
//
// Writes DIR/volumes.json (same fields as `vistrack volumes`), DIR/vv_###.ply and DIR/plan.svg
// (VPs, inscribed circles and footprints from above).
#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "vistrack/environment.hpp"
#include "vistrack/error.hpp"
#include "vistrack/orbit.hpp"
#include "vistrack/visibility.hpp"
#include "vistrack/volume.hpp"

#include "app_arguments.hpp"

namespace fs = std::filesystem;
using namespace vistrack;

namespace {

struct Options {
  std::string map;
  std::string up = "z";
  std::string path;
  std::string points;
  double spacing = Planning{}.spacing;
  double d_max = Sensor{}.d_max;
  double altitude = Uav{}.altitude;
  std::optional<std::pair<double, double>> band;
  double resolution = kDefaultResolutionDeg;
  std::string out = "vistrack-out/volumes";
  bool meshes = true;
  bool check = false;
};

void usage() {
  std::cerr << "usage: vistrack_vv --map FILE [--up z|y] (--path CSV [--spacing M] | --points \"x,y[,z];...\")\n"
               "                   [--d-max M] [--altitude Z] [--band H_LO H_HI] [--resolution DEG] [--out DIR]\n"
               "                   [--no-meshes] [--check]\n";
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    auto next = [&]() -> std::string {
      if (i + 1 >= argc) throw Error(flag + ": missing value");
      return argv[++i];
    };
    if (flag == "--map") o.map = next();
    else if (flag == "--up") o.up = next();
    else if (flag == "--path") o.path = next();
    else if (flag == "--points") o.points = next();
    else if (flag == "--spacing") o.spacing = vistrack::apps::number(flag, next());
    else if (flag == "--d-max") o.d_max = vistrack::apps::number(flag, next());
    else if (flag == "--altitude") o.altitude = vistrack::apps::number(flag, next());
    else if (flag == "--band") {
      const double lo = vistrack::apps::number(flag, next());
      o.band = std::make_pair(lo, vistrack::apps::number(flag, next()));
    } else if (flag == "--resolution") o.resolution = vistrack::apps::number(flag, next());
    else if (flag == "--out") o.out = next();
    else if (flag == "--no-meshes") o.meshes = false;
    else if (flag == "--check") o.check = true;
    else if (flag == "--help" || flag == "-h") {
      usage();
      std::exit(0);
    } else {
      throw Error("unknown option " + flag);
    }
  }
  if (o.map.empty()) throw Error("--map is required");
  if (o.path.empty() == o.points.empty()) throw Error("give exactly one of --path and --points");
  return o;
}

Environment load_map(const Options& o) {
  if (!fs::is_regular_file(o.map)) detail::fail_field("--map", o.map, "no such file");
  const std::string ext = fs::path(o.map).extension().string();
  if (ext == ".geojson" || ext == ".json") return Environment::from_geojson(o.map);
  return Environment::from_mesh(o.map, o.up);
}

// POI positions every `spacing` metres along the path (ends included) or the given points; a POI
// under the surface (uneven terrain) or without z is put 0.5 m above the surface.
Points3 poi_positions(const Options& o, const VisibilityScene& scene) {
  std::vector<Vec3> points;
  if (!o.path.empty()) {
    require_positive(o.spacing, "--spacing");
    const PoiPath poi = PoiPath::from_csv(o.path, 1.0);  // speed 1: time = arc length
    const int count = std::max(2, static_cast<int>(std::ceil(poi.length() / o.spacing)) + 1);
    for (int k = 0; k < count; ++k) points.push_back(poi.position(poi.length() * k / (count - 1)));
  } else {
    std::stringstream items(o.points);
    std::string item;
    int index = 0;
    while (std::getline(items, item, ';')) {
      if (item.empty()) continue;
      std::vector<double> values;
      std::stringstream fields(item);
      std::string field;
      while (std::getline(fields, field, ',')) values.push_back(vistrack::apps::number("--points[" + std::to_string(index) + "]", field));
      if (values.size() < 2 || values.size() > 3)
        detail::fail_field("--points[" + std::to_string(index) + "]", item, "expected x,y or x,y,z");
      points.emplace_back(values[0], values[1], values.size() == 3 ? values[2] : std::nan(""));
      ++index;
    }
    if (points.empty()) detail::fail_field("--points", o.points, "no points");
  }
  Points3 out(static_cast<Eigen::Index>(points.size()), 3);
  for (std::size_t k = 0; k < points.size(); ++k) {
    Vec3 p = points[k];
    const double surface = scene.surface_height(p.head<2>());
    if (!std::isfinite(p.z()) || p.z() < surface) p.z() = surface + 0.5;
    out.row(static_cast<Eigen::Index>(k)) = p.transpose();
  }
  return out;
}

nlohmann::json ring_json(const Ring& ring) {
  nlohmann::json out = nlohmann::json::array();
  for (const Vec2& p : ring) out.push_back({p.x(), p.y()});
  return out;
}

std::string svg_path(const Ring& ring, double y_flip) {
  std::ostringstream d;
  for (std::size_t k = 0; k < ring.size(); ++k) d << (k ? 'L' : 'M') << ring[k].x() << ',' << y_flip - ring[k].y();
  d << 'Z';
  return d.str();
}

void write_svg(const std::string& file, const Environment& env, const Points3& pois,
               const std::vector<std::vector<Polygon>>& vps, const std::vector<double>& radii, const Options& o) {
  const Vec2 lo = pois.colwise().minCoeff().head<2>().transpose() - Vec2::Constant(o.d_max);
  const Vec2 hi = pois.colwise().maxCoeff().head<2>().transpose() + Vec2::Constant(o.d_max);
  std::ofstream svg(file);
  svg << "<svg xmlns='http://www.w3.org/2000/svg' viewBox='" << lo.x() << ' ' << -hi.y() << ' ' << (hi - lo).x() << ' '
      << (hi - lo).y() << "' width='900' height='" << 900.0 * (hi - lo).y() / (hi - lo).x() << "'>\n"
      << "<rect x='" << lo.x() << "' y='" << -hi.y() << "' width='" << (hi - lo).x() << "' height='" << (hi - lo).y()
      << "' fill='#eee'/>\n";
  // Buildings: footprints, or the mesh's triangles from above.
  svg << "<g fill='#9ecae1' stroke='#3182bd' stroke-width='0.3'>\n";
  if (!env.buildings().empty()) {
    for (const Polygon& f : env.footprints()) {
      svg << "<path fill-rule='evenodd' d='" << svg_path(f.outer, 0.0);
      for (const Ring& h : f.holes) svg << svg_path(h, 0.0);
      svg << "'/>\n";
    }
  } else {
    const TriangleMesh& m = env.mesh();
    for (Eigen::Index t = 0; t < m.faces.rows(); ++t) {
      Ring tri;
      double top = -1e300;
      for (int c = 0; c < 3; ++c) {
        tri.emplace_back(m.vertices(m.faces(t, c), 0), m.vertices(m.faces(t, c), 1));
        top = std::max(top, m.vertices(m.faces(t, c), 2));
      }
      if (top > env.ground_level() + 0.5 && std::abs(signed_area(tri)) > 1e-6) svg << "<path d='" << svg_path(tri, 0.0) << "'/>\n";
    }
  }
  svg << "</g>\n";
  const char* colors[2] = {"magenta", "darkcyan"};
  const std::size_t picks[2] = {0, static_cast<std::size_t>(pois.rows()) - 1};
  for (int c = 0; c < (pois.rows() > 1 ? 2 : 1); ++c)
    for (const Polygon& p : vps[picks[c]]) {
      svg << "<path fill='" << colors[c] << "' fill-opacity='0.18' stroke='" << colors[c]
          << "' stroke-width='1' fill-rule='evenodd' d='" << svg_path(p.outer, 0.0);
      for (const Ring& h : p.holes) svg << svg_path(h, 0.0);
      svg << "'/>\n";
    }
  for (Eigen::Index k = 0; k < pois.rows(); ++k) {
    const char* color = k == 0 ? colors[0] : (k == pois.rows() - 1 ? colors[1] : "#555");
    svg << "<circle cx='" << pois(k, 0) << "' cy='" << -pois(k, 1) << "' r='" << radii[static_cast<std::size_t>(k)]
        << "' fill='none' stroke='" << color << "' stroke-dasharray='4 3'/>\n"
        << "<circle cx='" << pois(k, 0) << "' cy='" << -pois(k, 1) << "' r='2' fill='" << color << "'/>\n";
  }
  svg << "<text x='" << lo.x() + 5 << "' y='" << -lo.y() - 5 << "' font-size='9' fill='#555'>VPs at z = " << o.altitude
      << " m, map " << fs::path(o.map).filename().string() << "</text>\n</svg>\n";
}

int run(const Options& o) {
  const auto started = std::chrono::steady_clock::now();
  const Environment env = load_map(o);
  const VisibilityScene scene(env);
  const Points3 pois = poi_positions(o, scene);
  fs::create_directories(o.out);
  nlohmann::json records = nlohmann::json::array();
  std::vector<std::vector<Polygon>> vps;
  std::vector<double> radii;
  constexpr Eigen::Index kBatch = 8;
  for (Eigen::Index start = 0; start < pois.rows(); start += kBatch) {
    const Eigen::Index count = std::min(kBatch, pois.rows() - start);
    const std::vector<VisibilityVolume> batch = visibility_volumes(scene, pois.middleRows(start, count), o.d_max, o.band, o.resolution);
    for (Eigen::Index i = 0; i < count; ++i) {
      const VisibilityVolume& vv = batch[static_cast<std::size_t>(i)];
      const Eigen::Index k = start + i;
      std::vector<Polygon> vp = visibility_polygon(vv, o.altitude);
      const double radius = max_inscribed_radius(vp, vv.poi.head<2>());
      nlohmann::json record = {{"index", k},
                               {"poi", {vv.poi.x(), vv.poi.y(), vv.poi.z()}},
                               {"volume", vv.volume},
                               {"grid_volume", vv.grid_volume()},
                               {"max_radius", radius}};
      nlohmann::json polygons = nlohmann::json::array();
      for (const Polygon& p : vp) {
        nlohmann::json holes = nlohmann::json::array();
        for (const Ring& h : p.holes) holes.push_back(ring_json(h));
        polygons.push_back({{"outer", ring_json(p.outer)}, {"holes", holes}, {"area", area(p)}});
      }
      record["visibility_polygon"] = polygons;
      if (o.meshes) {
        char name[32];
        std::snprintf(name, sizeof(name), "vv_%03d.ply", static_cast<int>(k));
        vv.save((fs::path(o.out) / name).string());
        record["mesh"] = name;
      }
      if (o.check) {
        const MeshCheck check = check_closed_mesh(vv.mesh);
        record["mesh_valid"] = check.valid();
        record["mesh_problem"] = check.problem;
      }
      records.push_back(record);
      vps.push_back(std::move(vp));
      radii.push_back(radius);
    }
    std::cerr << "\rvisibility volumes: " << start + count << "/" << pois.rows() << std::flush;
  }
  std::cerr << "\n";
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  nlohmann::json summary = {{"format", "vistrack.volumes/1"}, {"map", o.map},           {"d_max", o.d_max},
                            {"altitude", o.altitude},         {"resolution_deg", o.resolution}, {"seconds", seconds},
                            {"points", records}};
  summary["altitude_band"] = o.band ? nlohmann::json{o.band->first, o.band->second} : nlohmann::json(nullptr);
  std::ofstream(fs::path(o.out) / "volumes.json") << summary.dump(1) << '\n';
  write_svg((fs::path(o.out) / "plan.svg").string(), env, pois, vps, radii, o);
  std::cout << records.size() << " VVs in " << seconds << " s; wrote " << o.out << '\n';
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(parse(argc, argv));
  } catch (const std::exception& error) {
    std::cerr << "vistrack_vv: error: " << error.what() << '\n';
    usage();
    return 2;
  }
}
