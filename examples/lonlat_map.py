"""Maps in and routes out through one georeference.

Writes Charlotte's footprints (local metres, ../shared/data) as a WGS84 longitude/latitude
GeoJSON, as OpenStreetMap exports give them, loads that back with and without an origin, plans
the paper's first example on it and exports the route for an autopilot and for a map:

    python examples/lonlat_map.py [OUT_DIR]

Prints the largest vertex difference between the metric city and the one read from longitude/
latitude, the origin chosen when none is given, and the files written.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

import numpy as np

import vistrack as vt

DATA = Path(__file__).resolve().parents[1].parent / "shared" / "data" / "charlotte"
ORIGIN = vt.Georeference(35.2249, -80.8403)  # ../shared/data/README.md


def to_lon_lat(source: Path, target: Path, ref: vt.Georeference) -> None:
    data = json.loads(source.read_text())
    data.pop("crs_note", None)  # the file's note says "local metres"; this copy is WGS84
    for feature in data["features"]:
        geometry = feature["geometry"]
        polygons = [geometry["coordinates"]] if geometry["type"] == "Polygon" else geometry["coordinates"]
        for ring in (ring for polygon in polygons for ring in polygon):
            xy = np.asarray(ring, dtype=float)
            lat, lon = ref.to_latlon(xy[:, 0], xy[:, 1])
            ring[:] = [[float(a), float(b)] for a, b in zip(lon, lat)]
    target.write_text(json.dumps(data))


def main(out: Path) -> None:
    out.mkdir(parents=True, exist_ok=True)
    lonlat = out / "charlotte_wgs84.geojson"
    to_lon_lat(DATA / "buildings.geojson", lonlat, ORIGIN)
    metric = vt.Environment.from_geojson(DATA / "buildings.geojson")
    env = vt.Environment.from_geojson(lonlat, origin=ORIGIN)
    print(f"{lonlat.name}: {env.num_buildings} buildings; largest vertex difference from the metric file "
          f"{np.max(np.abs(env.vertices - metric.vertices)):.1e} m")
    centred = vt.Environment.from_geojson(lonlat)
    print("without an origin it is projected about the data's centre: origin = "
          f"({centred.origin[0]:.7f}, {centred.origin[1]:.7f})")
    poi = vt.PoiPath.from_csv(DATA / "paths" / "paper_slow.csv", speed=5.0)
    uav = vt.Uav(speed=20.0, min_turn_radius=50.0, altitude=300.0)
    plan = vt.plan_orbits(env, poi, uav, vt.Sensor(d_max=400.0), vt.Planning(spacing=20.0, cutoff=20e6))
    mission = plan.to_mission(vt.Georeference.of(env))
    for name in ("route.plan", "route.waypoints", "route.geojson"):
        mission.save(out / name)
    print(f"R {plan.radii[0]:.1f} -> {plan.radii[-1]:.1f} m; {len(mission)} mission items written to "
          f"{out}/route.plan, route.waypoints, route.geojson")


if __name__ == "__main__":
    main(Path(sys.argv[1]) if len(sys.argv) > 1 else Path("lonlat-out"))
