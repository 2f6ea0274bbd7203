"""Small GeoJSON cities written as text."""

from __future__ import annotations


def square_collection(height: str) -> str:
    """One 10 m square building whose height is ``height`` as written in the JSON text."""
    return ('{"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {"height": ' + height
            + '}, "geometry": {"type": "Polygon", "coordinates": [[[0,0],[10,0],[10,10],[0,10]]]}}]}')
