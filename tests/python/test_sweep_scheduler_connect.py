"""``vistrack sweep --scheduler ADDR`` against addresses that are not a Dask scheduler (issue 29): a
TCP service that says nothing hung forever, one that answers garbage is not Dask, unreachable
addresses answered after 21 s, port 99999 was passed on. Each is a one-line error naming
--scheduler, within the connect timeout (vistrack.sweep.connect.CONNECT_TIMEOUT_S)."""

from __future__ import annotations

import os
import socket
import subprocess
import sys
import threading
from collections.abc import Iterator
from pathlib import Path

import pytest

from support.cli import one_line_error
from support.paths import EXAMPLES
from vistrack.sweep.connect import CONNECT_TIMEOUT_S

SWEEP = str(EXAMPLES / "sweep_follow.yaml")


@pytest.fixture
def tcp_server(request: pytest.FixtureRequest) -> Iterator[str]:
    """A plain TCP server thread on 127.0.0.1 that accepts and then says nothing, or sends
    ``request.param`` bytes; its tcp:// address."""
    reply: bytes = getattr(request, "param", b"")
    server = socket.create_server(("127.0.0.1", 0))
    accepted: list[socket.socket] = []
    stop = threading.Event()

    def serve() -> None:
        server.settimeout(0.2)
        while not stop.is_set():
            try:
                conn, _ = server.accept()
            except TimeoutError:
                continue
            except OSError:
                return
            accepted.append(conn)  # held open, silent unless there is a reply
            if reply:
                conn.sendall(reply)

    thread = threading.Thread(target=serve, daemon=True)
    thread.start()
    yield f"tcp://127.0.0.1:{server.getsockname()[1]}"
    stop.set()
    thread.join(5)
    server.close()
    for conn in accepted:
        conn.close()


def _sweep_in_a_subprocess(address: str, out: Path) -> subprocess.CompletedProcess[str]:
    code = ("import sys; sys.path.insert(0, %r); from support.build_tree import use_build_tree; use_build_tree(); "
            "from vistrack.cli import main; sys.exit(main(sys.argv[1:]))" % str(Path(__file__).parent))
    # The generous timeout only catches a hang (it hung forever); the connect timeout is 5 s a step.
    return subprocess.run([sys.executable, "-c", code, "sweep", SWEEP, "--scheduler", address, "--out", str(out)],
                          capture_output=True, text=True, timeout=120, env=dict(os.environ))


def test_a_silent_tcp_service_is_not_waited_on_forever(tcp_server: str, tmp_path: Path) -> None:
    done = _sweep_in_a_subprocess(tcp_server, tmp_path / "out")
    assert done.returncode == 1, done.stderr
    assert done.stderr.count("\n") == 1 and "Traceback" not in done.stderr, done.stderr
    assert f"--scheduler = {tcp_server}: no Dask scheduler answers there" in done.stderr
    assert f"at most {CONNECT_TIMEOUT_S:g} s" in done.stderr
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("tcp_server", [b"HTTP/1.1 400 Bad Request\r\n\r\nnot dask at all" * 8], indirect=True)
def test_a_tcp_service_answering_garbage_is_not_dask(tcp_server: str, tmp_path: Path,
                                                     capsys: pytest.CaptureFixture[str]) -> None:
    one_line_error(["sweep", SWEEP, "--scheduler", tcp_server, "--out", str(tmp_path / "out")], capsys, 1,
                   f"--scheduler = {tcp_server}", "does not speak Dask")


@pytest.mark.parametrize(("address", "fragment"), [
    ("tcp://127.0.0.1:99999", "the port must be a number in [1, 65535]"),
    ("tcp://127.0.0.1:1", "cannot connect"),
    ("tcp://no-such-host.invalid:8786", "cannot connect"),
    ("tcp://127.0.0.1", "expected tcp://host:port"),
    ("http://127.0.0.1:8786", "unknown protocol 'http'"),
])
def test_unreachable_or_malformed_addresses(address: str, fragment: str, tmp_path: Path,
                                            capsys: pytest.CaptureFixture[str]) -> None:
    one_line_error(["sweep", SWEEP, "--scheduler", address, "--out", str(tmp_path / "out")], capsys, 1,
                   f"--scheduler = {address}", fragment)
