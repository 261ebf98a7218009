"""A real browser, headless Chromium, loads the service's pages and reports what it saw.

The HTML pages must work in a plain browser and need no JavaScript of their own, so the
truest check is Debian's Chromium (/usr/bin/chromium): its parser, network stack, form
submission and renderer.  It is driven through the DevTools Protocol over
--remote-debugging-pipe (fd 3 = commands, fd 4 = messages, JSON ended by NUL), with the
standard library only.  The script judges nothing: it prints facts as one JSON object
(statuses, console messages, requests, element counts, broken images, sideways scrolling
on a phone) and saves screenshots and PDFs; the assertions live in the Rust test.

Usage: python3 browser.py PLAN.json   PLAN: {"base", "out", "pages": [{"path", "name",
"selectors", "evaluate"?}], "forms": [{"path", "name", "fill", "submit", "selectors"?,
"evaluate"?}], "svgs": [PATH],
"motions": [{"path", "name", "times": [s], "probes": [[[x, y]] per time]}],
"language"?: an Accept-Language every request of the run sends}
"evaluate": expressions whose values the page's or the submitted form's report gives.
The browser keeps its cookies from one item of the plan to the next (pages, then forms,
then SVGs).
A motion is an animated SVG (SMIL) opened alone at 820 x 520 CSS px: its animations paused
at each time, it reports which frames (g[data-step]) are visible, the element under each
probe (CSS px) with the frame it belongs to, and a screenshot's digest.
Exit 0 when the browser ran (a page's own trouble is reported in its "error"), else 1.
"""
import base64
import contextlib
import hashlib
import json
import os
import select
import shutil
import signal
import subprocess
import sys
import tempfile
import time

TIMEOUT = 30.0
IMAGES_DONE = "Array.from(document.images).every(i => i.complete)"
BROKEN_IMAGES = "Array.from(document.images).filter(i => i.naturalWidth === 0).map(i => i.src)"
HEIGHT = "(document.scrollingElement || document.documentElement).scrollHeight"
FOCUS = """(() => { const el = document.querySelector('[name=' + CSS.escape(%s) + ']');
  if (!el) return null; el.scrollIntoView({block: 'center'}); el.focus();
  if (el.select) el.select(); return el.localName; })()"""
CENTRE = """(() => { const el = document.querySelector(%s);
  if (!el) return null; el.scrollIntoView({block: 'center'}); const r = el.getBoundingClientRect();
  return [r.left + r.width / 2, r.top + r.height / 2]; })()"""
PAUSE_AT = """(() => { const s = document.documentElement; s.pauseAnimations(); s.setCurrentTime(%s);
  return Array.from(document.querySelectorAll('g[data-step]'))
    .filter(g => getComputedStyle(g).visibility === 'visible').map(g => +g.dataset.step); })()"""
HIT = """(() => { const e = document.elementFromPoint(%s, %s); if (!e) return null;
  const g = e.closest('g[data-step]'); return [e.localName, g ? +g.dataset.step : null]; })()"""
TWO_FRAMES = "new Promise(r => requestAnimationFrame(() => requestAnimationFrame(() => r(true))))"


class Fatal(Exception):
    """The browser could not be driven: the whole run fails."""


class PageError(Exception):
    """One page misbehaved (a timeout, a script error): reported in its entry."""


class Browser:
    def __init__(self):
        self.profile = tempfile.mkdtemp(prefix="browser-py-")
        self.log = tempfile.TemporaryFile()
        cmd_r, self.cmd_w = os.pipe()
        self.msg_r, msg_w = os.pipe()

        def child_fds():  # in the child, before exec: the pipes become fds 3 and 4
            os.dup2(cmd_r, 3)
            os.dup2(msg_w, 4)

        try:
            self.proc = subprocess.Popen(
                ["/usr/bin/chromium", "--headless", "--no-sandbox", "--disable-gpu",
                 "--disable-background-networking", f"--user-data-dir={self.profile}",
                 "--remote-debugging-pipe", "--no-first-run", "--hide-scrollbars",
                 "--host-resolver-rules=MAP * ~NOTFOUND, EXCLUDE 127.0.0.1"],
                stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=self.log,
                pass_fds=(3, 4), preexec_fn=child_fds, start_new_session=True)
        except OSError as e:
            shutil.rmtree(self.profile, ignore_errors=True)
            raise Fatal(f"cannot start /usr/bin/chromium: {e}") from None
        finally:
            os.close(cmd_r)
            os.close(msg_w)
        self.buf, self.next_id, self.session, self.frame = b"", 0, None, None
        self.reset()

    def start(self):
        target = self.call("Target.createTarget", session=False, url="about:blank")["targetId"]
        self.session = self.call("Target.attachToTarget", session=False,
                                 targetId=target, flatten=True)["sessionId"]
        for domain in ("Page", "Runtime", "Log", "Network"):
            self.call(f"{domain}.enable")
        self.frame = self.call("Page.getFrameTree")["frameTree"]["frame"]["id"]
        return self.call("Browser.getVersion", session=False)["product"]

    def close(self):
        with contextlib.suppress(OSError, subprocess.TimeoutExpired):  # politely first
            self._write({"id": 0, "method": "Browser.close"})
            self.proc.wait(5)
        with contextlib.suppress(ProcessLookupError):  # then the browser and its helpers: its process group
            os.killpg(self.proc.pid, signal.SIGKILL)
        self.proc.wait()
        os.close(self.cmd_w)
        os.close(self.msg_r)
        for _ in range(3):  # a dying helper may still write to the profile for a moment
            shutil.rmtree(self.profile, ignore_errors=True)
            if not os.path.exists(self.profile):
                break
            time.sleep(0.5)

    def stderr_tail(self):
        self.log.seek(0)  # without the D-Bus complaints of a machine with no session bus
        lines = self.log.read().decode(errors="replace").splitlines()
        return "\n".join(line for line in lines if "dbus" not in line)[-3000:]

    # --- the protocol: NUL-terminated JSON both ways ---
    def _write(self, msg):
        data = json.dumps(msg).encode() + b"\0"
        while data:
            data = data[os.write(self.cmd_w, data):]

    def _read(self, deadline):
        """The next message from the browser, or None at the deadline."""
        while b"\0" not in self.buf:
            left = deadline - time.monotonic()
            if left <= 0 or not select.select([self.msg_r], [], [], left)[0]:
                return None
            chunk = os.read(self.msg_r, 1 << 20)
            if not chunk:
                raise Fatal("the browser closed its DevTools pipe (it exited)")
            self.buf += chunk
        msg, _, self.buf = self.buf.partition(b"\0")
        return json.loads(msg)

    def call(self, method, session=True, **params):
        self.next_id += 1
        msg = {"id": self.next_id, "method": method, "params": params}
        if session:
            msg["sessionId"] = self.session
        self._write(msg)
        deadline = time.monotonic() + TIMEOUT
        while True:
            m = self._read(deadline)
            if m is None:
                raise Fatal(f"{method}: no answer from the browser within {TIMEOUT:.0f} s")
            if m.get("id") == self.next_id:
                if "error" in m:
                    raise Fatal(f"{method}: {m['error'].get('message')}")
                return m.get("result", {})
            self.on_event(m)

    def evaluate(self, expression):
        r = self.call("Runtime.evaluate", expression=expression, returnByValue=True)
        if "exceptionDetails" in r:
            d = r["exceptionDetails"]
            raise PageError(f"evaluating {expression[:60]!r}: "
                            f"{d.get('exception', {}).get('description') or d.get('text')}")
        return r["result"].get("value")

    # --- what is seen while on one page ---
    def reset(self):
        self.loaded, self.pending, self.url_of = False, set(), {}
        self.requests, self.failed, self.bad, self.console, self.document = [], [], [], [], {}
        self.nav_error = None

    def on_event(self, m):
        if "id" in m or m.get("sessionId") != self.session:
            return
        method, p = m.get("method"), m.get("params", {})
        if method == "Page.loadEventFired":
            self.loaded = True
        elif method == "Network.requestWillBeSent":
            self.url_of[p["requestId"]] = p["request"]["url"]
            self.requests.append(p["request"]["url"])
            self.pending.add(p["requestId"])
        elif method == "Network.responseReceived":
            response = p["response"]
            if p.get("type") == "Document" and p.get("frameId") == self.frame:
                self.document = {"status": response["status"], "url": response["url"],
                                 "mimeType": response.get("mimeType")}
            if response["status"] >= 400:
                self.bad.append({"url": response["url"], "status": response["status"]})
        elif method in ("Network.loadingFinished", "Network.loadingFailed"):
            self.pending.discard(p["requestId"])
            if method == "Network.loadingFailed":
                self.failed.append({"url": self.url_of.get(p["requestId"]), "errorText": p.get("errorText"),
                                    "blockedReason": p.get("blockedReason")})
        elif method == "Runtime.consoleAPICalled":
            frame = (p.get("stackTrace") or {}).get("callFrames") or [{}]
            self.console.append({"kind": "console", "level": p["type"], "url": frame[0].get("url"),
                                 "text": " ".join(map(arg_text, p.get("args", [])))})
        elif method == "Runtime.exceptionThrown":
            d = p["exceptionDetails"]
            self.console.append({"kind": "exception", "level": "error", "url": d.get("url"),
                                 "text": d.get("exception", {}).get("description") or d.get("text")})
        elif method == "Log.entryAdded":
            e = p["entry"]
            self.console.append({"kind": "log", "level": e["level"], "text": e["text"],
                                 "url": e.get("url"), "source": e.get("source")})
        elif method == "Page.javascriptDialogOpening":  # would block the page: dismiss, and say so
            self.console.append({"kind": "dialog", "level": p["type"], "text": p["message"], "url": p["url"]})
            self._write({"id": 0, "sessionId": self.session, "method": "Page.handleJavaScriptDialog",
                         "params": {"accept": False}})

    def settle(self, what):
        """Wait for the load event, no request pending, every <img> complete, 0.2 s of quiet."""
        deadline = time.monotonic() + TIMEOUT
        while True:
            if time.monotonic() >= deadline:
                raise PageError(f"{what}: not settled within {TIMEOUT:.0f} s (load event: {self.loaded}, "
                                f"pending: {sorted(self.url_of[r] for r in self.pending)})")
            m = self._read(min(deadline, time.monotonic() + 0.2))
            if m is not None:
                self.on_event(m)
            elif self.loaded and not self.pending and self.evaluate(IMAGES_DONE):
                return

    def goto(self, url):
        self.reset()
        self.call("Emulation.setDeviceMetricsOverride", width=1280, height=800, deviceScaleFactor=1, mobile=False)
        self.nav_error = self.call("Page.navigate", url=url).get("errorText")
        self.settle(f"loading {url}")

    def facts(self):
        return {"status": self.document.get("status"), "url": self.document.get("url"),
                **({"navigate_error": self.nav_error} if self.nav_error else {}),
                "console": self.console, "requests": self.requests, "failed": self.failed,
                "bad_responses": self.bad}

    def shoot(self, path, width, height, scale, mobile):
        """Full-page PNG at this width; returns [scrollWidth, innerWidth] at it."""
        metrics = dict(width=width, deviceScaleFactor=scale, mobile=mobile)
        self.call("Emulation.setDeviceMetricsOverride", height=height, **metrics)
        widths = self.evaluate("[document.documentElement.scrollWidth, window.innerWidth]")
        # scrollHeight is in CSS px; without <meta name=viewport> a phone lays out 980 px and zooms out
        full = min(max(round((self.evaluate(HEIGHT) or 1) * width / widths[1]), 1), 16384)  # cap: runaway page
        self.call("Emulation.setDeviceMetricsOverride", height=full, **metrics)
        save(path, self.call("Page.captureScreenshot", format="png", captureBeyondViewport=True)["data"])
        return widths


def save(path, data):
    """Writes base64 data to path; returns its size in bytes."""
    with open(path, "wb") as f:
        return f.write(base64.b64decode(data))


def arg_text(arg):
    """A console.log argument as text: strings as they are, other values as JSON or as described."""
    if isinstance(arg.get("value"), str):
        return arg["value"]
    return json.dumps(arg["value"]) if "value" in arg else str(arg.get("unserializableValue")
                                                               or arg.get("description") or arg.get("type"))


def common(b, selectors, expressions=()):
    return {"url": b.evaluate("location.href"), "title": b.evaluate("document.title"),
            "lang": b.evaluate("document.documentElement.lang"),
            "text": b.evaluate("document.body ? document.body.innerText : ''"),
            "counts": {s: b.evaluate(f"document.querySelectorAll({json.dumps(s)}).length") for s in selectors},
            "evaluated": {e: b.evaluate(e) for e in expressions}}


def page_report(b, base, out, page):
    name = page["name"]
    b.goto(base + page["path"])
    r = common(b, page.get("selectors", []), page.get("evaluate", []))
    r["broken_images"] = b.evaluate(BROKEN_IMAGES)
    r["screenshot"] = os.path.join(out, f"{name}.png")
    b.shoot(r["screenshot"], 1280, 800, 1, False)
    r["pdf_bytes"] = save(os.path.join(out, f"{name}.pdf"), b.call("Page.printToPDF")["data"])
    r["phone_screenshot"] = os.path.join(out, f"{name}-phone.png")
    scroll_width, inner_width = b.shoot(r["phone_screenshot"], 390, 844, 2, True)
    r["phone_overflow"], r["phone_inner_width"] = scroll_width > inner_width, inner_width
    return {**b.facts(), **r}  # facts last seen, after the screenshots too


def form_report(b, base, out, form):
    b.goto(base + form["path"])
    filled, missing = {}, []
    for field, value in form.get("fill", {}).items():
        kind = b.evaluate(FOCUS % json.dumps(field))
        if kind is None:
            missing.append(field)
            continue
        if kind == "select":  # a drop-down takes no typing: choose the option as a script would
            b.evaluate(f"(e => {{ e.value = {json.dumps(str(value))}; e.dispatchEvent(new Event('change', "
                       f"{{bubbles: true}})); }})(document.activeElement)")
        else:  # replaces the selected text, as typing would
            b.call("Input.insertText", text=str(value))
        filled[field] = b.evaluate("document.activeElement.value")
    centre = b.evaluate(CENTRE % json.dumps(form["submit"]))
    if centre is None:
        raise PageError(f"no element matches the submit selector {form['submit']!r}")
    x, y = centre
    b.loaded = False
    b.call("Input.dispatchMouseEvent", type="mouseMoved", x=x, y=y)
    for kind in ("mousePressed", "mouseReleased"):
        b.call("Input.dispatchMouseEvent", type=kind, x=x, y=y, button="left", clickCount=1)
    try:
        b.settle(f"the page after clicking {form['submit']!r}")
    except PageError as e:  # the likely cause: the browser's own validation stopped the submission
        invalid = b.evaluate("Array.from(document.querySelectorAll('[name]:invalid'), "
                             "e => `${e.name}: ${e.validationMessage}`)")
        raise PageError(f"{e}; fields the browser holds invalid: {invalid}") from None
    r = {**common(b, form.get("selectors", []), form.get("evaluate", [])), "filled": filled, "missing_fields": missing,
         "screenshot": os.path.join(out, f"{form['name']}.png")}
    b.shoot(r["screenshot"], 1280, 800, 1, False)
    return {**b.facts(), **r}


def svg_report(b, base, out, path):
    b.goto(base + path)
    return {**b.facts(), "content_type": b.document.get("mimeType"),
            "text": b.evaluate("document.documentElement ? document.documentElement.textContent : ''"),
            "root": b.evaluate("document.documentElement ? document.documentElement.localName : null"),
            "parsererror": b.evaluate("document.getElementsByTagNameNS('*', 'parsererror').length > 0")}


def motion_report(b, base, out, item):
    b.goto(base + item["path"])
    b.call("Emulation.setDeviceMetricsOverride", width=820, height=520, deviceScaleFactor=1, mobile=False)
    frames = []
    for k, (t, probes) in enumerate(zip(item["times"], item["probes"])):
        visible = b.evaluate(PAUSE_AT % json.dumps(t))
        b.call("Runtime.evaluate", expression=TWO_FRAMES, awaitPromise=True)  # drawn as paused
        shot = b.call("Page.captureScreenshot", format="png")["data"]
        save(os.path.join(out, f"{item['name']}-{k}.png"), shot)
        frames.append({"time": t, "visible": visible, "screenshot_sha256": hashlib.sha256(shot.encode()).hexdigest(),
                       "hits": [b.evaluate(HIT % (x, y)) for x, y in probes]})
    return {**b.facts(), "frames": frames}


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    with open(sys.argv[1]) as f:
        plan = json.load(f)
    base, out = plan["base"].rstrip("/"), plan["out"]
    os.makedirs(out, exist_ok=True)
    jobs = [("pages", p["name"], page_report, p) for p in plan.get("pages", [])]
    jobs += [("forms", f["name"], form_report, f) for f in plan.get("forms", [])]
    jobs += [("svgs", path, svg_report, path) for path in plan.get("svgs", [])]
    jobs += [("motions", m["name"], motion_report, m) for m in plan.get("motions", [])]
    try:
        b, failure = Browser(), None
    except Fatal as e:
        sys.exit(f"browser.py: {e}")
    try:
        report = {"pages": {}, "forms": {}, "svgs": {}, "motions": {}, "chromium": b.start()}
        if plan.get("language"):  # every request of the run asks for this language, as a browser set to it does
            b.call("Network.setExtraHTTPHeaders", headers={"Accept-Language": plan["language"]})
        for section, name, run, item in jobs:
            try:
                report[section][name] = run(b, base, out, item)
            except PageError as e:  # the page's trouble, for the Rust test to judge
                print(f"browser.py: {section} {name}: {e}", file=sys.stderr)
                report[section][name] = {**b.facts(), "error": str(e)}
    except Fatal as e:
        failure = f"browser.py: {e}\n--- chromium's stderr (tail) ---\n{b.stderr_tail()}"
    finally:
        b.close()
    if failure:
        sys.exit(failure)
    json.dump(report, sys.stdout, indent=1)
    print()


if __name__ == "__main__":
    main()
