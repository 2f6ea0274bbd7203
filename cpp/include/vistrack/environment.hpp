// The world the UAV flies in: 2.5D buildings or an arbitrary triangle mesh, the ground, the
// road network, and the point of interest (POI) moving along it. Section III.B-C of the
// visibility-volume paper.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "vistrack/geometry.hpp"

namespace vistrack {

// An extruded footprint B_i = A_i x [b_i, h_i]: section III.B's A_i x [0, h_i] with a base b_i
// (OSM's min_height: a building:part raised over the ground, a bridge, an overhang), so that the
// space under a raised part stays open for lines of sight.
struct Building {
  Polygon footprint;  // normalised: outer counter-clockwise, holes clockwise
  double height = 0.0;      // the top, metres above the ground
  int id = 0;               // from properties.id when present, else the feature index
  double min_height = 0.0;  // the base, metres above the ground: 0 <= min_height < height
};

// Graph G = (N, E) of road nodes on the ground plane. An edge is driven both ways unless
// oneway[e] is set: then only from edges[e].first to edges[e].second (a one-way street).
// oneway is empty (every edge two-way) or holds one flag per edge.
struct RoadNetwork {
  std::vector<Vec2> nodes;
  std::vector<std::pair<int, int>> edges;
  std::vector<bool> oneway{};
  bool is_oneway(std::size_t edge) const { return edge < oneway.size() && oneway[edge]; }
};

// Error naming the node or edge for a node outside the coordinate range (|v| <= 1e7 m), an edge
// index out of range, an edge joining a node to itself or two nodes at one place, or a oneway
// list whose length is neither 0 nor the number of edges.
void validate_road_network(const RoadNetwork& roads, const std::string& field = "roads");

// Nodes of a shortest route along road edges (Dijkstra, edge length = Euclidean distance),
// from `from` to `to` inclusive, one-way edges driven only their way. Error when a node does not
// exist or `to` is unreachable (saying so when only one-way streets prevent the route).
std::vector<int> shortest_route(const RoadNetwork& roads, int from, int to);

// A closed triangle mesh: vertices (n, 3) and faces (m, 3) indexing them.
struct TriangleMesh {
  Points3 vertices;
  Faces faces;
};

// Throws Error naming `field` for a mesh with no faces, a vertex outside the coordinate range
// (|v| <= 1e7 m, vistrack/limits.hpp) or a face index out of range; every function taking triangles from outside checks them with this.
void validate_triangle_mesh(const Points3& vertices, const Faces& faces, const std::string& field = "mesh");

// Where the local east-north-up frame is anchored on the Earth: WGS84 latitude and longitude in
// degrees and the altitude of local z = 0 in metres.
struct GeodeticPoint {
  double latitude = 0.0;
  double longitude = 0.0;
  double altitude = 0.0;
};
// Throws Error naming `field` for a latitude outside [-90, 90], a longitude outside [-180, 180]
// or a non-finite value.
void validate_geodetic_point(const GeodeticPoint& point, const std::string& field = "origin");

// Projects WGS84 (longitude, latitude) degrees, one row per point, to local east-north metres
// about `origin`. vistrack's is vistrack.mission.Georeference (pyproj's topocentric conversion),
// which the Python binding passes in; the C++ library carries no geodesy of its own.
using LonLatProjection = std::function<Points2(const Points2& lon_lat, const GeodeticPoint& origin)>;

// How from_geojson reads coordinates. Local metres are read as they are; WGS84 longitude/latitude
// (the GeoJSON default, what OpenStreetMap exports give) is projected with `project` about
// `origin`, or about the centre of the data's bounding box when no origin is given.
struct GeoJsonOptions {
  std::optional<GeodeticPoint> origin;
  LonLatProjection project;
};

class Environment {
 public:
  // 2.5D buildings from a GeoJSON FeatureCollection of Polygon / MultiPolygon features with
  // properties.height (or building:levels x 3 m) and optional properties.min_height (the base,
  // default 0, below the top). Validates every footprint (simple, at least
  // 3 points, positive finite height, disjoint interiors). Coordinates are local east-north
  // metres or WGS84 longitude/latitude degrees (told apart by their range; anything else is an
  // Error); degrees need options.project. The environment's origin() is options.origin, or the
  // one a longitude/latitude file was projected about.
  static Environment from_geojson(const std::string& path, const GeoJsonOptions& options = {});
  // Validated buildings plus optional roads (each edge checked against every footprint).
  // Footprints may overlap by at most 1 m^2 (walls drawn approximately), unless their heights
  // [min_height, height] do not overlap (parts stacked one on another); a footprint lying inside
  // another building whose [min_height, height] contains its own is accepted (a building part
  // drawn inside its outline adds nothing to the obstacles).
  static Environment from_buildings(std::vector<Building> buildings, RoadNetwork roads = {});
  // Any triangle mesh file (OBJ, PLY, STL, OFF). up = "z", or "y" for Y-up files whose north
  // is -Z: (east, north, up) = (x, -z, y).
  static Environment from_mesh(const std::string& path, const std::string& up = "z");
  // Triangles already in east-north-up metres.
  static Environment from_triangles(Points3 vertices, Faces faces);
  // The embedded synthetic downtown: a street grid (the road network) and blocks of buildings
  // from 10 to 150 m. Deterministic.
  static Environment demo();

  // Every obstacle triangle (buildings or mesh), without the ground plane.
  const TriangleMesh& mesh() const { return mesh_; }
  std::size_t num_triangles() const { return static_cast<std::size_t>(mesh_.faces.rows()); }
  // Tallest point of any obstacle above the ground level.
  double max_height() const;
  // Height of the ground plane (0 for buildings; the lowest vertex for a mesh).
  double ground_level() const { return ground_level_; }
  Bounds3 bounds() const { return bounds_; }
  // Empty for an environment made from a mesh.
  const std::vector<Building>& buildings() const { return buildings_; }
  std::vector<Polygon> footprints() const;
  std::vector<double> heights() const;
  std::vector<double> min_heights() const;  // the buildings' bases
  std::size_t num_buildings() const { return buildings_.size(); }
  const RoadNetwork& roads() const { return roads_; }
  // Replaces the road network after checking the nodes (finite), the edges (valid, distinct
  // nodes) and that no edge crosses a building footprint's interior (running along a wall is
  // allowed). An environment made from a mesh has no footprints to check against.
  void set_roads(RoadNetwork roads);
  // A deterministic content hash (geometry and roads), for caches keyed by environment.
  std::uint64_t fingerprint() const;
  // Where local (0, 0, 0) lies on the Earth, when known; not part of the fingerprint.
  const std::optional<GeodeticPoint>& origin() const { return origin_; }
  void set_origin(const std::optional<GeodeticPoint>& origin);  // validated

 private:
  // Buildings already validated and normalised: extrudes them, ground level 0.
  static Environment from_validated_buildings(std::vector<Building> buildings);

  std::vector<Building> buildings_;
  RoadNetwork roads_;
  TriangleMesh mesh_;
  Bounds3 bounds_{};
  double ground_level_ = 0.0;
  std::optional<GeodeticPoint> origin_;
};

// A POI moving at constant speed through waypoints (section III.C): piecewise-linear
// g(t) = p_i + v_g (t - t_i) (p_j - p_i) / |p_j - p_i|.
class PoiPath {
 public:
  // Waypoints (n, 2) or (n, 3) within the coordinate range (|v| <= 1e7 m); consecutive repeated
  // points are dropped; at least two distinct points; speed in [1e-6, 1e4] m/s.
  PoiPath(const Eigen::MatrixXd& waypoints, double speed);
  // CSV with one waypoint per line "x,y[,z]"; blank lines and lines starting with '#' are skipped,
  // and so is a first line whose first field is not a number (a header such as "x,y,z"). Any other
  // field that is not a number is an Error naming the line.
  static PoiPath from_csv(const std::string& path, double speed);
  // Through a sequence of road-network nodes, each consecutive pair joined by an edge.
  static PoiPath from_nodes(const RoadNetwork& roads, const std::vector<int>& nodes, double speed);

  Vec3 position(double t) const;   // clamped to [0, duration]
  Vec2 velocity(double t) const;   // of the segment containing t (right-continuous)
  double heading(double t) const;  // gamma, direction of the velocity
  const std::vector<double>& node_times() const { return node_times_; }  // t_i
  const Points3& waypoints() const { return waypoints_; }
  double speed() const { return speed_; }
  double duration() const { return node_times_.back(); }
  double length() const { return duration() * speed_; }

 private:
  Points3 waypoints_;
  std::vector<double> node_times_;
  double speed_ = 0.0;
};

}  // namespace vistrack
