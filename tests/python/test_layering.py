"""The architecture holds (DESIGN.md, Layers and The Python layer): a lower C++ area never includes
a higher one; over the Python package's whole import graph (imports in functions and under
TYPE_CHECKING included) there is no circle, the products (tracking, waypoint_nav, loiter, follow)
never import one another, the models never import report, plotting, sweep or commands, and the
library never imports its command line; the compiled module imports no Python; modules stay small
(450 lines, command modules 120); ``import vistrack`` loads neither matplotlib nor Dask."""

from __future__ import annotations

import ast
import re
import subprocess
import sys
from pathlib import Path

from support.paths import REPO

# Bottom to top. error/limits (the input ranges)/simd (the CPU check of the AVX2 kernels)/geometry
# are the base every area may use; planners are peers of one another and may not include each other.
LEVELS = {
    "error": 0, "limits": 0.5, "simd": 0.5, "geometry": 1, "environment": 3, "dubins": 4, "visibility": 5,
    "volume": 6,
    "vehicle": 4.5, "orbit": 7, "guidance": 8, "ode": 9, "simulate": 10, "flight": 11,
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


PACKAGE = REPO / "python" / "vistrack"
PRODUCTS = {"tracking", "waypoint_nav", "loiter", "follow"}
VIEWS = {"report", "plotting", "sweep", "commands"}  # what a model never imports
NOT_MODELS = VIEWS | {"cli", "__main__"}
MODULE_LINES, COMMAND_LINES = 450, 120


def _module_names(root: Path) -> dict[str, Path]:
    """Dotted name -> file of every module of the package at ``root`` (a package is its __init__)."""
    names = {}
    for path in sorted(root.rglob("*.py")):
        parts = [root.name, *path.relative_to(root).with_suffix("").parts]
        names[".".join(parts[:-1] if parts[-1] == "__init__" else parts)] = path
    return names


def _imported_modules(path: Path, root: Path = PACKAGE) -> set[str]:
    """Absolute names of what a file imports (``from a import b``: a.b, a module or a name in a),
    anywhere in it: at the top, in functions and under TYPE_CHECKING alike; relative imports
    resolved."""
    parts = [root.name, *path.relative_to(root).with_suffix("").parts]
    package = parts[:-1]  # a module's package; __init__'s is the package itself
    names = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            names |= {alias.name for alias in node.names}
        elif isinstance(node, ast.ImportFrom):
            base = package[: len(package) - node.level + 1] if node.level else []
            module = ".".join(base + ([node.module] if node.module else []))
            names |= {f"{module}.{alias.name}" for alias in node.names}
    return names


def _import_graph(root: Path = PACKAGE) -> dict[str, set[str]]:
    """Module -> the package's modules it imports (an imported name that is no module counts as
    its module; importing a.b.c counts as importing a.b.c, not its parent packages). The compiled
    ``_core`` imports no Python and is left out."""
    modules = _module_names(root)
    graph = {}
    for name, path in modules.items():
        used = set()
        for imported in _imported_modules(path, root):
            if imported.split(".")[1:2] == ["_core"]:
                continue
            while imported and imported not in modules:
                imported = imported.rpartition(".")[0]
            if imported and imported != name:
                used.add(imported)
        graph[name] = used
    return graph


def _cycle(graph: dict[str, set[str]]) -> list[str]:
    """One import circle as [a, b, ..., a], or [] when there is none (depth-first search)."""
    state: dict[str, int] = {}  # 1: on the current path, 2: done
    path: list[str] = []

    def visit(node: str) -> list[str]:
        state[node] = 1
        path.append(node)
        for nxt in sorted(graph.get(node, ())):
            if state.get(nxt) == 1:
                return [*path[path.index(nxt):], nxt]
            if nxt not in state and (found := visit(nxt)):
                return found
        state[node] = 2
        path.pop()
        return []

    for start in sorted(graph):
        if start not in state and (found := visit(start)):
            return found
    return []


def _area(module: str) -> str:
    """vistrack.loiter.files -> loiter; vistrack (the package itself) -> ''."""
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else ""


def _rule_breaks(graph: dict[str, set[str]]) -> list[str]:
    """Imports a product makes of another product's modules, and a model's of a view."""
    found = []
    for module, used in sorted(graph.items()):
        for target in sorted(used):
            mine, theirs = _area(module), _area(target)
            if mine in PRODUCTS and theirs in PRODUCTS and mine != theirs:
                found.append(f"product {module} imports {target} (another product)")
            if mine not in NOT_MODELS and theirs in VIEWS:
                found.append(f"model {module} imports {target} ({theirs})")
    return found


def _too_long(root: Path = PACKAGE) -> list[str]:
    """Modules over MODULE_LINES lines, command modules over COMMAND_LINES (the stubs are .pyi)."""
    found = []
    for path in sorted(root.rglob("*.py")):
        relative = path.relative_to(root)
        limit = COMMAND_LINES if relative.parts[0] == "commands" else MODULE_LINES
        lines = len(path.read_text().splitlines())
        if lines > limit:
            found.append(f"{relative}: {lines} lines (at most {limit})")
    return found


def _python_imports_in_bindings(folder: Path) -> list[str]:
    """Binding sources that import the Python package (the compiled module must not)."""
    return [f"{path.name}:{n}" for path in sorted(folder.glob("*.cpp"))
            for n, line in enumerate(path.read_text().splitlines(), start=1) if 'import("vistrack' in line]


def test_the_library_never_imports_the_cli() -> None:
    offenders = []
    for path in sorted(PACKAGE.rglob("*.py")):
        relative = path.relative_to(PACKAGE)
        if relative.parts[0] == "commands" or relative.name in ("cli.py", "__main__.py"):
            continue
        bad = sorted(m for m in _imported_modules(path) if m.startswith(("vistrack.commands", "vistrack.cli")))
        if bad:
            offenders.append(f"{relative}: {bad}")
    assert not offenders, "library modules import the CLI:\n" + "\n".join(offenders)


def test_the_package_has_no_import_circle() -> None:
    cycle = _cycle(_import_graph())
    assert not cycle, "import circle: " + " -> ".join(cycle)


def test_products_and_models_keep_their_imports() -> None:
    breaks = _rule_breaks(_import_graph())
    assert not breaks, "import rules broken:\n" + "\n".join(breaks)


def test_no_module_is_too_long() -> None:
    long = _too_long()
    assert not long, "split these modules:\n" + "\n".join(long)


def test_the_compiled_module_never_imports_python() -> None:
    found = _python_imports_in_bindings(REPO / "bindings")
    assert not found, "bindings import the Python package (attach such methods in Python): " + ", ".join(found)


def _tree(root: Path, files: dict[str, str]) -> Path:
    """A synthetic package ``vistrack`` under ``root`` with the given files."""
    package = root / "vistrack"
    for name, text in files.items():
        (package / name).parent.mkdir(parents=True, exist_ok=True)
        (package / name).write_text(text)
    return package


def test_the_import_checks_catch_circles_and_broken_rules(tmp_path: Path) -> None:
    package = _tree(tmp_path, {
        "__init__.py": "from . import io\n",
        "io/__init__.py": "from .text import read\n",
        "io/text.py": "def read(): pass\n",
        "mission/__init__.py": "from typing import TYPE_CHECKING\nif TYPE_CHECKING:\n    from ..loiter import plan\n",
        "loiter/__init__.py": "def plan():\n    from ..mission import builder\n",
        "mission/builder.py": "from vistrack.io.text import read\n",
        "follow/run.py": "from ..loiter import plan\nfrom ..plotting import figures\n",
        "plotting/figures.py": "from ..follow import run\n",
        "plotting/__init__.py": "",
        "follow/__init__.py": "",
        "report/loiter.py": "from ..loiter import plan\n",
    })
    graph = _import_graph(package)
    assert graph["vistrack.mission.builder"] == {"vistrack.io.text"}
    assert graph["vistrack.loiter"] == {"vistrack.mission.builder"}  # a function-level import counts
    assert _cycle(graph) == ["vistrack.follow.run", "vistrack.plotting.figures", "vistrack.follow.run"]
    del graph["vistrack.follow.run"]
    assert _cycle(graph) == []  # mission -> loiter -> mission.builder is no circle: builder imports io only
    graph["vistrack.mission.builder"].add("vistrack.mission")
    assert _cycle(graph) == ["vistrack.loiter", "vistrack.mission.builder", "vistrack.mission", "vistrack.loiter"]
    assert _rule_breaks(_import_graph(package)) == [
        "product vistrack.follow.run imports vistrack.loiter (another product)",
        "model vistrack.follow.run imports vistrack.plotting.figures (plotting)",
    ]


def test_the_size_and_binding_checks_catch_offenders(tmp_path: Path) -> None:
    package = _tree(tmp_path, {
        "small.py": "x = 1\n" * MODULE_LINES,
        "big.py": "x = 1\n" * (MODULE_LINES + 1),
        "commands/__init__.py": "x = 1\n" * (COMMAND_LINES + 1),
        "commands/run.py": "x = 1\n" * COMMAND_LINES,
        "_core/__init__.pyi": "x: int\n" * 2000,
    })
    assert _too_long(package) == [f"big.py: {MODULE_LINES + 1} lines (at most {MODULE_LINES})",
                                  f"commands/__init__.py: {COMMAND_LINES + 1} lines (at most {COMMAND_LINES})"]
    bindings = tmp_path / "bindings"
    bindings.mkdir()
    (bindings / "bind_orbit.cpp").write_text('auto m = py::module_::import("numpy");\n'
                                            'return py::module_::import("vistrack.mission").attr("f")();\n')
    (bindings / "bind_loiter.cpp").write_text("// no import\n")
    assert _python_imports_in_bindings(bindings) == ["bind_orbit.cpp:2"]


def _loaded_after(code: str, prefixes: tuple[str, ...]) -> list[str]:
    """The modules starting with ``prefixes`` a fresh interpreter holds after running ``code``."""
    setup = f"import sys; sys.path.insert(0, {str(Path(__file__).parent)!r}); import conftest"
    show = f"print([m for m in sys.modules if m.startswith({prefixes!r})])"
    run = subprocess.run([sys.executable, "-c", f"{setup}; {code}; {show}"], capture_output=True, text=True,
                         check=True, cwd=REPO)
    loaded: list[str] = ast.literal_eval(run.stdout.strip().splitlines()[-1])
    return loaded


def test_importing_the_library_loads_no_command_module() -> None:
    assert _loaded_after("import vistrack, vistrack.pipeline, vistrack.report",
                         ("vistrack.commands", "vistrack.cli")) == []


def test_importing_vistrack_loads_neither_matplotlib_nor_dask() -> None:
    assert _loaded_after("import vistrack", ("matplotlib", "dask", "distributed")) == []


def test_importing_vistrack_does_not_load_jsbsim() -> None:
    """JSBSim loads with the first 6-DOF flight (vistrack.fdm), not with the package."""
    assert _loaded_after("import vistrack, vistrack.pipeline", ("jsbsim",)) == []
