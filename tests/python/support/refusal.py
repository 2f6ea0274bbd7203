"""How the tests of bad input check a refusal: the call raises VistrackError (or the given type)
whose message holds every expected fragment (the field, the value, the range)."""

from __future__ import annotations

from typing import Any, Callable

import pytest

from vistrack import VistrackError


def refuses(call: Callable[[], Any], *fragments: str, error: type[BaseException] = VistrackError) -> str:
    """``call()`` raises ``error`` whose message holds every fragment; the message."""
    with pytest.raises(error) as raised:
        call()
    message = str(raised.value)
    for fragment in fragments:
        assert fragment in message, f"{fragment!r} not in {message!r}"
    return message
