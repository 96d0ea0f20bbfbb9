"""The book's checks on the built pages (build/book/html) and their sources, fast and with
the standard library alone:

    python3 book/tools/check_book.py build/book/html

- links: every local link and image of every page leads to a file that exists, and every
  #anchor to an id in it;
- navigation: the sidebar lists the title page, every chapter in folder order, then the extra
  pages; the title page lists the chapters in that order; every chapter page ends with links
  to the previous and the next chapter; every chapter page begins '# Chapter N: ...
  {#chNN_...}' with N its folder's number;
- snippets: every \\snippet region is found, holds code, and its comment lines appear on the
  page (Doxygen strips them when STRIP_CODE_COMMENTS is YES);
- math: the pages that promise formulas (book_pages.MATH) show at least that many;
- code: no typographic quote or dash inside inline code or code blocks, and no stray
  backtick in the prose (what Doxygen leaves of an inline code span holding a quote);
- figures: every chapter shows at least one image or diagram;
- cross-references: every 'chapter N' in the prose of a page is a link (its own number aside),
  and every chapter opens with what the reader will build;
- project, not machine: no page names a build folder of one machine (build-h1, ...), an
  absolute path of one machine (/work/..., /tmp/...), or a load average.

Each problem is printed as 'check: page: message'. book_pages.KNOWN_GAPS lists the problems
the book still has, by check and page: they are reported but do not fail, and one that has
been fixed fails until it is taken off the list."""
import html as htmllib
import pathlib
import re
import sys
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import book_pages  # noqa: E402

ROOT = book_pages.ROOT
EXAMPLE_PATH = [ROOT / d for d in ("chapters", "lib", "tests", "bench", "apps", "examples")]
TYPOGRAPHIC = "\u2018\u2019\u201c\u201d\u2013\u2014"
ENTITIES = ("&lsquo;", "&rsquo;", "&ldquo;", "&rdquo;", "&ndash;", "&mdash;")


class Book:
    def __init__(self, html_dir):
        self.html = html_dir
        self.chapters = book_pages.chapters()
        self.extras = book_pages.extra_pages()
        self.pages = self.chapters + self.extras
        self._text = {}

    def text(self, name):
        if name not in self._text:
            self._text[name] = (self.html / name).read_text(encoding="utf-8", errors="replace")
        return self._text[name]

    def contents(self, anchor):
        """The page's own part (between the title and Doxygen's footer)."""
        t = self.text(anchor + ".html")
        start = t.find('<div class="contents">')
        end = t.find("<!-- contents -->")
        return t[start:end] if start >= 0 and end > start else t


def strip_tags(s):
    return htmllib.unescape(re.sub(r"<[^>]*>", "", s))


def norm(s):
    return " ".join(s.split())


# --- links -----------------------------------------------------------------------------------

LINK = re.compile(r'\b(href|src)="([^"]*)"')
IDS = re.compile(r'\b(?:id|name)="([^"]*)"')


def check_links(book, problems):
    files = sorted(book.html.glob("*.html"))
    ids = {}

    def ids_of(path):
        if path not in ids:
            ids[path] = set(IDS.findall(path.read_text(encoding="utf-8", errors="replace")))
        return ids[path]

    count = 0
    for f in files:
        text = f.read_text(encoding="utf-8", errors="replace")
        for kind, url in LINK.findall(text):
            if re.match(r"^(https?:|mailto:|javascript:|data:)", url) or url == "":
                continue
            count += 1
            url = htmllib.unescape(url)
            target, _, frag = url.partition("#")
            path = f if target == "" else (f.parent / target.split("?")[0]).resolve()
            if not path.exists():
                problems.append(("links", f.name, f"{kind} {url}: no such file"))
            elif frag and path.suffix == ".html" and frag not in ids_of(path):
                problems.append(("links", f.name, f"{url}: no anchor '{frag}' in {path.name}"))
    return f"{count} links in {len(files)} pages"


# --- navigation ------------------------------------------------------------------------------

def check_navigation(book, problems):
    # The first level of the sidebar, in order.
    tree = book.text("navtreedata.js")
    top = re.findall(r'^    \[ "(?:[^"\\]|\\.)*", "([^"#]+)[^"]*", ', tree, re.M)
    want = ["index.html"] + [p.anchor + ".html" for p in book.pages]
    if top[: len(want)] != want:
        problems.append(("navigation", "sidebar",
                         f"lists {top[:len(want)]}, expected the title page, the chapters, then {want[len(book.chapters) + 1:]}"))
    # The title page's list of chapters.
    index = book.contents("index") if (book.html / "index.html").exists() else ""
    chapter_files = [p.anchor + ".html" for p in book.chapters]
    seen = [h for h in re.findall(r'href="([^"#]+)', index) if h in chapter_files]
    first = list(dict.fromkeys(seen))
    if first != chapter_files:
        problems.append(("navigation", "index", f"lists the chapters as {first}, expected {chapter_files}"))
    for i, page in enumerate(book.chapters):
        # The heading.
        m = re.match(r"^Chapter (\d+): \S", page.title)
        if not m or int(m.group(1)) != page.number or not page.anchor.startswith(f"ch{page.number:02d}_"):
            problems.append(("navigation", page.anchor,
                             f"{page.path.relative_to(ROOT)}:1: must begin '# Chapter {page.number}: Title {{#ch{page.number:02d}_name}}'"))
        # The previous/next links.
        c = book.contents(page.anchor)
        nav = re.search(r'<div class="chapter-nav">(.*?)</div>', c, re.S)
        if not nav:
            problems.append(("navigation", page.anchor, "no previous/next links"))
            continue
        prev = re.search(r'chapter-nav-prev"><a class="el" href="([^"]+)"', nav.group(1))
        nxt = re.search(r'chapter-nav-next"><a class="el" href="([^"]+)"', nav.group(1))
        want_prev = book.chapters[i - 1].anchor + ".html" if i > 0 else None
        want_next = book.chapters[i + 1].anchor + ".html" if i + 1 < len(book.chapters) else None
        if (prev.group(1) if prev else None) != want_prev or (nxt.group(1) if nxt else None) != want_next:
            problems.append(("navigation", page.anchor, f"previous/next lead to {prev and prev.group(1)}/"
                             f"{nxt and nxt.group(1)}, expected {want_prev}/{want_next}"))
    return f"{len(book.chapters)} chapters, {len(book.extras)} extra pages"


# --- snippets --------------------------------------------------------------------------------

SNIPPET = re.compile(r"^\s*\\snippet(?:\{[a-z]+\})?\s+(\S+)\s+(\S+)", re.M)


def find_example(name):
    for base in EXAMPLE_PATH:
        if (base / name).is_file():
            return base / name
    # Doxygen also finds an example by its file name alone.
    hits = [p for base in EXAMPLE_PATH for p in base.rglob(pathlib.Path(name).name) if p.is_file()]
    return hits[0] if len(hits) == 1 else None


def region(path, name):
    marker = f"[{name}]"
    lines = path.read_text(encoding="utf-8").splitlines()
    at = [i for i, line in enumerate(lines) if marker in line]
    if len(at) < 2:
        return None
    return lines[at[0] + 1: at[1]]


def comment_of(line, suffix):
    s = line.strip()
    if suffix in (".txt", ".cmake", ".sh", ".py"):
        return s if s.startswith("#") else None
    return s if s.startswith("//") else None


def check_snippets(book, problems):
    count = 0
    comments = 0
    for page in [*book.pages]:
        src = page.path.read_text(encoding="utf-8")
        page_text = None
        for m in SNIPPET.finditer(src):
            count += 1
            name, reg = m.group(1), m.group(2)
            line = src.count("\n", 0, m.start()) + 1
            where = f"{page.path.relative_to(ROOT)}:{line}"
            path = find_example(name)
            if path is None:
                problems.append(("snippets", page.anchor, f"{where}: {name} not found"))
                continue
            body = region(path, reg)
            if body is None:
                problems.append(("snippets", page.anchor, f"{where}: no region [{reg}] in {name}"))
                continue
            if not any(b.strip() for b in body):
                problems.append(("snippets", page.anchor, f"{where}: region [{reg}] of {name} is empty"))
                continue
            if page_text is None:
                page_text = norm(strip_tags(book.contents(page.anchor)))
            for b in body:
                c = comment_of(b, path.suffix)
                if c is None:
                    continue
                comments += 1
                if norm(c) not in page_text:
                    problems.append(("snippets", page.anchor,
                                     f"{where}: the comment '{c[:60]}' of [{reg}] is not on the page"))
                    break
    return f"{count} snippets, {comments} comment lines"


# --- math ------------------------------------------------------------------------------------

def check_math(book, problems):
    total = 0
    for anchor, least in book_pages.MATH.items():
        c = book.contents(anchor)
        n = c.count("\\(") + c.count("\\[")
        total += n
        if n < least:
            problems.append(("math", anchor, f"{n} formulas, at least {least} promised"))
    return f"{total} formulas on {len(book_pages.MATH)} pages"


# --- code typography -------------------------------------------------------------------------

CODE = re.compile(r'<code\b[^>]*>.*?</code>|<div class="fragment">.*?</div><!-- fragment -->|<pre\b.*?</pre>', re.S)


def check_code(book, problems):
    spans = 0
    for anchor in ["index"] + [p.anchor for p in book.pages]:
        c = book.contents(anchor)
        for m in CODE.finditer(c):
            spans += 1
            raw = m.group(0)
            if any(e in raw for e in ENTITIES) or any(ch in strip_tags(raw) for ch in TYPOGRAPHIC):
                problems.append(("code", anchor, f"typographic quote or dash in code: {norm(strip_tags(raw))[:80]}"))
        prose = CODE.sub("", c)
        prose = re.sub(r'<script\b.*?</script>', "", prose, flags=re.S)
        for m in re.finditer(r"`", strip_tags(prose)):
            t = strip_tags(prose)
            problems.append(("code", anchor, f"stray backtick (an inline code span Doxygen did not "
                             f"read; a quote inside `...` needs ``...``): ...{norm(t[max(0, m.start() - 60):m.start() + 20])}..."))
            break
    return f"{spans} code spans and blocks"


# --- figures ---------------------------------------------------------------------------------

def check_figures(book, problems):
    count = 0
    for page in book.chapters:
        c = book.contents(page.anchor)
        n = c.count('<div class="image">') + c.count('class="dotgraph"')
        count += n
        if n == 0:
            problems.append(("figures", page.anchor, "no figure"))
    return f"{count} figures"


# --- cross-references and openings ------------------------------------------------------------

def check_references(book, problems):
    links = 0
    for page in [None] + book.pages:
        anchor = "index" if page is None else page.anchor
        c = book.contents(anchor)
        links += len(re.findall(r'<a class="el" href="ch\d\d_', c))
        prose = CODE.sub("", c)
        prose = re.sub(r"<a\b.*?</a>|<script\b.*?</script>|<h[1-6]\b.*?</h[1-6]>", "", prose, flags=re.S)
        own = page.number if page is not None else None
        for m in re.finditer(r"\b[Cc]hapter (\d{1,2})\b", strip_tags(prose)):
            if int(m.group(1)) != own:
                problems.append(("references", anchor, f"'{m.group(0)}' is not a link"))
                break
        if page is not None and page.number is not None:
            head = c.split("<h2", 1)[0]
            if not re.search(r"<blockquote[^>]*>\s*<p\s*>(?:&zwj;)?\s*<b>What you will build</b>", head):
                problems.append(("openings", anchor, "no '> **What you will build**: ...' before its first section"))
    return f"{links} links to chapters"


# --- project, not machine -----------------------------------------------------------------------

MACHINE = re.compile(r"\bbuild-h\d|(?<![\w.])/(?:work|tmp|root|home)/|load average", re.I)


def check_machine(book, problems):
    for page in book.pages + [book_pages.Page(ROOT / "book" / "mainpage.md")]:
        if page.anchor == "measurement":  # the page that names the machine, and its load
            continue
        for n, line in enumerate(page.path.read_text(encoding="utf-8").splitlines(), 1):
            m = MACHINE.search(line)
            if m:
                anchor = "index" if page.anchor == "mainpage" else page.anchor
                problems.append(("machine", anchor, f"{page.path.relative_to(ROOT)}:{n}: '{m.group(0)}'"))
                break
    return "machine-free pages"


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    book = Book(pathlib.Path(sys.argv[1]).resolve())
    start = time.monotonic()
    problems = []
    summary = []
    for check in (check_links, check_navigation, check_snippets, check_math, check_code, check_figures,
                  check_references, check_machine):
        summary.append(check(book, problems))
    known = {(c, a) for c, anchors in book_pages.KNOWN_GAPS.items() for a in anchors}
    failed = 0
    found = set()
    for check, anchor, message in problems:
        found.add((check, anchor))
        gap = (check, anchor) in known
        failed += not gap
        print(f"check_book: {'known gap: ' if gap else ''}{check}: {anchor}: {message}")
    for check, anchor in sorted(known - found):
        failed += 1
        print(f"check_book: {check}: {anchor}: fixed; take it off book_pages.KNOWN_GAPS")
    print(f"check_book: {'; '.join(summary)}; {failed} problems ({time.monotonic() - start:.1f} s)")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
