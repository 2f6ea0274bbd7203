"""Moved: the code lives in ``vistrack.tracking.saved_volumes``; this name stays for old imports."""

from .tracking.saved_volumes import *  # noqa: F403
from .tracking.saved_volumes import __all__  # noqa: F401
