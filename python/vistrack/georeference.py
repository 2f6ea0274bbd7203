"""The georeference: vistrack's local east-north-up metres on the WGS84 ellipsoid, through pyproj.

One :class:`Georeference` serves maps in (``Environment.from_geojson`` projects longitude/latitude
files with :func:`project_lon_lat`, which this module hands to the compiled loader) and routes out
(``vistrack.mission``), so a route drawn over a building corner in local metres lands on that
corner's latitude and longitude.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from functools import lru_cache
from typing import TYPE_CHECKING, Any, Callable, Optional

import numpy as np

from ._core import Environment
from ._core import limits as _limits
from .schema import fail, number

if TYPE_CHECKING:
    from pyproj import Transformer

__all__ = ["Georeference", "degrees", "project_lon_lat"]




@lru_cache(maxsize=64)
def _topocentric(lat: float, lon: float, alt: float) -> Transformer:
    """pyproj's geodetic (lon, lat, h) -> ENU pipeline about one origin (cached: building one
    costs about a millisecond)."""
    from pyproj import Transformer

    return Transformer.from_pipeline(
        "+proj=pipeline +step +proj=cart +ellps=WGS84 "
        f"+step +proj=topocentric +ellps=WGS84 +lat_0={lat!r} +lon_0={lon!r} +h_0={alt!r}")


def _array(key: str, value: Any, low: float | None = None, high: float | None = None,
           unit: str = "degrees") -> np.ndarray:
    """A float array of finite values in [low, high]; VistrackError naming key[i] otherwise."""
    try:
        array = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise fail(key, value, "must be numbers") from None
    bad = ~np.isfinite(array)
    if low is not None:
        bad |= array < low
    if high is not None:
        bad |= array > high
    if bad.any():
        index = np.unravel_index(int(np.argmax(bad)), array.shape) if array.ndim else ()
        name = key + "".join(f"[{i}]" for i in index)
        allowed = "must be finite" if low is None else f"must be in [{low:g}, {high:g}] {unit}"
        raise fail(name, float(array[index]), allowed)
    return array


def degrees(key: str, value: Any, limit: float) -> float:
    """A latitude (limit 90) or longitude (limit 180) in degrees."""
    result = number(key, value)
    if not -limit <= result <= limit:
        raise fail(key, value, f"must be in [-{limit:g}, {limit:g}] degrees")
    return result


def _altitude(key: str, value: Any) -> float:
    """An origin altitude in metres: |alt| <= MAX_ALTITUDE (100 km, the edge of space; at 1e20 m
    every waypoint came out at lat/lon 1e-18)."""
    return number(key, value, low=-_limits.MAX_ALTITUDE, high=_limits.MAX_ALTITUDE)


# How far from the origin (east and north, each) to_latlon goes: within it the round trip through
# to_local returns the input to 1e-6 m (2.2e-7 m at the corner (2e6, 2e6) m; tests/python/
# test_georeference_range.py); beyond ~3e6 m the map plane leaves the origin's height surface
# behind (1.3 mm at 3e6 m, 0.8 m at 4e6 m, 1.1e7 m returned for 1e7 m). Local coordinates
# themselves go to MAX_COORDINATE (1e7 m); only their latitude and longitude are limited.
MAX_MAP_OFFSET = 2e6  # m


def _local(key: str, value: Any, limit: float = _limits.MAX_COORDINATE, unit: str = "m") -> np.ndarray:
    """Local map-plane coordinates in metres: |v| <= limit (MAX_COORDINATE, 1e7 m, by default)."""
    return _array(key, value, -limit, limit, unit)


def _result(*arrays: np.ndarray) -> tuple[Any, ...]:
    """Plain floats for scalar input, arrays otherwise."""
    return tuple(float(a) if a.ndim == 0 else a for a in arrays)


@dataclass(frozen=True)
class Georeference:
    """Where local (0, 0, 0) lies on the Earth: WGS84 latitude and longitude in degrees, and the
    altitude of local z = 0 in metres above mean sea level (AMSL missions and the home position
    use it). The tangent plane takes ``alt`` as an ellipsoidal height; the difference (the geoid
    undulation, tens of metres) scales local distances by under 1e-5.

    Conversions take and return numpy arrays (any broadcastable shapes; floats for scalars):
    :meth:`enu` / :meth:`geodetic` are the exact 3D local tangent plane (pyproj
    ``+proj=topocentric``); :meth:`to_local` / :meth:`to_latlon` are the map plane vistrack's 2.5D
    world uses, the horizontal ENU coordinates of points at the origin's height, and exact inverses
    of each other.
    """

    lat: float
    lon: float
    alt: float = 0.0

    def __post_init__(self) -> None:
        object.__setattr__(self, "lat", degrees("lat", self.lat, 90.0))
        object.__setattr__(self, "lon", degrees("lon", self.lon, 180.0))
        object.__setattr__(self, "alt", _altitude("alt", self.alt))

    @classmethod
    def from_value(cls, value: Georeference | Sequence[float], key: str = "origin") -> Georeference:
        """A Georeference from itself or a sequence (lat, lon[, alt]); errors name ``key[i]``."""
        if isinstance(value, Georeference):
            return value
        if isinstance(value, (str, bytes)) or not isinstance(value, Sequence) or len(value) not in (2, 3):
            raise fail(key, value, "must be [lat, lon] or [lat, lon, alt] (degrees, degrees, metres AMSL)")
        lat = degrees(f"{key}[0]", value[0], 90.0)
        lon = degrees(f"{key}[1]", value[1], 180.0)
        alt = _altitude(f"{key}[2]", value[2]) if len(value) == 3 else 0.0
        return cls(lat, lon, alt)

    @classmethod
    def of(cls, env: Environment | None) -> Georeference | None:
        """The environment's origin (``env.origin``) as a Georeference, or None when unknown."""
        origin = None if env is None else env.origin
        return None if origin is None else cls(*origin)

    def enu(self, lat: Any, lon: Any, alt: Any) -> tuple[Any, Any, Any]:
        """(east, north, up) metres of WGS84 points (degrees, metres)."""
        lat = _array("lat", lat, -90.0, 90.0)
        lon = _array("lon", lon, -180.0, 180.0)
        alt = _array("alt", alt)
        lat, lon, alt = np.broadcast_arrays(lat, lon, alt)
        east, north, up = _topocentric(self.lat, self.lon, self.alt).transform(lon, lat, alt)
        return _result(np.asarray(east), np.asarray(north), np.asarray(up))

    def geodetic(self, east: Any, north: Any, up: Any) -> tuple[Any, Any, Any]:
        """(lat, lon, alt) of local ENU points: the exact inverse of :meth:`enu`."""
        from pyproj.enums import TransformDirection

        east, north, up = np.broadcast_arrays(_array("east", east), _array("north", north), _array("up", up))
        lon, lat, alt = _topocentric(self.lat, self.lon, self.alt).transform(
            east, north, up, direction=TransformDirection.INVERSE)
        return _result(np.asarray(lat), np.asarray(lon), np.asarray(alt))

    def to_local(self, lat: Any, lon: Any) -> tuple[Any, Any]:
        """(east, north) on the map plane: the horizontal ENU coordinates of (lat, lon) at the
        origin's height (how longitude/latitude footprints become local metres)."""
        east, north, _ = self.enu(lat, lon, self.alt)
        return east, north

    def to_latlon(self, east: Any, north: Any) -> tuple[Any, Any]:
        """(lat, lon) of map-plane points: the exact inverse of :meth:`to_local`. It finds the
        point above (east, north) along the origin's up axis that lies at the origin's height
        (Newton on the height; each step shrinks the error by 1 - cos of the angle between the
        two verticals, about 1e-6 at 10 km: two or three steps). |east|, |north| <= MAX_MAP_OFFSET
        (2e6 m), where the round trip holds to 1e-6 m."""
        unit = "m from the origin (MAX_MAP_OFFSET: where the round trip through to_local holds to 1e-6 m)"
        east, north = np.broadcast_arrays(_local("east", east, MAX_MAP_OFFSET, unit),
                                          _local("north", north, MAX_MAP_OFFSET, unit))
        up = np.zeros_like(east)
        for _ in range(50):
            lat, lon, alt = (np.asarray(v) for v in self.geodetic(east, north, up))
            miss = alt - self.alt
            if np.all(np.abs(miss) < 1e-9):
                break
            up = up - miss
        return _result(lat, lon)

    def __repr__(self) -> str:
        return f"Georeference(lat={self.lat!r}, lon={self.lon!r}, alt={self.alt!r})"


def project_lon_lat(lon_lat: np.ndarray, origin: Georeference | Sequence[float]) -> np.ndarray:
    """WGS84 (longitude, latitude) rows, shape (n, 2), to local (east, north) metres about
    ``origin`` on the map plane: what ``Environment.from_geojson`` calls for longitude/latitude
    files."""
    points = np.asarray(lon_lat, dtype=float).reshape(-1, 2)
    east, north = Georeference.from_value(origin).to_local(points[:, 1], points[:, 0])
    return np.column_stack([east, north])


# The binding (it takes the projection as an argument); __wrapped__ keeps a reload from wrapping the wrapper.
_from_geojson = getattr(Environment.from_geojson, "__wrapped__", Environment.from_geojson)


def _environment_from_geojson(path: Any, origin: Any = None,
                              project: Optional[Callable[..., Any]] = project_lon_lat) -> Environment:
    return _from_geojson(path, origin, project)


_environment_from_geojson.__wrapped__ = _from_geojson  # type: ignore[attr-defined]
_environment_from_geojson.__doc__ = (_from_geojson.__doc__ or "").partition("\n\n")[2]  # without the signature line
Environment.from_geojson = staticmethod(_environment_from_geojson)  # type: ignore[method-assign]
