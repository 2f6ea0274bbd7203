"""Moved: the code lives in ``vistrack.tracking.metrics``; this name stays for old imports."""

from .tracking.metrics import *  # noqa: F403
from .tracking.metrics import __all__  # noqa: F401
