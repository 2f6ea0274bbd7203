"""Moved: the code lives in ``vistrack.follow.scenario``; this name stays for old imports."""

from .follow.scenario import *  # noqa: F403
from .follow.scenario import __all__  # noqa: F401
