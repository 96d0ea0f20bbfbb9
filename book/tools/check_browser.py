"""Renders the book's pages in headless Chromium (Debian's chromium) and fails when a page is
wider than the window, when MathJax reports an error or leaves a formula untypeset, when a
page throws a JavaScript error, or when a page asks for anything outside the book's folder.

    python3 book/tools/check_browser.py build/book/html [--all] [--chromium PATH]

By default it renders the book's own pages (the title page, the chapters, the extra pages)
at 1280 px and at 400 px (a phone), and every other page (classes, files, sources) at 1280 px
with --all. Chromium is driven over its DevTools protocol on a pipe, with the standard library
alone."""
import argparse
import fcntl
import json
import os
import pathlib
import shutil
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import book_pages  # noqa: E402

# Runs in the page once it has loaded: waits for MathJax to finish, then measures.
MEASURE = r"""
new Promise(resolve => {
  const measure = () => {
    const out = {};
    const doc = document.documentElement;
    const content = document.getElementById('doc-content') || doc;
    out.window = window.innerWidth;
    out.width = Math.max(doc.scrollWidth, content.scrollWidth + (window.innerWidth - content.clientWidth));
    // What sticks out, for the message: elements reaching past the window that are not inside
    // an element that scrolls by itself.
    out.wide = [];
    if (out.width > out.window) {
      const scrolls = e => { for (; e && e !== content; e = e.parentElement) {
        const s = getComputedStyle(e);
        if ((s.overflowX === 'auto' || s.overflowX === 'scroll' || s.overflowX === 'hidden') &&
            e.scrollWidth > e.clientWidth) return true; } return false; };
      for (const e of content.querySelectorAll('*')) {
        const r = e.getBoundingClientRect();
        if (r.right > out.window + 1 && !scrolls(e.parentElement)) {
          out.wide.push(e.tagName.toLowerCase() + (e.className ? '.' + String(e.className).split(' ')[0] : '') +
                        ' ' + Math.round(r.width) + ' px: ' + (e.textContent || e.getAttribute('src') || '').trim().slice(0, 60));
          if (out.wide.length >= 3) break;
        }
      }
    }
    out.math = document.querySelectorAll('script[type^="math/tex"]').length;
    out.typeset = document.querySelectorAll('.MathJax_SVG, .MathJax_SVG_Display').length;
    out.errors = [];
    if (window.MathJax && MathJax.Hub) {
      for (const m of (MathJax.Hub.signal.posted || [])) {
        const name = Array.isArray(m) ? String(m[0]) : String(m);
        if (/error/i.test(name)) out.errors.push(Array.isArray(m) ?
            m.filter(x => typeof x === 'string').join(': ').slice(0, 200) : name);
      }
      for (const jax of MathJax.Hub.getAllJax()) {
        const mml = jax.root && jax.root.toMathML ? jax.root.toMathML('') : '';
        if (mml.includes('<merror')) out.errors.push('TeX error in: ' + jax.originalText.slice(0, 120));
      }
    }
    resolve(out);
  };
  if (window.MathJax && MathJax.Hub && MathJax.Hub.Queue) MathJax.Hub.Queue(measure);
  else measure();
})
"""


class Chromium:
    """One headless Chromium, spoken to over --remote-debugging-pipe (fd 3 in, fd 4 out)."""

    def __init__(self, exe):
        self.profile = tempfile.mkdtemp(prefix="rtk-book-check-")
        to_chrome_r, self.to_chrome = os.pipe()
        self.from_chrome, from_chrome_w = os.pipe()
        # Chromium reads the protocol on fd 3 and writes on fd 4; the shell puts the pipes there
        # (from fds of 10 and above, which the redirections cannot clobber).
        a = fcntl.fcntl(to_chrome_r, fcntl.F_DUPFD, 10)
        b = fcntl.fcntl(from_chrome_w, fcntl.F_DUPFD, 10)
        for fd in (to_chrome_r, from_chrome_w):
            os.close(fd)
        flags = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                 "--disable-background-networking", "--disable-component-update", "--disable-sync",
                 "--hide-scrollbars", "--mute-audio", f"--user-data-dir={self.profile}",
                 "--remote-debugging-pipe", "about:blank"]
        self.proc = subprocess.Popen(
            ["bash", "-c", f'exec "$0" "$@" 3<&{a} 4>&{b} {a}<&- {b}>&-', exe, *flags],
            pass_fds=(a, b), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        os.close(a)
        os.close(b)
        self.buffer = b""
        self.next_id = 0
        self.events = []

    def close(self):
        try:
            self.send("Browser.close")
        except Exception:
            pass
        try:
            self.proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.proc.kill()
        shutil.rmtree(self.profile, ignore_errors=True)

    def _read_message(self, deadline):
        while b"\0" not in self.buffer:
            if time.monotonic() > deadline:
                raise TimeoutError("Chromium did not answer")
            chunk = os.read(self.from_chrome, 1 << 20)
            if not chunk:
                raise RuntimeError("Chromium closed the pipe")
            self.buffer += chunk
        raw, self.buffer = self.buffer.split(b"\0", 1)
        return json.loads(raw)

    def send(self, method, params=None, session=None, timeout=30):
        self.next_id += 1
        msg = {"id": self.next_id, "method": method, "params": params or {}}
        if session:
            msg["sessionId"] = session
        os.write(self.to_chrome, json.dumps(msg).encode() + b"\0")
        deadline = time.monotonic() + timeout
        while True:
            reply = self._read_message(deadline)
            if reply.get("id") == self.next_id:
                if "error" in reply:
                    raise RuntimeError(f"{method}: {reply['error']}")
                return reply.get("result", {})
            self.events.append(reply)

    def wait_event(self, method, timeout=30):
        deadline = time.monotonic() + timeout
        while True:
            for i, e in enumerate(self.events):
                if e.get("method") == method:
                    del self.events[i]
                    return e
            self.events.append(self._read_message(deadline))


def book_page_files(html):
    names = ["index.html"] + [p.anchor + ".html" for p in book_pages.chapters() + book_pages.extra_pages()]
    return [html / n for n in names]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("html", type=pathlib.Path)
    ap.add_argument("--all", action="store_true", help="also every other page, at 1280 px")
    ap.add_argument("--chromium", default=shutil.which("chromium") or "/usr/bin/chromium")
    args = ap.parse_args()
    html = args.html.resolve()
    start = time.monotonic()

    book = book_page_files(html)
    runs = [(1280, p) for p in book] + [(400, p) for p in book]
    if args.all:
        others = sorted(set(html.glob("*.html")) - set(book))
        runs += [(1280, p) for p in others]

    browser = Chromium(args.chromium)
    failures = []
    try:
        target = browser.send("Target.createTarget", {"url": "about:blank"})["targetId"]
        s = browser.send("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
        for domain in ("Page", "Runtime", "Network"):
            browser.send(f"{domain}.enable", session=s)
        width = None
        for w, page in runs:
            if w != width:
                browser.send("Emulation.setDeviceMetricsOverride",
                             {"width": w, "height": 900, "deviceScaleFactor": 1, "mobile": w < 800},
                             session=s)
                width = w
            browser.events.clear()
            browser.send("Page.navigate", {"url": page.as_uri()}, session=s)
            browser.wait_event("Page.loadEventFired")
            r = browser.send("Runtime.evaluate", {"expression": MEASURE, "awaitPromise": True,
                                                   "returnByValue": True}, session=s)
            if "exceptionDetails" in r:
                failures.append(f"{page.name} at {w} px: the check itself failed: {r['exceptionDetails']}")
                continue
            m = r["result"]["value"]
            where = f"{page.name} at {w} px"
            if m["width"] > m["window"]:
                failures.append(f"{where}: {m['width']} px wide ({'; '.join(m['wide']) or '?'})")
            for e in m["errors"]:
                failures.append(f"{where}: MathJax: {e}")
            if m["typeset"] < m["math"]:
                failures.append(f"{where}: MathJax typeset {m['typeset']} of {m['math']} formulas")
            for e in browser.events:
                method = e.get("method")
                if method == "Runtime.exceptionThrown":
                    d = e["params"]["exceptionDetails"]
                    text = d.get("exception", {}).get("description") or d.get("text")
                    failures.append(f"{where}: JavaScript error: {str(text).splitlines()[0]}")
                elif method == "Network.requestWillBeSent":
                    url = e["params"]["request"]["url"]
                    if not (url.startswith("file://" + str(html)) or url.startswith("data:")):
                        failures.append(f"{where}: loads {url[:120]} (outside the book)")
    finally:
        browser.close()

    seconds = time.monotonic() - start
    for f in failures:
        print("check_browser:", f)
    print(f"check_browser: {len(runs)} renderings of {len(set(p for _, p in runs))} pages "
          f"in {seconds:.1f} s, {len(failures)} problems")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
