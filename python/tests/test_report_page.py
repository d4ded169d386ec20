"""`liftoff report` / `--report`: the page opens in headless Chromium without a console error, a
script error or a resource load (it must be self-contained), shows every figure with a size, and
prints with each figure on a page of its own.

The browser is driven through the DevTools protocol over a pipe (`--remote-debugging-pipe`):
every console message, uncaught exception, log entry (a failed load logs "Failed to load
resource") and network request of the page is an event, so nothing depends on what Chromium
prints on stderr. Chromium is required: `./test` installs it when missing, and without it these
tests fail (they never skip)."""

from __future__ import annotations

import base64
import json
import os
import pathlib
import re
import select
import shutil
import subprocess
import tempfile
import time

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
BIN = os.environ.get("LIFTOFF_BIN", str(ROOT / "target" / "release" / "liftoff"))


def chromium() -> str:
    """The browser: $LIFTOFF_CHROMIUM, or chromium / chromium-browser / google-chrome on PATH."""
    for name in (os.environ.get("LIFTOFF_CHROMIUM"), "chromium", "chromium-browser", "google-chrome"):
        if name and shutil.which(name):
            return shutil.which(name)
    pytest.fail(
        "headless Chromium is needed to test report.html and none was found "
        "(chromium, chromium-browser, google-chrome, or $LIFTOFF_CHROMIUM); "
        "./test installs Debian's `chromium` package when it is missing"
    )


class Browser:
    """One headless Chromium driven over --remote-debugging-pipe (fd 3 in, fd 4 out)."""

    def __init__(self, timeout: float = 60.0):
        self.timeout = timeout
        self.profile = tempfile.TemporaryDirectory(prefix="liftoff-chromium-")
        to_child_r, self.to_child = os.pipe()
        self.from_child, from_child_w = os.pipe()

        def fds():
            # Through fresh descriptors, so that neither end lands on the other's number first;
            # the child keeps 3 and 4 only (pass_fds: closing the rest comes after this).
            a, b = os.dup(to_child_r), os.dup(from_child_w)
            os.dup2(a, 3)
            os.dup2(b, 4)

        self.proc = subprocess.Popen(
            [
                chromium(),
                "--headless",
                "--disable-gpu",
                "--no-sandbox",
                "--no-first-run",
                "--disable-extensions",
                "--disable-background-networking",
                "--disable-component-update",
                "--disable-sync",
                f"--user-data-dir={self.profile.name}",
                "--remote-debugging-pipe",
                "about:blank",
            ],
            stdin=subprocess.DEVNULL,
            stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL,
            preexec_fn=fds,
            pass_fds=(3, 4),
        )
        os.close(to_child_r)
        os.close(from_child_w)
        self.buffer = b""
        self.next_id = 0
        self.events: list[dict] = []

    def send(self, method: str, params: dict | None = None, session: str | None = None) -> dict:
        """Send a command and wait for its answer (events that arrive meanwhile are kept)."""
        self.next_id += 1
        message = {"id": self.next_id, "method": method, "params": params or {}}
        if session:
            message["sessionId"] = session
        os.write(self.to_child, json.dumps(message).encode() + b"\0")
        while True:
            m = self.receive()
            if m.get("id") == self.next_id:
                if "error" in m:
                    raise AssertionError(f"{method}: {m['error']}")
                return m.get("result", {})
            self.events.append(m)

    def receive(self, deadline: float | None = None) -> dict:
        deadline = deadline or time.monotonic() + self.timeout
        while b"\0" not in self.buffer:
            left = deadline - time.monotonic()
            if left <= 0:
                raise TimeoutError("no message from chromium")
            ready, _, _ = select.select([self.from_child], [], [], left)
            if ready:
                chunk = os.read(self.from_child, 1 << 20)
                if not chunk:
                    raise AssertionError("chromium closed its pipe")
                self.buffer += chunk
        message, self.buffer = self.buffer.split(b"\0", 1)
        return json.loads(message)

    def wait_for(self, method: str, seconds: float) -> None:
        """Keep events until `method` arrives (or `seconds` pass: then fail)."""
        deadline = time.monotonic() + seconds
        while not any(e.get("method") == method for e in self.events):
            self.events.append(self.receive(deadline))

    def drain(self, seconds: float) -> None:
        """Keep the events that arrive within `seconds`."""
        deadline = time.monotonic() + seconds
        try:
            while True:
                self.events.append(self.receive(deadline))
        except TimeoutError:
            pass

    def close(self) -> None:
        try:
            self.send("Browser.close")
        except Exception:
            pass
        try:
            self.proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()
        os.close(self.to_child)
        os.close(self.from_child)
        self.profile.cleanup()


def open_page(path: pathlib.Path) -> dict:
    """Load `path` in a fresh tab and report what happened: the page's problems (console errors
    and warnings, uncaught exceptions, error log entries, failed loads, every request for
    anything but the page itself), what its DOM shows, and how many pages it prints on."""
    url = path.resolve().as_uri()
    b = Browser()
    try:
        target = b.send("Target.createTarget", {"url": "about:blank"})["targetId"]
        session = b.send("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
        for domain in ("Runtime", "Log", "Network", "Page"):
            b.send(f"{domain}.enable", session=session)
        b.send("Page.navigate", {"url": url}, session=session)
        b.wait_for("Page.loadEventFired", 60)
        b.drain(1.0)
        shown = b.send(
            "Runtime.evaluate",
            {
                "expression": """JSON.stringify({
                    title: document.title,
                    figures: Array.from(document.querySelectorAll('figure.chart')).map(f => {
                        const s = f.querySelector(':scope > svg');
                        const r = s ? s.getBoundingClientRect() : {width: 0, height: 0};
                        return {svg: !!s, width: r.width, height: r.height,
                                shapes: s ? s.querySelectorAll('rect,polygon,polyline,path,circle,line,text').length : 0,
                                namespace: s ? s.namespaceURI : ''};
                    }),
                    tables: document.querySelectorAll('table').length,
                    scripts: document.querySelectorAll('script').length,
                    sources: document.querySelectorAll('[src],link,iframe,object,embed').length,
                    text: document.body.innerText,
                })""",
                "returnByValue": True,
            },
            session=session,
        )["result"]["value"]
        # As printed on A4 (190 mm between the margins, 718 px): nothing wider than the page.
        b.send("Emulation.setEmulatedMedia", {"media": "print"}, session=session)
        b.send(
            "Emulation.setDeviceMetricsOverride",
            {"width": 718, "height": 1000, "deviceScaleFactor": 1, "mobile": False},
            session=session,
        )
        wide = b.send(
            "Runtime.evaluate",
            {
                "expression": """JSON.stringify(Array.from(document.querySelectorAll('body *'))
                    .filter(e => e.getBoundingClientRect().right > window.innerWidth + 1)
                    .slice(0, 5).map(e => e.tagName + ' ' + (e.textContent || '').slice(0, 60)))""",
                "returnByValue": True,
            },
            session=session,
        )["result"]["value"]
        b.send("Emulation.clearDeviceMetricsOverride", session=session)
        pdf = b.send("Page.printToPDF", {"printBackground": True}, session=session)["data"]
        pages = len(re.findall(rb"/Type\s*/Page(?!s)", base64.b64decode(pdf)))
        b.drain(0.5)
    finally:
        b.close()
    problems = []
    for e in b.events:
        m, p = e.get("method"), e.get("params", {})
        if m == "Runtime.exceptionThrown":
            problems.append(f"exception: {p['exceptionDetails'].get('exception', {}).get('description') or p['exceptionDetails'].get('text')}")
        elif m == "Runtime.consoleAPICalled" and p.get("type") in ("error", "warning", "assert"):
            problems.append(f"console.{p['type']}: {[a.get('value', a.get('description')) for a in p.get('args', [])]}")
        elif m == "Log.entryAdded" and p["entry"].get("level") in ("error", "warning"):
            problems.append(f"log {p['entry']['level']}: {p['entry'].get('text')} {p['entry'].get('url', '')}")
        elif m == "Network.loadingFailed":
            problems.append(f"failed load: {p.get('errorText')}")
        elif m == "Network.requestWillBeSent" and p["request"]["url"] != url:
            problems.append(f"request: {p['request']['url']}")
    shown = json.loads(shown)
    shown["problems"] = problems
    shown["pages"] = pages
    shown["wider_than_print"] = json.loads(wide)
    return shown


def cli(*args: str) -> subprocess.CompletedProcess:
    p = subprocess.run([BIN, *args], capture_output=True, text=True)
    assert p.returncode == 0, f"liftoff {' '.join(args)}: exit {p.returncode}\n{p.stderr}"
    return p


def svgs(folder: pathlib.Path) -> list:
    return sorted(folder.glob("*.svg")) + sorted(folder.glob("*/*.svg"))


def check(report: pathlib.Path, figures: int) -> dict:
    shown = open_page(report)
    assert shown["problems"] == [], f"{report}: {shown['problems']}"
    assert shown["scripts"] == 0 and shown["sources"] == 0, shown
    assert len(shown["figures"]) == figures, f"{len(shown['figures'])} figures, {figures} SVG files"
    for i, f in enumerate(shown["figures"], 1):
        assert f["svg"] and f["namespace"] == "http://www.w3.org/2000/svg", f"figure {i}: {f}"
        assert f["width"] > 300 and f["height"] > 200, f"figure {i} is not drawn at a readable size: {f}"
        assert f["shapes"] > 10, f"figure {i} is empty: {f}"
    assert shown["wider_than_print"] == [], f"cut off in print: {shown['wider_than_print']}"
    # Printed, every figure starts a page.
    assert shown["pages"] > figures, f"{shown['pages']} printed pages for {figures} figures"
    return shown


def test_the_report_of_a_jointed_solve_opens_clean(tmp_path):
    out = tmp_path / "pavement"
    cli("solve", str(ROOT / "examples" / "pavement-3x3.toml"), "--out", str(out), "--report")
    shown = check(out / "report.html", len(svgs(out)))
    assert shown["title"].startswith("Jointed pavement, 3 × 3 panels"), shown["title"]
    for words in ("Combinations and envelope", "axle-night: Joints", "Dowels", "largest deflection", "nodes.csv"):
        assert words in shown["text"], f"`{words}` not on the page"


def test_the_report_of_a_critical_search_opens_clean(tmp_path):
    out = tmp_path / "critical"
    cli("critical", "example:pavement-3x3", "--load", "axle", "--grid", "5,3", "--out", str(out), "--report")
    shown = check(out / "report.html", len(svgs(out)))
    for words in ("Critical positions", "bottom tension", "dowel force", "Influence maps"):
        assert words in shown["text"], f"`{words}` not on the page"


def test_a_scene_title_with_markup_stays_text(tmp_path):
    scene = (ROOT / "examples" / "slab-on-grade.toml").read_text()
    scene = re.sub(r'^title = ".*"$', 'title = "<script>alert(1)</script><img src=x onerror=alert(2)>"', scene, count=1, flags=re.M)
    path = tmp_path / "scene.toml"
    path.write_text(scene)
    out = tmp_path / "slab"
    cli("solve", str(path), "--out", str(out))
    cli("report", str(out))
    shown = check(out / "report.html", len(svgs(out)))
    assert shown["title"] == "<script>alert(1)</script><img src=x onerror=alert(2)>", shown["title"]


def test_the_check_sees_a_script_error_and_a_missing_file(tmp_path):
    """The checker itself: a page with a console error, an uncaught exception and a missing
    image is not clean (so that the tests above could fail)."""
    bad = tmp_path / "bad.html"
    bad.write_text(
        "<!DOCTYPE html><html><head><title>bad</title></head><body>"
        '<img src="missing.png"><script>console.error("boom"); undefinedFunction();</script>'
        "</body></html>"
    )
    problems = "\n".join(open_page(bad)["problems"])
    assert "boom" in problems, problems
    assert "undefinedFunction" in problems, problems
    assert "missing.png" in problems, problems
