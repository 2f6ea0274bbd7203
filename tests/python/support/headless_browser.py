"""Load an HTML page in headless Chromium, collect its errors and take a screenshot.

Chromium writes every console message to stderr as ``INFO:CONSOLE`` whatever its level, so the
page is loaded from a copy with a small script first in <head> that reports console.error calls,
uncaught errors, rejected promises and, once plotly has drawn, the figure's trace count, each
as a tagged console.log line. Run as a script to take a screenshot of a report by hand:
``python tests/python/support/headless_browser.py report.html shot.png``.
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
from dataclasses import dataclass, field
from pathlib import Path

TAG = "VISTRACK-PAGE"
HOOK = """<script>
(function () {
  var log = console.log.bind(console);
  console.error = function () { log("%(tag)s error " + Array.prototype.join.call(arguments, " ")); };
  window.addEventListener("error", function (e) { log("%(tag)s error " + e.message); });
  window.addEventListener("unhandledrejection", function (e) { log("%(tag)s error rejected " + e.reason); });
  function exercise(gd) {
    // What a reader does: the time slider's last step, then the volume slider's last step.
    var sliders = gd.layout.sliders || [];
    var time = sliders.filter(function (s) { return s.steps[0].method === "animate"; })[0];
    var layer = sliders.filter(function (s) { return s.steps[0].method === "restyle"; })[0];
    var last = time.steps[time.steps.length - 1];
    Plotly.animate(gd, last.args[0], last.args[1]).then(function () {
      var uav = gd._fullData.filter(function (t) { return t.name === "UAV"; })[0];
      log("%(tag)s animated frame=" + last.args[0][0] + " x=" + uav.x[0] + " y=" + uav.y[0]);
      if (!layer) return;
      var step = layer.steps[layer.steps.length - 1];
      return Plotly.restyle(gd, step.args[0], step.args[1]).then(function () {
        var shown = gd._fullData.filter(function (t) { return t.name === "visibility volume"; })
          .map(function (t) { return t.visible === true ? "1" : "0"; }).join("");
        log("%(tag)s layers visible=" + shown);
      });
    }).catch(function (e) { log("%(tag)s error exercise " + e); });
  }
  window.addEventListener("load", function () {
    setTimeout(function () {
      var gd = document.getElementById("figure3d");
      var traces = gd && gd._fullData ? gd._fullData.length : -1;
      var canvases = document.querySelectorAll("#figure3d canvas").length;
      log("%(tag)s plot traces=" + traces + " canvases=" + canvases);
      if (window.VISTRACK_EXERCISE && traces > 0) exercise(gd);
    }, 2000);
  });
})();
</script>""" % {"tag": TAG}


def find_chromium() -> str | None:
    """The Chromium (or Chrome) executable, or None."""
    for name in (os.environ.get("VISTRACK_CHROMIUM", ""), "chromium", "chromium-browser", "google-chrome"):
        if name and shutil.which(name):
            return shutil.which(name)
    return None


@dataclass
class PageLoad:
    errors: list[str] = field(default_factory=list)
    plot: dict[str, int] = field(default_factory=dict)
    animated: dict[str, str] = field(default_factory=dict)  # frame, x, y of the UAV after the time slider
    layers: str = ""  # "0001": which VV is visible after the volume slider's last step
    log: str = ""


def load(page: Path, screenshot: Path, size: tuple[int, int] = (1400, 1000), budget_ms: int = 25000,
         chromium: str | None = None, exercise: bool = False) -> PageLoad:
    """Open ``page`` (through a hooked copy beside ``screenshot``), wait ``budget_ms`` of virtual
    time, save the screenshot and return what the page reported. With ``exercise``, the page
    also moves the time slider and the volume slider to their last steps (the screenshot then
    shows that state)."""
    chromium = chromium or find_chromium()
    if chromium is None:
        raise RuntimeError("no chromium executable")
    text = Path(page).read_text(encoding="utf-8")
    head = text.index("<head>") + len("<head>")
    copy = screenshot.with_name(screenshot.stem + "_page.html")
    flag = "<script>window.VISTRACK_EXERCISE = true;</script>" if exercise else ""
    copy.write_text(text[:head] + flag + HOOK + text[head:], encoding="utf-8")
    command = [chromium, "--headless", "--no-sandbox", "--hide-scrollbars", "--enable-unsafe-swiftshader",
               "--use-angle=swiftshader", "--enable-logging=stderr", "--v=0", f"--window-size={size[0]},{size[1]}",
               f"--virtual-time-budget={budget_ms}", f"--screenshot={screenshot}", copy.resolve().as_uri()]
    done = subprocess.run(command, capture_output=True, text=True, timeout=180)
    result = PageLoad(log=done.stderr)
    for line in done.stderr.splitlines():
        found = re.search(TAG + r" (error|plot|animated|layers) (.*?)\", source", line)
        if not found:
            continue
        kind, text = found.groups()
        if kind == "error":
            result.errors.append(text)
        elif kind == "plot":
            result.plot = {k: int(v) for k, v in re.findall(r"(\w+)=(-?\d+)", text)}
        elif kind == "animated":
            result.animated = dict(re.findall(r"(\w+)=(\S+)", text))
        else:
            result.layers = text.split("=", 1)[1]
        # Uncaught errors also appear untagged when the hook itself could not run.
    result.errors += [line for line in done.stderr.splitlines() if "CONSOLE" in line and "Uncaught" in line
                      and TAG not in line]
    copy.unlink()
    return result


if __name__ == "__main__":
    loaded = load(Path(sys.argv[1]), Path(sys.argv[2]), exercise="--exercise" in sys.argv[3:])
    print(f"plot: {loaded.plot}; errors: {loaded.errors or 'none'}; animated: {loaded.animated}; "
          f"layers: {loaded.layers}; screenshot: {sys.argv[2]}")
