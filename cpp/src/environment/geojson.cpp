// Environment::from_geojson: 2.5D buildings from a GeoJSON FeatureCollection.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>

#include "environment/detail.hpp"
#include "limits/json_input.hpp"
#include "vistrack/error.hpp"
#include "vistrack/limits.hpp"

namespace vistrack {

namespace {

using nlohmann::json;

// A JSON value quoted in a message: compact, at most 40 characters (only that much is walked).
std::string text_of(const json& value) { return detail::json_preview(value); }

// A number, or a numeric string such as "12" or "12.5 m" as OSM tags often are; nothing when
// the property is absent or null.
std::optional<double> number_property(const json& properties, const std::string& key, const std::string& field) {
  const auto it = properties.find(key);
  if (it == properties.end() || it->is_null()) return std::nullopt;
  if (it->is_number()) return it->get<double>();
  if (it->is_string()) {
    const std::string text = it->get<std::string>();
    std::istringstream in(text);
    double value = 0.0;
    if (in >> value) {
      std::string unit;
      in >> unit;
      if (unit.empty() || unit == "m") return value;
    } else if (text == "nan" || text == "NaN" || text == "NAN") {
      return std::nan("");
    }
    detail::fail_field(field, text_of(*it), "expected a number of metres");
  }
  detail::fail_field(field, text_of(*it), "expected a number");
}

Ring ring_from_json(const json& coordinates, const std::string& field) {
  if (!coordinates.is_array()) detail::fail_field(field, text_of(coordinates), "a ring must be an array of [x, y] points");
  Ring ring;
  for (std::size_t i = 0; i < coordinates.size(); ++i) {
    const json& point = coordinates[i];
    if (!point.is_array() || point.size() < 2 || !point[0].is_number() || !point[1].is_number())
      detail::fail_field(field + "[" + std::to_string(i) + "]", text_of(point), "a point must be [x, y] numbers");
    ring.emplace_back(point[0].get<double>(), point[1].get<double>());
  }
  return ring;  // cleaned once in metres (after any projection)
}

Polygon polygon_from_json(const json& rings, const std::string& field, detail::BuildingSource& source) {
  if (!rings.is_array() || rings.empty())
    detail::fail_field(field, text_of(rings), "a Polygon needs at least its outer ring");
  Polygon polygon;
  source.outer_field = field + "[0]";
  polygon.outer = ring_from_json(rings[0], source.outer_field);
  for (std::size_t r = 1; r < rings.size(); ++r) {
    source.hole_fields.push_back(field + "[" + std::to_string(r) + "]");
    polygon.holes.push_back(ring_from_json(rings[r], source.hole_fields.back()));
  }
  return polygon;
}


// Every footprint point, rings in order, as one (n, 2) array and back.
template <typename Visit>
void for_each_ring(std::vector<Building>& buildings, Visit visit) {
  for (Building& building : buildings) {
    visit(building.footprint.outer);
    for (Ring& hole : building.footprint.holes) visit(hole);
  }
}

// GeoJSON's coordinates are WGS84 longitude/latitude (RFC 7946), but files of local metres are
// common too: tell them apart by range. A lon/lat city spans well under a degree; a city in
// metres spans more than a metre and, being local, lies within kMaxLocalMetres of its origin
// (farther out is a projected CRS such as UTM, where float32 ray tracing would also lose
// centimetres).
constexpr double kMaxLocalMetres = 1e5;

enum class Units { metres, degrees };

std::string short_text(double value) {
  std::ostringstream out;
  out.precision(10);
  out << value;
  return out.str();
}

// Longitude/latitude footprints the local projection would misread: one that touches a pole
// (the east-north plane is singular there) or crosses the antimeridian (its longitudes jump by
// 360 degrees, so the whole file spans more than a degree and was read as metres: a 20 m building
// became a 360 m x 0.0002 m sliver). Called when every point lies within the degree ranges and
// the latitudes span less than a degree: a lon/lat file. Refuses naming the feature.
void refuse_singular_lon_lat(const std::vector<Building>& buildings,
                             const std::vector<detail::BuildingSource>& sources, double x_extent) {
  double low = std::numeric_limits<double>::infinity(), high = -low;  // longitudes in [0, 360)
  for (std::size_t b = 0; b < buildings.size(); ++b) {
    const Ring& ring = buildings[b].footprint.outer;
    double west = std::numeric_limits<double>::infinity(), east = -west;
    for (const Vec2& p : ring) {
      if (std::abs(p.y()) >= 90.0)
        detail::fail_field(sources[b].name, "(" + short_text(p.x()) + ", " + short_text(p.y()) + ")",
                           "a longitude/latitude footprint touches a pole, where the local east-north plane is "
                           "singular; give footprints off the pole or in local metres");
      west = std::min(west, p.x());
      east = std::max(east, p.x());
      const double wrapped = p.x() < 0.0 ? p.x() + 360.0 : p.x();
      low = std::min(low, wrapped);
      high = std::max(high, wrapped);
    }
    if (east - west > 180.0)
      detail::fail_field(sources[b].name, "longitudes " + short_text(west) + " to " + short_text(east),
                         "a longitude/latitude footprint crosses the antimeridian (180 degrees); split it there, "
                         "or give local metres");
  }
  if (x_extent >= 1.0 && high - low < 1.0)  // buildings on both sides of the antimeridian
    detail::fail_field("features[*].geometry.coordinates", "longitudes on both sides of 180 degrees",
                       "a longitude/latitude city across the antimeridian; give local metres (or an origin "
                       "and footprints on one side)");
}

Units coordinate_units(std::vector<Building>& buildings, const std::vector<detail::BuildingSource>& sources) {
  Vec2 low = Vec2::Constant(std::numeric_limits<double>::infinity()), high = -low;
  for_each_ring(buildings, [&](const Ring& ring) {
    for (const Vec2& p : ring) {
      low = low.cwiseMin(p);
      high = high.cwiseMax(p);
    }
  });
  const std::string field = "features[*].geometry.coordinates";
  const std::string range = "x in [" + short_text(low.x()) + ", " + short_text(high.x()) + "], y in [" +
                            short_text(low.y()) + ", " + short_text(high.y()) + "]";
  const std::string neither = "neither WGS84 longitude/latitude degrees (|x| <= 180, |y| <= 90, spanning less than "
                              "1 degree) nor local east-north metres (spanning more than 1 m, within " +
                              short_text(kMaxLocalMetres / 1000.0) + " km of the origin)";
  const double extent = (high - low).maxCoeff();
  if (low.x() >= -180.0 && high.x() <= 180.0 && low.y() >= -90.0 && high.y() <= 90.0 && high.y() - low.y() < 1.0)
    refuse_singular_lon_lat(buildings, sources, high.x() - low.x());
  if (extent < 1.0) {
    if (low.x() >= -180.0 && high.x() <= 180.0 && low.y() >= -90.0 && high.y() <= 90.0) return Units::degrees;
    detail::fail_field(field, range, neither);
  }
  if (std::max(low.cwiseAbs().maxCoeff(), high.cwiseAbs().maxCoeff()) > kMaxLocalMetres)
    detail::fail_field(field, range, neither + " (a projected CRS such as UTM? give WGS84 longitude/latitude)");
  return Units::metres;
}

// Projects longitude/latitude footprints to local metres in place; returns the environment's
// origin (the given one, or the centre of the data's bounding box rounded to 1e-7 degree).
std::optional<GeodeticPoint> to_local_metres(std::vector<Building>& buildings,
                                             const std::vector<detail::BuildingSource>& sources,
                                             const GeoJsonOptions& options) {
  if (options.origin) validate_geodetic_point(*options.origin, "origin");
  if (coordinate_units(buildings, sources) == Units::metres) return options.origin;
  std::size_t count = 0;
  for_each_ring(buildings, [&](const Ring& ring) { count += ring.size(); });
  Points2 lon_lat(static_cast<Eigen::Index>(count), 2);
  Eigen::Index row = 0;
  for_each_ring(buildings, [&](const Ring& ring) {
    for (const Vec2& p : ring) lon_lat.row(row++) = p.transpose();
  });
  if (!options.project)
    detail::fail_field("features[*].geometry.coordinates", "longitude/latitude degrees",
                       "this loader has no projection to local metres (vistrack.Environment.from_geojson in Python "
                       "projects with pyproj; C++ callers pass GeoJsonOptions::project)");
  GeodeticPoint origin;
  if (options.origin) {
    origin = *options.origin;
  } else {
    const Vec2 centre = 0.5 * (lon_lat.colwise().minCoeff() + lon_lat.colwise().maxCoeff()).transpose();
    origin.longitude = std::round(centre.x() * 1e7) / 1e7;
    origin.latitude = std::round(centre.y() * 1e7) / 1e7;
  }
  const Points2 local = options.project(lon_lat, origin);
  if (local.rows() != lon_lat.rows() || !local.allFinite())
    detail::fail_field("project", std::to_string(local.rows()) + " rows",
                       "the projection must return one finite (east, north) row per input point (" +
                           std::to_string(lon_lat.rows()) + ")");
  row = 0;
  for_each_ring(buildings, [&](Ring& ring) {
    for (Vec2& p : ring) p = local.row(row++).transpose();
  });
  return origin;
}

// The buildings of a parsed FeatureCollection, each with the fields it came from.
void read_features(const json& root, std::vector<Building>& buildings, std::vector<detail::BuildingSource>& sources) {
  if (!root.is_object() || !root.contains("type") || root["type"] != "FeatureCollection")
    detail::fail_field("type", root.is_object() && root.contains("type") ? text_of(root["type"]) : std::string("missing"),
                       "expected a GeoJSON FeatureCollection");
  const auto features = root.find("features");
  if (features == root.end() || !features->is_array())
    detail::fail_field("features", features == root.end() ? std::string("missing") : text_of(*features),
                       "expected an array of features");
  if (features->empty()) detail::fail_field("features", "[]", "the collection has no buildings");

  for (std::size_t f = 0; f < features->size(); ++f) {
    const json& feature = (*features)[f];
    const std::string name = "features[" + std::to_string(f) + "]";
    static const json kNoProperties = json::object();
    const json& properties = feature.contains("properties") && feature["properties"].is_object()
                                 ? feature["properties"] : kNoProperties;
    int id = static_cast<int>(f);
    if (const auto it = properties.find("id"); it != properties.end() && it->is_number_integer())
      id = it->get<int>();
    double height = 0.0;
    std::string height_field = name + ".properties.height";
    if (const auto h = number_property(properties, "height", height_field)) {
      height = *h;
    } else if (const auto levels = number_property(properties, "building:levels", name + ".properties.building:levels")) {
      height_field = name + ".properties.building:levels";
      require_positive(*levels, height_field);
      height = 3.0 * *levels;  // 3 m per storey
    } else {
      detail::fail_field(height_field, "missing", "each building needs properties.height or building:levels");
    }
    // The base (OSM's min_height: the height above the ground where a raised part starts).
    const std::string min_height_field = name + ".properties.min_height";
    const double min_height = number_property(properties, "min_height", min_height_field).value_or(0.0);
    if (!feature.contains("geometry") || !feature["geometry"].is_object())
      detail::fail_field(name + ".geometry", "missing", "each feature needs a Polygon or MultiPolygon geometry");
    const json& geometry = feature["geometry"];
    const std::string type = geometry.value("type", std::string());
    const std::string coordinates_field = name + ".geometry.coordinates";
    if (!geometry.contains("coordinates"))
      detail::fail_field(coordinates_field, "missing", "the geometry has no coordinates");
    const json& coordinates = geometry["coordinates"];
    if (type == "Polygon") {
      detail::BuildingSource source{name, height_field, {}, {}, min_height_field};
      Building building{polygon_from_json(coordinates, coordinates_field, source), height, id, min_height};
      buildings.push_back(std::move(building));
      sources.push_back(std::move(source));
    } else if (type == "MultiPolygon") {
      if (!coordinates.is_array() || coordinates.empty())
        detail::fail_field(coordinates_field, text_of(coordinates), "a MultiPolygon needs at least one polygon");
      // Each part becomes its own building with the feature's id and height.
      for (std::size_t p = 0; p < coordinates.size(); ++p) {
        detail::BuildingSource source{name + ".geometry.coordinates[" + std::to_string(p) + "]", height_field, {}, {},
                                      min_height_field};
        Building building{polygon_from_json(coordinates[p], coordinates_field + "[" + std::to_string(p) + "]", source),
                          height, id, min_height};
        buildings.push_back(std::move(building));
        sources.push_back(std::move(source));
      }
    } else {
      detail::fail_field(name + ".geometry.type", text_of(json(type)), "expected Polygon or MultiPolygon");
    }
  }
}

}  // namespace

Environment Environment::from_geojson(const std::string& path, const GeoJsonOptions& options) {
  require_regular_file(path, "path", "GeoJSON");
  std::ifstream in(path, std::ios::binary);
  if (!in) detail::fail_field("path", path, "cannot open the GeoJSON file for reading");
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  if (text.find_first_not_of(" \t\r\n") == std::string::npos)
    detail::fail_field("path", path, "the GeoJSON file is empty");
  const json root = detail::parse_json(text, "path = " + path);
  std::vector<Building> buildings;
  std::vector<detail::BuildingSource> sources;
  try {
    read_features(root, buildings, sources);
  } catch (const json::exception& error) {  // a member of an unexpected JSON type
    detail::fail_field("path", path, std::string("unexpected GeoJSON structure: ") + error.what());
  }
  const std::optional<GeodeticPoint> origin = to_local_metres(buildings, sources, options);
  for (Building& building : buildings) {
    building.footprint.outer = detail::clean_ring(building.footprint.outer);
    for (Ring& hole : building.footprint.holes) hole = detail::clean_ring(hole);
  }
  detail::validate_buildings(buildings, sources);
  Environment env = from_validated_buildings(std::move(buildings));
  env.set_origin(origin);
  return env;
}

}  // namespace vistrack
