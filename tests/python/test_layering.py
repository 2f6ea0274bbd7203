"""The architecture holds: a lower C++ area never includes a higher one (DESIGN.md, Layers), and the
Python library never imports its command line."""

from __future__ import annotations

import ast
import re
import subprocess
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]

# Bottom to top. error/limits (the input ranges)/geometry are the base every area may use;
# planners are peers of one another and may not include each other.
LEVELS = {
    "error": 0, "limits": 0.5, "geometry": 1, "environment": 3, "dubins": 4, "visibility": 5,
    "volume": 6,
    "orbit": 7, "guidance": 8, "ode": 9, "simulate": 10, "flight": 11,
    "waypoint_nav": 12, "loiter": 12, "follow": 12,
}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.MULTILINE)


def _area_of_header(stem: str) -> str:
    """An area's parameter structs have their own header: orbit_parameters -> orbit."""
    return stem.removesuffix("_parameters")


def _area_of_include(name: str) -> str:
    """"vistrack/orbit.hpp" -> orbit; "vistrack/orbit_parameters.hpp" -> orbit; "dubins/kernel.hpp" (a private
    header) -> dubins."""
    folder, _, file = name.partition("/")
    return _area_of_header(Path(file).stem) if folder == "vistrack" else folder


def _sources() -> list[tuple[Path, str]]:
    """(file, its area) for every public header and every source under cpp/src/<area>/."""
    files = [(p, _area_of_header(p.stem)) for p in sorted((REPO / "cpp" / "include" / "vistrack").glob("*.hpp"))]
    for folder in sorted(p for p in (REPO / "cpp" / "src").iterdir() if p.is_dir()):
        files += [(p, folder.name) for p in sorted(folder.rglob("*")) if p.suffix in (".hpp", ".cpp")]
    return files


def test_every_area_has_a_level() -> None:
    areas = {area for _, area in _sources()}
    unknown = sorted(areas - set(LEVELS))
    assert not unknown, f"areas without a place in the layering: {unknown} (add them to LEVELS and DESIGN.md)"


def _violations(sources: list[tuple[Path, str]]) -> list[str]:
    found = []
    for path, area in sources:
        for name in INCLUDE.findall(path.read_text()):
            used = _area_of_include(name)
            if used != area and used in LEVELS and LEVELS[used] >= LEVELS[area]:
                found.append(f"{path.name} ({area}) includes {name} ({used})")
    return found


def test_no_area_includes_a_higher_or_peer_area() -> None:
    violations = _violations(_sources())
    assert not violations, "layering broken:\n" + "\n".join(violations)


def test_the_layering_check_catches_upward_and_peer_includes(tmp_path: Path) -> None:
    upward = tmp_path / "orbit_extra.hpp"
    upward.write_text('#include "vistrack/geometry.hpp"\n#include "vistrack/simulate.hpp"\n')
    peer = tmp_path / "tour.cpp"
    peer.write_text('#include "loiter/detail.hpp"\n#include "vistrack/flight.hpp"\n')
    fine = tmp_path / "kernel.cpp"
    fine.write_text('#include "dubins/kernel.hpp"\n#include "vistrack/environment.hpp"\n')
    assert _violations([(upward, "orbit"), (peer, "follow"), (fine, "dubins")]) == [
        "orbit_extra.hpp (orbit) includes vistrack/simulate.hpp (simulate)",
        "tour.cpp (follow) includes loiter/detail.hpp (loiter)",
    ]


def _imported_modules(path: Path) -> set[str]:
    """Absolute names of the vistrack modules a file imports (relative imports resolved)."""
    package = "vistrack." + ".".join(path.relative_to(REPO / "python" / "vistrack").with_suffix("").parts)
    package = package.rsplit(".", 1)[0] if path.name != "__init__.py" else package.removesuffix(".__init__")
    names = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            names |= {alias.name for alias in node.names}
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")
                base = base[: len(base) - node.level + 1]
                module = ".".join(base + ([node.module] if node.module else []))
            else:
                module = node.module or ""
            names.add(module)
            names |= {f"{module}.{alias.name}" for alias in node.names}
    return names


def test_the_library_never_imports_the_cli() -> None:
    root = REPO / "python" / "vistrack"
    offenders = []
    for path in sorted(root.rglob("*.py")):
        relative = path.relative_to(root)
        if relative.parts[0] == "commands" or relative.name in ("cli.py", "__main__.py"):
            continue
        bad = sorted(m for m in _imported_modules(path) if m.startswith(("vistrack.commands", "vistrack.cli")))
        if bad:
            offenders.append(f"{relative}: {bad}")
    assert not offenders, "library modules import the CLI:\n" + "\n".join(offenders)


def test_importing_the_library_loads_no_command_module() -> None:
    code = ("import sys, vistrack, vistrack.pipeline, vistrack.report; "
            "print([m for m in sys.modules if m.startswith(('vistrack.commands', 'vistrack.cli'))])")
    env_path = str(Path(__file__).parent)
    run = subprocess.run([sys.executable, "-c", f"import sys; sys.path.insert(0, {env_path!r}); import conftest; {code}"],
                         capture_output=True, text=True, check=True, cwd=REPO)
    assert run.stdout.strip().splitlines()[-1] == "[]"
