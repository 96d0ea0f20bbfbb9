"""The book's pages in reading order, read from the source tree: one module for the Doxygen
input filter that writes each chapter's previous/next links and for the book's checks."""
import pathlib
import re

ROOT = pathlib.Path(__file__).resolve().parents[2]
HEADING = re.compile(r"^# (?P<title>.*?)\s*\{#(?P<anchor>[A-Za-z0-9_]+)\}\s*$")


class Page:
    """A page of the book: its file, its anchor (the HTML file's name) and its title."""

    def __init__(self, path):
        self.path = pathlib.Path(path)
        first = self.path.read_text(encoding="utf-8").splitlines()[0]
        m = HEADING.match(first)
        if not m:
            raise ValueError(f"{self.path}:1: the page must begin '# Title {{#anchor}}'")
        self.title = m["title"]
        self.anchor = m["anchor"]
        self.number = None
        folder = self.path.parent.name
        if self.path.name == "chapter.md" and re.match(r"^\d\d_", folder):
            self.number = int(folder[:2])

    def __repr__(self):
        return f"Page({self.anchor!r})"


def chapters(root=ROOT):
    """The chapters in reading order: chapters/NN_topic/chapter.md, sorted by folder."""
    return [Page(p) for p in sorted((root / "chapters").glob("[0-9][0-9]_*/chapter.md"))]


# The pages after the chapters, in the sidebar's order (book/CMakeLists.txt lists the same).
EXTRA_PAGES = ["reading.md", "measurement.md", "conventions.md", "embree_comparison.md"]


def extra_pages(root=ROOT):
    return [Page(root / "book" / name) for name in EXTRA_PAGES]


# The pages that promise formulas, and how many they show at least (check_book.py).
MATH = {
    "ch01_base": 3,        # the slab test
    "ch02_bvh2": 3,        # Moeller-Trumbore by Cramer's rule, the node's entry and exit
    "ch04_sah": 4,         # the SAH cost and the leaf test
    "ch11_sampling": 3,    # the Monte Carlo estimate, the cosine-weighted density
    "ch12_materials": 8,   # GGX, Smith's masking, visible normals, the rough conductor, plastic
    "ch07_intersectors": 2,  # the Pluecker edge function, the watertight test's edge functions
    "ch13_lights": 3,      # the light-sampling estimate, the area and the environment densities
    "ch14_pathtracer": 2,  # the rendering equation, the power heuristic
}

# Problems the book still has, by check and page: check_book.py reports them without failing,
# and fails once one is fixed, until it is taken off this list.
KNOWN_GAPS = {}
