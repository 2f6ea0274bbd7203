"""The Dask worker plugin that gives each worker its own :class:`~vistrack.sweep.resources.Resources`.

Kept apart from :mod:`vistrack.sweep.resources` so that ``import vistrack`` does not import
Dask; a worker imports this module when it unpickles the plugin.
"""

from __future__ import annotations

from typing import Any, Optional

from distributed.diagnostics.plugin import WorkerPlugin

from .resources import PLUGIN_NAME, Resources

__all__ = ["SweepPlugin"]


class SweepPlugin(WorkerPlugin):
    """Set up on every worker when registered (``Client.register_plugin``) and on workers that
    join later: a fresh Resources per worker (built there: the plugin is pickled without it)."""

    name = PLUGIN_NAME

    def __init__(self) -> None:
        self.resources: Optional[Resources] = None

    def setup(self, worker: Any) -> None:
        self.resources = Resources()
