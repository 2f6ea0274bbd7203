"""Moved: the code lives in ``vistrack.tracking.tuning``; this name stays for old imports."""

from .tracking.tuning import *  # noqa: F403
from .tracking.tuning import __all__  # noqa: F401
