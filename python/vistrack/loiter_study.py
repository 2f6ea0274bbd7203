"""Moved: the code lives in ``vistrack.loiter.study``; this name stays for old imports."""

from .loiter.study import *  # noqa: F403
from .loiter.study import __all__  # noqa: F401
