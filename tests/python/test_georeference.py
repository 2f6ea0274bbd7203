"""vt.Georeference against pyproj's own geodesy (geodesics, geocentric coordinates), a published
survey pair, and the longitude/latitude GeoJSON it brings in."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from pyproj import Geod, Transformer

import vistrack as vt
from vistrack.mission import Georeference, project_lon_lat

CHARLOTTE = Georeference(35.2249, -80.8403)
WGS84_A, WGS84_F = 6378137.0, 1 / 298.257223563
E2 = WGS84_F * (2 - WGS84_F)


def enu_by_geocentric(ref: Georeference, lat, lon, alt) -> np.ndarray:
    """An independent ENU: pyproj's geodetic -> geocentric (EPSG:4979 -> EPSG:4978), then the
    textbook rotation about the origin's geocentric position."""
    to_ecef = Transformer.from_crs("EPSG:4979", "EPSG:4978", always_xy=True)
    x, y, z = to_ecef.transform(lon, lat, alt)
    x0, y0, z0 = to_ecef.transform(ref.lon, ref.lat, ref.alt)
    phi, lam = math.radians(ref.lat), math.radians(ref.lon)
    rotation = np.array([
        [-math.sin(lam), math.cos(lam), 0.0],
        [-math.sin(phi) * math.cos(lam), -math.sin(phi) * math.sin(lam), math.cos(phi)],
        [math.cos(phi) * math.cos(lam), math.cos(phi) * math.sin(lam), math.sin(phi)],
    ])
    return (rotation @ np.vstack([np.asarray(x) - x0, np.asarray(y) - y0, np.asarray(z) - z0])).T


@pytest.mark.parametrize("lat, lon", [(35.2249, -80.8403), (35.312865337828214, -80.74022444600895),
                                      (-33.9, 151.2), (69.6, 18.9)])
def test_enu_matches_pyproj_geodesics_10_km_away_to_1_mm(lat: float, lon: float) -> None:
    """Points 10 km along geodesics in 16 azimuths (pyproj.Geod, on the ellipsoid): our ENU has
    the geodesic's azimuth, and the horizontal distance and drop below the tangent plane of the
    normal section, a circle of Euler's radius R_a to far below a millimetre over 10 km."""
    ref = Georeference(lat, lon)
    geod = Geod(ellps="WGS84")
    azimuths = np.arange(16) * 22.5
    distance = 10_000.0
    lons, lats, _ = geod.fwd(np.full(16, lon), np.full(16, lat), azimuths, np.full(16, distance))
    east, north, up = (np.asarray(v) for v in ref.enu(lats, lons, np.zeros(16)))
    phi = math.radians(lat)
    n_radius = WGS84_A / math.sqrt(1 - E2 * math.sin(phi) ** 2)
    m_radius = n_radius * (1 - E2) / (1 - E2 * math.sin(phi) ** 2)
    alpha = np.radians(azimuths)
    euler = 1 / (np.cos(alpha) ** 2 / m_radius + np.sin(alpha) ** 2 / n_radius)
    # Azimuth: 1e-7 rad is 1 mm at 10 km.
    azimuth_error = np.angle(np.exp(1j * (np.arctan2(east, north) - alpha)))
    assert np.max(np.abs(azimuth_error)) < 1e-7
    # The normal section's chord: R sin(s/R) across, R (1 - cos(s/R)) down (4 mm and 7.8 m
    # from the flat-earth values, so an equirectangular shortcut fails this).
    assert np.max(np.abs(np.hypot(east, north) - euler * np.sin(distance / euler))) < 1e-3
    assert np.max(np.abs(up + euler * (1 - np.cos(distance / euler)))) < 1e-3
    # And the whole 3D vector against pyproj's geocentric coordinates, here with an origin 230 m
    # up, to 1 mm (in fact about 1e-9 m).
    raised = Georeference(lat, lon, 230.0)
    independent = enu_by_geocentric(raised, lats, lons, np.zeros(16))
    assert np.max(np.abs(np.column_stack(raised.enu(lats, lons, np.zeros(16))) - independent)) < 1e-3


def test_zermatt_to_matterhorn_published_pair() -> None:
    """MathWorks' geodetic2enu example: the Matterhorn (45.976, 7.658, 4531 m) from Zermatt
    (46.017, 7.750, 1673 m) is (-7134.8, -4556.3, 2852.4) m; the printed digits hold 0.05 m."""
    zermatt = Georeference(46.017, 7.750, 1673.0)
    east, north, up = zermatt.enu(45.976, 7.658, 4531.0)
    assert isinstance(east, float)
    np.testing.assert_allclose([east, north, up], [-7134.8, -4556.3, 2852.4], atol=0.05)
    lat, lon, alt = zermatt.geodetic(east, north, up)
    np.testing.assert_allclose([lat, lon], [45.976, 7.658], rtol=0, atol=1e-11)
    assert alt == pytest.approx(4531.0, abs=1e-6)


def test_map_plane_round_trips_and_is_not_flat_earth() -> None:
    rng = np.random.default_rng(1)
    east, north = rng.uniform(-10_000, 10_000, (2, 500))
    lat, lon = CHARLOTTE.to_latlon(east, north)
    back_e, back_n = CHARLOTTE.to_local(lat, lon)
    assert np.max(np.abs(back_e - east)) < 1e-6 and np.max(np.abs(back_n - north)) < 1e-6
    # The points lie at the origin's height (the map plane), not on the tangent plane.
    assert np.max(np.abs(np.asarray(CHARLOTTE.geodetic(east, north, 0 * east)[2]))) > 5.0
    # An equirectangular shortcut differs by decimetres at 10 km (scale varies with latitude).
    approx_n = np.radians(lat - CHARLOTTE.lat) * 6378137.0
    assert np.max(np.abs(approx_n - north)) > 0.5
    # Broadcasting and shapes.
    e2, n2 = CHARLOTTE.to_local(np.full((2, 3), 35.23), -80.84)
    assert np.shape(e2) == (2, 3) and np.shape(n2) == (2, 3)


@pytest.mark.parametrize("args, message", [
    ((95.0, 0.0), r"lat = 95\.0: must be in \[-90, 90\] degrees"),
    ((-90.5, 0.0), r"lat = -90\.5"),
    ((0.0, 181.0), r"lon = 181\.0"),
    ((0.0, 0.0, math.nan), r"alt = nan: must be a finite number"),
    (("north", 0.0), r"lat = 'north': must be a number"),
])
def test_bad_georeference_names_the_field(args, message) -> None:
    with pytest.raises(vt.VistrackError, match=message):
        Georeference(*args)


def test_bad_conversion_input_names_the_point() -> None:
    with pytest.raises(vt.VistrackError, match=r"lat\[2\] = 91\.0: must be in \[-90, 90\] degrees"):
        CHARLOTTE.to_local([35.0, 35.1, 91.0], [-80.0, -80.0, -80.0])
    with pytest.raises(vt.VistrackError, match=r"east\[1\] = inf"):
        CHARLOTTE.to_latlon([0.0, math.inf], [0.0, 0.0])
    with pytest.raises(vt.VistrackError, match=r"origin\[0\] = 123"):
        Georeference.from_value([123, 0])
    with pytest.raises(vt.VistrackError, match=r"origin = 'x'"):
        Georeference.from_value("x")


@pytest.mark.sanitize
def test_origin_altitude_and_local_coordinates_are_bounded(tmp_path) -> None:
    """An origin at 1e20 m put every waypoint at lat/lon 1e-18 (at 1e300 the message said
    `up = nan`); to_latlon(1e8, 0) returned a position: |alt| <= 1e5 m, |east, north| <= 1e7 m."""
    with pytest.raises(vt.VistrackError, match=r"^alt = 1e\+20: must be <= 100000 and >= -100000$"):
        Georeference(0.0, 0.0, 1e20)
    with pytest.raises(vt.VistrackError, match=r"^origin\[2\] = 1e\+300: must be <= 100000 and >= -100000$"):
        Georeference.from_value([0.0, 0.0, 1e300])
    # to_latlon's own range is tighter (MAX_MAP_OFFSET 2e6 m: test_georeference_range.py).
    with pytest.raises(vt.VistrackError, match=r"^east = 100000000\.0: must be in \[-2e\+06, 2e\+06\] m from"):
        CHARLOTTE.to_latlon(1e8, 0.0)
    path = tmp_path / "m.geojson"
    path.write_text(json.dumps({"type": "FeatureCollection", "features": [
        {"type": "Feature", "properties": {"height": 5},
         "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [10, 0], [10, 10], [0, 10]]]}}]}))
    with pytest.raises(vt.VistrackError, match=r"^origin(\.altitude|\[2\]) = 1e\+20: must be"):
        vt.Environment.from_geojson(path, origin=(0.0, 0.0, 1e20))
    env = vt.Environment.from_geojson(path, origin=CHARLOTTE)
    with pytest.raises(vt.VistrackError, match=r"^origin\.altitude = -1e\+20: must be a finite number in"):
        env.origin = (0.0, 0.0, -1e20)
    assert Georeference(0.0, 0.0, 1e5).alt == 1e5


def test_georeference_pickles_and_compares() -> None:
    import pickle

    copy = pickle.loads(pickle.dumps(CHARLOTTE))
    assert copy == CHARLOTTE and copy.to_local(35.23, -80.84) == CHARLOTTE.to_local(35.23, -80.84)


# --- maps in: longitude/latitude GeoJSON -----------------------------------------------------------


def lon_lat_copy(path, tmp_path, ref: Georeference):
    """The metric GeoJSON converted to WGS84 longitude/latitude with the georeference."""
    data = json.loads(path.read_text())
    for feature in data["features"]:
        geometry = feature["geometry"]
        polygons = [geometry["coordinates"]] if geometry["type"] == "Polygon" else geometry["coordinates"]
        for polygon in polygons:
            for ring in polygon:
                xy = np.asarray(ring, dtype=float)
                lat, lon = ref.to_latlon(xy[:, 0], xy[:, 1])
                ring[:] = [[float(a), float(b)] for a, b in zip(lon, lat)]
    data.pop("crs_note", None)
    out = tmp_path / "lonlat.geojson"
    out.write_text(json.dumps(data))
    return out


def test_charlotte_to_lon_lat_and_back_is_the_same_environment_to_1_cm(charlotte, tmp_path) -> None:
    metric = vt.Environment.from_geojson(charlotte / "buildings.geojson")
    assert metric.origin is None
    lonlat = lon_lat_copy(charlotte / "buildings.geojson", tmp_path, CHARLOTTE)
    env = vt.Environment.from_geojson(lonlat, origin=CHARLOTTE)
    assert env.origin == (35.2249, -80.8403, 0.0)
    assert env.num_buildings == metric.num_buildings == 167
    assert env.num_triangles == metric.num_triangles
    assert np.max(np.abs(env.vertices - metric.vertices)) < 1e-6  # asked: 1 cm; measured 2.6e-9 m
    assert np.max(np.abs(env.heights - metric.heights)) == 0.0
    assert env.building_ids == metric.building_ids
    # A tuple origin works the same; without an origin the data's bounding-box centre is used and
    # reported, and the city is the same up to the shift between the two origins.
    assert np.max(np.abs(vt.Environment.from_geojson(str(lonlat), origin=(35.2249, -80.8403)).vertices
                         - env.vertices)) == 0.0
    centred = vt.Environment.from_geojson(lonlat)
    lat0, lon0, alt0 = centred.origin
    assert (lat0, lon0, alt0) != (35.2249, -80.8403, 0.0) and alt0 == 0.0
    assert round(lat0, 7) == lat0 and round(lon0, 7) == lon0
    shift = np.array(CHARLOTTE.to_local(lat0, lon0))
    assert np.max(np.abs(centred.vertices[:, :2] + shift - env.vertices[:, :2])) < 0.01


def test_lon_lat_geojson_errors(tmp_path) -> None:
    def write(coordinates) -> str:
        path = tmp_path / "f.geojson"
        path.write_text(json.dumps({"type": "FeatureCollection", "features": [
            {"type": "Feature", "properties": {"height": 5},
             "geometry": {"type": "Polygon", "coordinates": [coordinates]}}]}))
        return str(path)

    square = [[-80.8404, 35.2248], [-80.8403, 35.2248], [-80.8403, 35.2249], [-80.8404, 35.2249]]
    env = vt.Environment.from_geojson(write(square))
    assert env.origin == pytest.approx((35.22485, -80.84035, 0.0), abs=1e-12)
    assert env.footprints[0].outer.shape == (4, 2)
    with pytest.raises(vt.VistrackError, match=r"origin\.latitude = 95"):
        vt.Environment.from_geojson(write(square), origin=(95.0, 0.0))
    with pytest.raises(vt.VistrackError, match=r"origin = 'Charlotte': must be \(lat, lon\)"):
        vt.Environment.from_geojson(write(square), origin="Charlotte")
    with pytest.raises(vt.VistrackError, match=r"x in \[500\.1, 500\.5\].*neither WGS84 longitude/latitude"):
        vt.Environment.from_geojson(write([[500.1, 0.1], [500.5, 0.1], [500.5, 0.5]]))
    with pytest.raises(vt.VistrackError, match=r"neither.*UTM"):
        vt.Environment.from_geojson(write([[514500, 3897900], [514600, 3897900], [514600, 3898000]]))


def test_the_loader_projects_with_the_projection_it_is_given(tmp_path) -> None:
    """The compiled loader imports no Python: the package hands it georeference.project_lon_lat; a
    caller may pass another projection, or none (then longitude/latitude is refused)."""
    path = tmp_path / "f.geojson"
    path.write_text(json.dumps({"type": "FeatureCollection", "features": [
        {"type": "Feature", "properties": {"height": 5}, "geometry": {"type": "Polygon", "coordinates": [
            [[-80.8404, 35.2248], [-80.8403, 35.2248], [-80.8403, 35.2249], [-80.8404, 35.2249]]]}}]}))
    seen = []

    def shifted(lon_lat, origin):
        seen.append(origin)
        return project_lon_lat(lon_lat, origin) + 100.0

    moved = vt.Environment.from_geojson(path, origin=CHARLOTTE, project=shifted)
    plain = vt.Environment.from_geojson(path, origin=CHARLOTTE)
    assert seen == [(CHARLOTTE.lat, CHARLOTTE.lon, CHARLOTTE.alt)]
    np.testing.assert_allclose(moved.footprints[0].outer, plain.footprints[0].outer + 100.0, atol=1e-9)
    with pytest.raises(vt.VistrackError, match=r"this loader has no projection to local metres"):
        vt.Environment.from_geojson(path, project=None)
    with pytest.raises(vt.VistrackError, match=r"project = 1 rows"):
        vt.Environment.from_geojson(path, project=lambda lon_lat, origin: np.zeros((1, 2)))


def test_metric_geojson_keeps_an_origin_and_env_origin_is_settable(tmp_path) -> None:
    path = tmp_path / "m.geojson"
    path.write_text(json.dumps({"type": "FeatureCollection", "features": [
        {"type": "Feature", "properties": {"height": 5},
         "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [10, 0], [10, 10], [0, 10]]]}}]}))
    env = vt.Environment.from_geojson(path, origin=CHARLOTTE)
    assert env.origin == (35.2249, -80.8403, 0.0)
    assert env.bounds[1][0] == 10.0
    env.origin = (1.0, 2.0, 3.0)
    assert Georeference.of(env) == Georeference(1.0, 2.0, 3.0)
    env.origin = None
    assert Georeference.of(env) is None
    with pytest.raises(vt.VistrackError, match=r"origin\.longitude = 200"):
        env.origin = (0.0, 200.0)


def test_project_lon_lat_is_the_map_plane() -> None:
    points = np.array([[-80.84, 35.23], [-80.85, 35.22]])
    xy = project_lon_lat(points, (35.2249, -80.8403))
    east, north = CHARLOTTE.to_local(points[:, 1], points[:, 0])
    np.testing.assert_array_equal(xy, np.column_stack([east, north]))
