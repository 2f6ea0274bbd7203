"""Checking a Dask scheduler address before a sweep connects to it: the address's form and port,
a TCP connection within CONNECT_TIMEOUT_S, and a peer that answers Dask's handshake and an
``identity`` request as a scheduler. distributed's own ``Client(address, timeout=...)`` waits for
the peer's handshake without a timeout (a TCP service that says nothing hung a sweep forever) and
retries a refused connection until its timeout (21 s for an address nothing listens on)."""

from __future__ import annotations

import asyncio
import queue
import socket
import threading
from typing import Any

from .._core import VistrackError

__all__ = ["CONNECT_TIMEOUT_S", "check_scheduler"]

CONNECT_TIMEOUT_S = 5.0  # s: TCP connection, Dask handshake and identity reply, each


def check_scheduler(address: str, field: str = "scheduler", timeout: float = CONNECT_TIMEOUT_S) -> None:
    """VistrackError naming ``field`` unless a Dask scheduler answers at ``address`` within
    ``timeout`` seconds per step (a malformed address or a port outside 1-65535 at once)."""
    scheme, host, port = _parse(address, field)
    if scheme in ("tcp", "tls"):
        try:
            with socket.create_connection((host, port), timeout=timeout):
                pass
        except OSError as error:
            raise VistrackError(f"{field} = {address}: cannot connect ({_reason(error)})") from None
    if scheme == "tls":
        return  # the TLS handshake needs the Dask config's certificates: Client checks it
    outcome: queue.Queue[Any] = queue.Queue()

    def probe() -> None:
        try:
            outcome.put(asyncio.run(_identity(address, timeout)))
        except BaseException as error:  # handed to the caller's thread
            outcome.put(error)

    threading.Thread(target=probe, name="vistrack-scheduler-probe", daemon=True).start()
    try:
        reply = outcome.get(timeout=3 * timeout + 1)
    except queue.Empty:
        reply = TimeoutError(f"no answer within {3 * timeout:g} s")
    if isinstance(reply, (TimeoutError, asyncio.TimeoutError, OSError)):
        raise VistrackError(f"{field} = {address}: no Dask scheduler answers there ({_reason(reply)}; "
                            f"waited at most {timeout:g} s per step)") from None
    if isinstance(reply, BaseException):  # a reply that is not Dask's protocol (an HTTP server, junk)
        raise VistrackError(f"{field} = {address}: the service there does not speak Dask's protocol "
                            f"({_reason(reply)[:120]})") from None
    if not isinstance(reply, dict) or reply.get("type") != "Scheduler":
        kind = reply.get("type") if isinstance(reply, dict) else type(reply).__name__
        raise VistrackError(f"{field} = {address}: the peer speaks Dask but is not a scheduler ({kind})")


def _parse(address: str, field: str) -> tuple[str, str, int]:
    if not isinstance(address, str) or not address.strip():
        raise VistrackError(f"{field} = {address!r}: expected a scheduler address such as tcp://host:8786")
    scheme, sep, rest = address.partition("://")
    if not sep:
        scheme, rest = "tcp", address
    if scheme not in ("tcp", "tls", "inproc", "ucx", "ws", "wss"):
        raise VistrackError(f"{field} = {address}: unknown protocol {scheme!r} (tcp://host:port, tls://...)")
    if scheme not in ("tcp", "tls"):
        return scheme, rest, 0
    host, colon, port_text = rest.rstrip("/").rpartition(":")
    host = host.strip("[]")
    if not colon or not host:
        raise VistrackError(f"{field} = {address}: expected {scheme}://host:port")
    if not port_text.isdigit() or not 1 <= int(port_text) <= 65535:
        raise VistrackError(f"{field} = {address}: the port must be a number in [1, 65535]")
    return scheme, host, int(port_text)


async def _identity(address: str, timeout: float) -> Any:
    from distributed.comm import connect

    comm = await asyncio.wait_for(connect(address, timeout=timeout), timeout)  # the handshake read too
    try:
        await asyncio.wait_for(comm.write({"op": "identity", "reply": True}), timeout)
        return await asyncio.wait_for(comm.read(), timeout)
    finally:
        comm.abort()


def _reason(error: BaseException) -> str:
    if isinstance(error, (TimeoutError, asyncio.TimeoutError, socket.timeout)):
        return str(error) or "timed out"
    if isinstance(error, socket.gaierror):
        return f"unknown host: {error.strerror}"
    text = " ".join(str(error).split())
    return f"{type(error).__name__}: {text}" if text else type(error).__name__
