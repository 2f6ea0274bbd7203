"""Griffe extension: read ``Name = _module.Name`` as a re-export, so the API reference shows it.

The package's thin modules re-export the compiled module's classes and functions by
assignment (``Wind = _flight.Wind``, with ``from ._core import flight as _flight``). Static
analysis sees an attribute with no docstring there and hides it; this extension makes each such
assignment an alias of its target, whose documentation comes from the ``_core/*.pyi`` stubs.
"""

from __future__ import annotations

from typing import Any

import griffe


class AssignedReexports(griffe.Extension):
    def on_module_members(self, *, mod: griffe.Module, **kwargs: Any) -> None:
        for name, member in list(mod.members.items()):
            if member.is_alias or not member.is_attribute:
                continue
            parts = str(getattr(member, "value", "")).split(".")
            if len(parts) != 2 or parts[0] not in mod.imports:
                continue
            target = f"{mod.imports[parts[0]]}.{parts[1]}"
            mod.set_member(name, griffe.Alias(name, target, lineno=member.lineno,
                                              endlineno=member.endlineno, parent=mod))
