"""Checks the HTML copies of the notebooks as a reader sees them: opens each in headless
Chromium (file://, no network), lets its scripts run (MathJax typesets the Markdown's TeX),
and fails (exit 1) if any visible text still holds unrendered TeX — `$…$`, `$$`, a `\\command`
such as `\\frac` or `\\varepsilon` — or MathJax reports an error. Code cells' sources are not
read (Rust is not mathematics). Saves a screenshot of each page's first screen beside it
(`screens/<name>.png`), for a person to look at.

usage: python3 scripts/check_html.py [--screens DIR] out/notebooks/*.html
       python3 scripts/check_html.py --self-test MATHJAX_JS   (the check can fail: a page with
                                      raw TeX is refused, the same page with MathJax passes)
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile
from html.parser import HTMLParser

CHROMIUM_FLAGS = [
    "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
    "--disable-background-networking", "--disable-component-update", "--disable-sync",
    "--hide-scrollbars",
    # scripts run until the page is idle, on a virtual clock (MathJax finishes well within)
    "--virtual-time-budget=30000",
]

# TeX a reader should never see: inline or display delimiters around text, or a command
TEX_LEFT = [
    re.compile(r"\$\$"),
    re.compile(r"(?<![\w$])\$[^$\s][^$\n]{0,200}?\$(?![\w$])"),
    re.compile(r"\\[A-Za-z]{2,}"),
]

# elements whose text a reader does not see as text
SKIP_TAGS = {"script", "style", "noscript", "template", "svg", "mjx-assistive-mml", "head"}
# code cells' sources (nbconvert's lab template)
SKIP_CLASSES = ("jp-InputArea-editor", "jp-InputPrompt", "jp-OutputPrompt")
VOID = {"area", "base", "br", "col", "embed", "hr", "img", "input", "link", "meta", "source",
        "track", "wbr"}


class VisibleText(HTMLParser):
    """The text of a rendered page outside skipped elements, and MathJax's error count."""

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.stack = []  # (tag, skipped)
        self.parts = []
        self.errors = 0

    def skipping(self):
        return bool(self.stack) and self.stack[-1][1]

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "mjx-merror" or "data-mjx-error" in a:
            self.errors += 1
        if tag in VOID:
            return
        classes = a.get("class") or ""
        skip = self.skipping() or tag in SKIP_TAGS or any(c in classes for c in SKIP_CLASSES)
        self.stack.append((tag, skip))

    def handle_endtag(self, tag):
        # close up to the matching tag (HTML allows omitted end tags)
        for k in range(len(self.stack) - 1, -1, -1):
            if self.stack[k][0] == tag:
                del self.stack[k:]
                break

    def handle_data(self, data):
        if not self.skipping():
            self.parts.append(data)


def chromium():
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    sys.exit("check_html: Chromium not found (scripts/notebooks.sh installs the package chromium)")


def render(path, profile):
    """The page's DOM after its scripts ran."""
    url = "file://" + os.path.abspath(path)
    out = subprocess.run(
        [chromium(), *CHROMIUM_FLAGS, f"--user-data-dir={profile}", "--dump-dom", url],
        capture_output=True, text=True, timeout=300, check=False,
    )
    if out.returncode != 0 or "<body" not in out.stdout:
        raise RuntimeError(f"Chromium could not render {path}: {out.stderr.strip()[-300:]}")
    return out.stdout


def screenshot(path, png, profile):
    url = "file://" + os.path.abspath(path)
    subprocess.run(
        [chromium(), *CHROMIUM_FLAGS, f"--user-data-dir={profile}", "--window-size=1280,1000",
         f"--screenshot={os.path.abspath(png)}", url],
        capture_output=True, text=True, timeout=300, check=True,
    )


def problems(dom):
    """Unrendered TeX in the visible text, and MathJax errors."""
    parser = VisibleText()
    parser.feed(dom)
    text = " ".join(" ".join(parser.parts).split())
    found = []
    for pattern in TEX_LEFT:
        for m in pattern.finditer(text):
            a, b = max(0, m.start() - 40), min(len(text), m.end() + 40)
            found.append(f"unrendered TeX {m.group(0)[:60]!r} in …{text[a:b]}…")
    if parser.errors:
        found.append(f"{parser.errors} MathJax error(s)")
    return found, len(dom.split("<mjx-container")) - 1


def check(paths, screens):
    failed = 0
    with tempfile.TemporaryDirectory() as profile:
        for path in paths:
            found, typeset = problems(render(path, profile))
            if screens is not None:
                os.makedirs(screens, exist_ok=True)
                png = os.path.join(screens, os.path.basename(path).removesuffix(".html") + ".png")
                screenshot(path, png, profile)
            if found:
                failed += 1
                print(f"check_html: {path}: {len(found)} problem(s)")
                for f in found[:10]:
                    print(f"  {f}")
            else:
                print(f"check_html: {path}: ok ({typeset} formulas typeset)")
    return failed


def mathjax_config():
    """The MathJax configuration of the notebooks' HTML template (its first script)."""
    template = os.path.join(os.path.dirname(os.path.abspath(__file__)), "nbconvert", "offline.html.j2")
    with open(template, encoding="utf-8") as f:
        text = f.read()
    return re.search(r"<script>.*?</script>", text, re.S).group(0)


def self_test(mathjax):
    """A page with TeX and no MathJax must fail; the same page with the template's MathJax
    configuration and script must pass."""
    page = """<!DOCTYPE html><html><head>{head}</head><body>
<div class="jp-MarkdownCell"><p>The error is $\\varepsilon = \\frac{{1}}{{2}}$ and</p>
<p>$$p(t) = a_0 + a_1 t$$</p></div>
<div class="jp-InputArea-editor"><pre>let s = "$\\\\frac$";</pre></div></body></html>"""
    with tempfile.TemporaryDirectory() as d:
        shutil.copy(mathjax, os.path.join(d, "mj.js"))
        raw, typeset = os.path.join(d, "raw.html"), os.path.join(d, "typeset.html")
        with open(raw, "w", encoding="utf-8") as f:
            f.write(page.format(head=""))
        with open(typeset, "w", encoding="utf-8") as f:
            f.write(page.format(head=mathjax_config() + '<script src="mj.js"></script>'))
        with tempfile.TemporaryDirectory() as profile:
            bad, _ = problems(render(raw, profile))
            good, n = problems(render(typeset, profile))
    if len(bad) < 3 or good or n != 2:
        sys.exit(f"check_html self-test failed: raw page {bad}, typeset page {good} ({n} formulas)")
    print("check_html: self-test ok (raw TeX refused, typeset page accepted)")


if __name__ == "__main__":
    args = sys.argv[1:]
    if args[:1] == ["--self-test"]:
        self_test(args[1])
        sys.exit(0)
    screens = None
    if args[:1] == ["--screens"]:
        screens, args = args[1], args[2:]
    bad = check(args, screens)
    if bad:
        sys.exit(f"check_html: {bad} of {len(args)} pages show unrendered mathematics")
    print(f"check_html: {len(args)} pages, every formula rendered")
