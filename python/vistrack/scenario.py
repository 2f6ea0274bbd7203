"""Moved: the code lives in ``vistrack.tracking.scenario``; this name stays for old imports."""

from .tracking.scenario import *  # noqa: F403
from .tracking.scenario import __all__  # noqa: F401
