#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <optional>
#include <tuple>
#include <vector>

#include "bindings.hpp"
#include "vistrack/environment.hpp"
#include "vistrack/error.hpp"

namespace py = pybind11;

namespace vistrack::bindings {

namespace {

using Edges = Eigen::Matrix<std::int64_t, Eigen::Dynamic, 2, Eigen::RowMajor>;

RoadNetwork roads_from_arrays(const Points2& nodes, const Edges& edges, const std::optional<std::vector<bool>>& oneway) {
  RoadNetwork roads;
  if (oneway) roads.oneway = *oneway;
  for (Eigen::Index i = 0; i < nodes.rows(); ++i) roads.nodes.emplace_back(nodes(i, 0), nodes(i, 1));
  for (Eigen::Index e = 0; e < edges.rows(); ++e) {
    for (int k = 0; k < 2; ++k)
      if (edges(e, k) < 0 || edges(e, k) > std::numeric_limits<int>::max())
        detail::fail_field("edges[" + std::to_string(e) + "][" + std::to_string(k) + "]", edges(e, k),
                           "must be a node index");
    roads.edges.emplace_back(static_cast<int>(edges(e, 0)), static_cast<int>(edges(e, 1)));
  }
  validate_road_network(roads, "");  // NaN nodes or edges to no node are refused here, not later
  return roads;
}

Points2 nodes_array(const RoadNetwork& roads) {
  Points2 nodes(static_cast<Eigen::Index>(roads.nodes.size()), 2);
  for (std::size_t i = 0; i < roads.nodes.size(); ++i) nodes.row(static_cast<Eigen::Index>(i)) = roads.nodes[i].transpose();
  return nodes;
}

Edges edges_array(const RoadNetwork& roads) {
  Edges edges(static_cast<Eigen::Index>(roads.edges.size()), 2);
  for (std::size_t e = 0; e < roads.edges.size(); ++e)
    edges.row(static_cast<Eigen::Index>(e)) << roads.edges[e].first, roads.edges[e].second;
  return edges;
}

Eigen::Array<bool, Eigen::Dynamic, 1> oneway_array(const RoadNetwork& roads) {
  Eigen::Array<bool, Eigen::Dynamic, 1> flags(static_cast<Eigen::Index>(roads.edges.size()));
  for (std::size_t e = 0; e < roads.edges.size(); ++e) flags(static_cast<Eigen::Index>(e)) = roads.is_oneway(e);
  return flags;
}

// Items (Polygon, height), (Polygon, height, id) or (Polygon, height, id, min_height); the id
// defaults to the position, the base to 0.
std::vector<Building> buildings_from_python(const py::iterable& items) {
  std::vector<Building> buildings;
  for (const py::handle item : items) {
    const std::string field = "buildings[" + std::to_string(buildings.size()) + "]";
    const auto entry = py::reinterpret_borrow<py::sequence>(item);
    if (entry.size() < 2 || entry.size() > 4)
      detail::fail_field(field, py::str(item).cast<std::string>(),
                         "expected (Polygon, height), (Polygon, height, id) or (Polygon, height, id, min_height)");
    Building building;
    if (py::isinstance<Polygon>(entry[0])) building.footprint = entry[0].cast<Polygon>();
    else building.footprint.outer = ring_from_array(entry[0].cast<Points2>(), field + "[0]");  // an (n, 2) array
    building.height = entry[1].cast<double>();
    building.id = entry.size() >= 3 ? entry[2].cast<int>() : static_cast<int>(buildings.size());
    if (entry.size() == 4) building.min_height = entry[3].cast<double>();
    buildings.push_back(std::move(building));
  }
  return buildings;
}

// An origin from Python: None, a sequence (lat, lon[, alt]) or an object with lat, lon and
// optional alt attributes (vistrack.Georeference); validated.
std::optional<GeodeticPoint> origin_from_python(const py::object& origin, const std::string& field) {
  if (origin.is_none()) return std::nullopt;
  const std::string shape = "must be (lat, lon), (lat, lon, alt) or a vistrack.Georeference";
  GeodeticPoint point;
  try {
    if (py::hasattr(origin, "lat") && py::hasattr(origin, "lon")) {
      point = {origin.attr("lat").cast<double>(), origin.attr("lon").cast<double>(),
               py::hasattr(origin, "alt") ? origin.attr("alt").cast<double>() : 0.0};
    } else {
      const auto values = origin.cast<std::vector<double>>();
      if (values.size() != 2 && values.size() != 3) detail::fail_field(field, py::repr(origin).cast<std::string>(), shape);
      point = {values[0], values[1], values.size() == 3 ? values[2] : 0.0};
    }
  } catch (const py::cast_error&) {
    detail::fail_field(field, py::repr(origin).cast<std::string>(), shape);
  }
  validate_geodetic_point(point, field);
  return point;
}

std::optional<std::tuple<double, double, double>> origin_to_python(const std::optional<GeodeticPoint>& origin) {
  if (!origin) return std::nullopt;
  return std::make_tuple(origin->latitude, origin->longitude, origin->altitude);
}

// Longitude/latitude files are projected by a Python callable (the package passes
// vistrack.georeference.project_lon_lat); `project` outlives the load, so it is held by reference
// and never copied while the GIL is released.
LonLatProjection lon_lat_projection(const py::object& project) {
  if (project.is_none()) return {};
  return [&project](const Points2& lon_lat, const GeodeticPoint& origin) {
    py::gil_scoped_acquire gil;
    return project(lon_lat, py::make_tuple(origin.latitude, origin.longitude, origin.altitude)).cast<Points2>();
  };
}

}  // namespace

void bind_environment(py::module_& m) {
  py::class_<RoadNetwork>(m, "RoadNetwork",
                          "Road graph G = (N, E): nodes on the ground plane; edges driven both ways "
                          "unless one-way.")
      .def(py::init([](const Points2& nodes, const Edges& edges, const std::optional<std::vector<bool>>& oneway) {
             return roads_from_arrays(nodes, edges, oneway);
           }),
           py::arg("nodes"), py::arg("edges"), py::arg("oneway") = py::none(),
           "nodes: (n, 2) float array of positions in metres; edges: (m, 2) int array of node pairs; "
           "oneway: None (every edge two-way) or one bool per edge, True when the edge is driven only "
           "from its first node to its second.")
      .def_property_readonly("oneway", &oneway_array,
                             "Per edge, True when it is driven only from edges[e][0] to edges[e][1]; bool array (m,).")
      .def_property_readonly("nodes", &nodes_array, "Node positions, numpy array (n, 2).")
      .def_property_readonly("edges", &edges_array, "Edges as node index pairs, numpy int64 array (m, 2).")
      .def("shortest_route", [](const RoadNetwork& roads, int from, int to) { return shortest_route(roads, from, to); },
           py::arg("start"), py::arg("goal"),
           "Node indices of a shortest route along the edges from start to goal (Dijkstra, Euclidean "
           "edge lengths, one-way edges only their way), both included. VistrackError when goal is "
           "unreachable, saying so when only one-way streets stand in the way.")
      .def("nearest_node", [](const RoadNetwork& roads, const Vec2& point) {
             if (roads.nodes.empty()) throw Error("nodes: the road network has no nodes");
             int best = 0;
             for (std::size_t i = 1; i < roads.nodes.size(); ++i)
               if ((roads.nodes[i] - point).squaredNorm() < (roads.nodes[static_cast<std::size_t>(best)] - point).squaredNorm())
                 best = static_cast<int>(i);
             return best;
           },
           py::arg("point"), "Index of the node closest to a point (x, y) (lowest index on ties).")
      .def("__repr__", [](const RoadNetwork& r) {
        const auto oneway = static_cast<std::size_t>(std::count(r.oneway.begin(), r.oneway.end(), true));
        return Repr("RoadNetwork").add("nodes", r.nodes.size()).add("edges", r.edges.size()).add("oneway", oneway).str();
      });

  py::class_<Environment>(m, "Environment",
                          "Obstacles (2.5D buildings or a triangle mesh), ground and road network.")
      .def_static(
          "from_geojson",
          [](const py::object& path, const py::object& origin, const py::object& project) {
            const std::string name = path_string(path);
            const GeoJsonOptions options{origin_from_python(origin, "origin"), lon_lat_projection(project)};
            py::gil_scoped_release release;
            return Environment::from_geojson(name, options);
          },
          py::arg("path"), py::arg("origin") = py::none(), py::arg("project") = py::none(),
                  "2.5D buildings from a GeoJSON FeatureCollection of Polygon/MultiPolygon features: "
                  "height from properties.height, else building:levels x 3 m; the base from properties.min_height "
                  "(default 0, below the top); id from properties.id, "
                  "else the feature index. Coordinates in local east-north metres, or WGS84 longitude/latitude "
                  "(the GeoJSON default, as OpenStreetMap exports give; told apart by range, anything else is a "
                  "VistrackError) projected to local metres by project(lon_lat, (lat, lon, alt)) (the package "
                  "passes vistrack.georeference.project_lon_lat: pyproj, ellipsoidal tangent plane) about "
                  "origin (lat, lon[, alt]) or a Georeference, else about the centre of the "
                  "data's bounding box (rounded to 1e-7 degree); env.origin reports it. Footprints are validated "
                  "(simple, >= 3 points, holes inside, positive height, disjoint interiors: overlaps up "
                  "to 1 m^2 are taken as touching walls, and a footprint inside a building at least as "
                  "tall as a building part) and normalised counter-clockwise.")
      .def_static(
          "from_mesh",
          [](const py::object& path, const std::string& up) {
            const std::string name = path_string(path);
            py::gil_scoped_release release;
            return Environment::from_mesh(name, up);
          },
          py::arg("path"), py::arg("up") = "z",
                  "Any mesh file CGAL reads (.obj .ply .stl .off): duplicate points merged, polygons "
                  "triangulated, degenerate triangles dropped. up='y' maps a Y-up, north=-Z file "
                  "(x, y, z) to east-north-up (x, -z, y). The ground level is the lowest vertex.")
      .def_static(
          "from_buildings",
          [](const py::iterable& items, std::optional<RoadNetwork> roads) {
            std::vector<Building> buildings = buildings_from_python(items);
            py::gil_scoped_release release;
            return Environment::from_buildings(std::move(buildings), roads.value_or(RoadNetwork{}));
          },
          py::arg("buildings"), py::arg("roads") = py::none(),
          "Environment from a list of (Polygon, height), (Polygon, height, id) or (Polygon, height, id, "
          "min_height) (the base: a raised part from min_height to height; an (n, 2) array "
          "may stand for a Polygon without holes), validated as in "
          "from_geojson; optional RoadNetwork checked against every footprint.")
      .def_static("from_triangles", &Environment::from_triangles, py::arg("vertices"), py::arg("faces"),
                  "Environment from triangles: vertices (n, 3) float in east-north-up metres, faces "
                  "(m, 3) int indexing them. The ground level is the lowest vertex.")
      .def_static("demo", &Environment::demo, py::call_guard<py::gil_scoped_release>(),
                  "The embedded synthetic downtown (800 m x 800 m, street grid as road network, "
                  "buildings 10-150 m tall). Deterministic.")
      .def_property_readonly("num_triangles", &Environment::num_triangles,
                             "Number of obstacle triangles (the ground plane not counted).")
      .def_property_readonly("max_height", &Environment::max_height,
                             "Tallest obstacle point above the ground level, in metres.")
      .def_property_readonly("ground_level", &Environment::ground_level,
                             "Height of the ground plane in metres (0 for buildings, lowest vertex for a mesh).")
      .def_property_readonly(
          "bounds",
          [](const Environment& e) {
            Eigen::Matrix<double, 2, 3, Eigen::RowMajor> box;
            box.row(0) = e.bounds().min.transpose();
            box.row(1) = e.bounds().max.transpose();
            return box;
          },
          "Axis-aligned bounds of the obstacles, numpy array (2, 3): [min, max].")
      .def_property_readonly(
          "vertices", [](const Environment& e) { return e.mesh().vertices; },
          "Obstacle vertices, numpy array (n, 3).")
      .def_property_readonly(
          "faces", [](const Environment& e) { return e.mesh().faces; },
          "Obstacle triangles, numpy int32 array (m, 3) of vertex indices, outward oriented for buildings.")
      .def_property_readonly("num_buildings", &Environment::num_buildings,
                             "Number of 2.5D buildings (0 for an environment made from a mesh).")
      .def_property_readonly("footprints", &Environment::footprints,
                             "Building footprints as a list of Polygon (outer counter-clockwise, holes clockwise).")
      .def_property_readonly(
          "heights", [](const Environment& e) { const auto h = e.heights(); return Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(h.data(), static_cast<Eigen::Index>(h.size()))); },
          "Building heights (their tops) in metres above the ground, numpy array (num_buildings,).")
      .def_property_readonly(
          "min_heights", [](const Environment& e) { const auto h = e.min_heights(); return Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(h.data(), static_cast<Eigen::Index>(h.size()))); },
          "Building bases (min_height) in metres above the ground, numpy array (num_buildings,): 0 for "
          "a building standing on the ground, above 0 for a raised part with open space under it.")
      .def_property_readonly(
          "building_ids",
          [](const Environment& e) {
            std::vector<int> ids;
            for (const Building& b : e.buildings()) ids.push_back(b.id);
            return ids;
          },
          "Building ids (properties.id, else the feature index), list of int.")
      .def_property_readonly("roads", &Environment::roads, "The road network (RoadNetwork).")
      .def("set_roads", &Environment::set_roads, py::arg("roads"),
           "Replace the road network; VistrackError naming the edge and the building when an edge "
           "crosses a footprint interior (running along a wall is allowed).")
      .def("set_roads",
           [](Environment& e, const Points2& nodes, const Edges& edges, const std::optional<std::vector<bool>>& oneway) {
             e.set_roads(roads_from_arrays(nodes, edges, oneway));
           },
           py::arg("nodes"), py::arg("edges"), py::arg("oneway") = py::none(),
           "Replace the road network from arrays nodes (n, 2), edges (m, 2) and optional oneway flags (m,).")
      .def_property_readonly("fingerprint", &Environment::fingerprint,
                             "Deterministic 64-bit content hash of the geometry and roads, for caches.")
      .def_property(
          "origin", [](const Environment& e) { return origin_to_python(e.origin()); },
          [](Environment& e, const py::object& origin) { e.set_origin(origin_from_python(origin, "origin")); },
          "Where local (0, 0, 0) lies on the Earth: (lat, lon, alt) in degrees and metres, or None when "
          "unknown. Set by from_geojson (its origin argument, or the origin a longitude/latitude file was "
          "projected about); assignable (a tuple or a vistrack.Georeference). Not part of the fingerprint.")
      .def("__repr__", [](const Environment& e) {
        return Repr("Environment")
            .add("buildings", e.num_buildings())
            .add("triangles", e.num_triangles())
            .add("max_height", e.max_height())
            .str();
      });

  py::class_<PoiPath>(m, "PoiPath", "A point of interest moving at constant speed through waypoints.")
      .def(py::init<const Eigen::MatrixXd&, double>(), py::arg("waypoints"), py::arg("speed"),
           "Waypoints (n, 2) or (n, 3) in metres; speed in m/s (> 0).")
      .def_static(
          "from_csv", [](const py::object& path, double speed) { return PoiPath::from_csv(path_string(path), speed); },
          py::arg("path"), py::arg("speed"),
                  "Read waypoints from a CSV file with lines x,y[,z].")
      .def_static("from_nodes", &PoiPath::from_nodes, py::arg("roads"), py::arg("nodes"), py::arg("speed"),
                  "Path through a sequence of road-network node indices, each consecutive pair joined by an edge.")
      .def("position", &PoiPath::position, py::arg("t"), "Position (3,) at time t (clamped to the path).")
      .def("velocity", &PoiPath::velocity, py::arg("t"), "Velocity (2,) of the segment containing t.")
      .def("heading", &PoiPath::heading, py::arg("t"), "Direction of the velocity at t, radians.")
      .def_property_readonly("node_times", &PoiPath::node_times, "Times t_i at each waypoint (s).")
      .def_property_readonly("waypoints", &PoiPath::waypoints, "Waypoints (n, 3) after dropping repeats.")
      .def_property_readonly("speed", &PoiPath::speed, "Speed v_g in m/s.")
      .def_property_readonly("duration", &PoiPath::duration, "Time to travel the whole path (s).")
      .def_property_readonly("length", &PoiPath::length, "Path length in metres.");
}

}  // namespace vistrack::bindings
