"""Old addresses of names that moved into a product package: a shared package (``io``, ``mission``)
must not import the products built on it, so it finds such a name on first use instead."""

from __future__ import annotations

import importlib
from typing import Any, Callable


def forward(package: str, moved: dict[str, str]) -> Callable[[str], Any]:
    """A module ``__getattr__`` that answers each name of ``moved`` from the module named for it
    (or with that module itself when it is the package's submodule of that name)."""

    def __getattr__(name: str) -> Any:
        if name in moved:
            module = importlib.import_module(moved[name])
            return module if module.__name__ == f"{package}.{name}" else getattr(module, name)
        raise AttributeError(f"module {package!r} has no attribute {name!r}")

    __getattr__.moved = dict(moved)  # type: ignore[attr-defined]  # what it answers (tests check each)
    return __getattr__
