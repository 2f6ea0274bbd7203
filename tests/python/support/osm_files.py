"""Small hand-written OpenStreetMap XML files for the importer's tests."""

from __future__ import annotations

from pathlib import Path
from xml.sax.saxutils import quoteattr


class OsmWriter:
    """Nodes, ways and relations written as OSM XML (``<osm version="0.6">``)."""

    def __init__(self) -> None:
        self.nodes: list[tuple[int, float, float]] = []
        self.ways: list[tuple[int, list[int], dict[str, str]]] = []
        self.relations: list[tuple[int, list[tuple[str, int, str]], dict[str, str]]] = []
        self._next = 1

    def _id(self) -> int:
        self._next += 1
        return self._next

    def node(self, lat: float, lon: float) -> int:
        ident = self._id()
        self.nodes.append((ident, lat, lon))
        return ident

    def way(self, nodes: list[int], **tags: str) -> int:
        ident = self._id()
        self.ways.append((ident, nodes, {k.replace("__", ":"): v for k, v in tags.items()}))
        return ident

    def ring(self, corners: list[tuple[float, float]], closed: bool = True, **tags: str) -> int:
        """A way through (lat, lon) corners, closed unless told otherwise."""
        ids = [self.node(lat, lon) for lat, lon in corners]
        return self.way(ids + ids[:1] if closed else ids, **tags)

    def box(self, lat: float, lon: float, size: float = 1e-4, **tags: str) -> int:
        """A closed square way with its south-west corner at (lat, lon), ``size`` degrees wide."""
        return self.ring([(lat, lon), (lat, lon + size), (lat + size, lon + size), (lat + size, lon)], **tags)

    def relation(self, members: list[tuple[str, int, str]], **tags: str) -> int:
        ident = self._id()
        self.relations.append((ident, members, {k.replace("__", ":"): v for k, v in tags.items()}))
        return ident

    def write(self, path: Path) -> Path:
        def tag_lines(tags: dict[str, str]) -> str:
            return "".join(f"<tag k={quoteattr(k)} v={quoteattr(v)}/>" for k, v in tags.items())

        lines = ['<?xml version="1.0" encoding="UTF-8"?>', '<osm version="0.6" generator="vistrack tests">']
        lines += [f'<node id="{i}" lat="{lat:.7f}" lon="{lon:.7f}"/>' for i, lat, lon in self.nodes]
        lines += [f'<way id="{i}">' + "".join(f'<nd ref="{n}"/>' for n in nodes) + tag_lines(tags) + "</way>"
                  for i, nodes, tags in self.ways]
        lines += [f'<relation id="{i}">' + "".join(f'<member type="{t}" ref="{r}" role="{role}"/>'
                                                  for t, r, role in members) + tag_lines(tags) + "</relation>"
                  for i, members, tags in self.relations]
        lines.append("</osm>")
        path.write_text("\n".join(lines) + "\n")
        return path
