"""Doxygen input filter for chapters/NN_topic/chapter.md: prints the page as it is and appends
the links to the previous chapter, the contents and the next chapter, so that a reader can
walk the book in order. The order is the chapter folders' order (book_pages.py)."""
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import book_pages  # noqa: E402


def footer(path):
    pages = book_pages.chapters()
    here = [i for i, p in enumerate(pages) if p.path == path]
    if not here:
        return ""
    i = here[0]
    prev = pages[i - 1] if i > 0 else None
    nxt = pages[i + 1] if i + 1 < len(pages) else None
    # A blank line ends any list or paragraph the page ends with; the div is an HTML block,
    # and Doxygen resolves \ref inside it (a renamed page fails the build).
    out = ["", "", '<div class="chapter-nav">']
    if prev:
        out.append(f'<span class="chapter-nav-prev">\\ref {prev.anchor} "← {prev.title}"</span>')
    else:
        out.append('<span class="chapter-nav-prev"></span>')
    out.append('<span class="chapter-nav-up">\\ref index "Contents"</span>')
    if nxt:
        out.append(f'<span class="chapter-nav-next">\\ref {nxt.anchor} "{nxt.title} →"</span>')
    out.append("</div>")
    return "\n".join(out) + "\n"


def main():
    path = pathlib.Path(sys.argv[1]).resolve()
    text = path.read_text(encoding="utf-8")
    sys.stdout.reconfigure(encoding="utf-8")
    sys.stdout.write(text)
    if not text.endswith("\n"):
        sys.stdout.write("\n")
    sys.stdout.write(footer(path))


if __name__ == "__main__":
    main()
