#!/usr/bin/env python3
"""Print a report's HTML to PDF with Chromium, letting a chapter follow on a short page.

Every chapter (h1) opens a page in print (paper/style.css), so that an edit in one chapter
cannot push a figure of the next over a break.  The price is the last page of a chapter that
spills a few lines over: a stub.  CSS cannot say "break before this heading only if the page
so far is at least half full", so the printer measures instead: it prints, reads each page's
fill (page_fill.py) and the page each chapter opens on (the PDF's named destinations, one per
element id), and for each chapter whose previous page is less than half full it lets that
chapter follow on the same page (break-before: auto for its id), then prints again, until no
chapter changes (at most PASSES prints).  The HTML file itself is not changed: the rules go
into a temporary copy next to it.
usage: print_pdf.py REPORT.html OUT.pdf
"""
import os
import re
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import page_fill  # noqa: E402

HALF = 0.9   # a chapter follows on the previous page when that page is less full than this
PASSES = 6   # prints at most; each pass can only let more chapters follow, so it ends


def chromium():
    found = shutil.which("chromium") or shutil.which("chromium-browser")
    return found or sys.exit("print_pdf: chromium not installed (make deps installs it)")


def print_to(chrome, html, pdf):
    r = subprocess.run([chrome, "--headless", "--no-sandbox", "--disable-gpu", "--no-pdf-header-footer",
                        "--print-to-pdf=" + pdf, "file://" + os.path.abspath(html)],
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    if r.returncode != 0 or not os.path.exists(pdf):
        sys.exit("print_pdf: chromium could not print '%s' (exit %d)" % (html, r.returncode))


def with_flow(text, ids):
    """The HTML with print rules letting the chapters ids follow on the previous page."""
    if not ids:
        return text
    rule = "<style>@media print { %s { break-before: auto; } }</style>" % ", ".join(
        "[id=\"%s\"]" % i for i in ids)
    at = text.find("</head>")
    if at < 0:
        sys.exit("print_pdf: no </head> in the HTML")
    return text[:at] + rule + text[at:]


def stubs(pdf, chapters, flowing):
    """Chapters (not yet following) that open a page whose previous page is under HALF full."""
    data, body, pages = page_fill.read_pages(pdf)
    index = {p["object"]: i for i, p in enumerate(pages)}
    dests = page_fill.destinations(data, body)
    out = []
    for c in chapters:
        if c not in dests or dests[c][0] not in index:
            # Chromium names a destination only for an id a link points at (the contents).
            sys.exit("print_pdf: chapter '%s' has no destination in the PDF: is it in the contents?" % c)
        if c in flowing:
            continue
        i = index[dests[c][0]]
        if i > 0 and pages[i - 1]["fill"] < HALF:
            out.append((c, i))
    return out


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: print_pdf.py REPORT.html OUT.pdf")
    html, pdf = sys.argv[1:]
    try:
        text = open(html, encoding="utf-8").read()
    except OSError as e:
        sys.exit("print_pdf: cannot read '%s': %s" % (html, e.strerror))
    # Chapters: h1 elements with an id (the title has none), in document order.
    chapters = re.findall(r'<h1 id="([^"]+)"', text)
    chrome, flowing = chromium(), []
    copy = os.path.join(os.path.dirname(os.path.abspath(html)), ".print-%d-%s" % (os.getpid(), os.path.basename(html)))
    try:
        for n in range(1, PASSES + 1):
            with open(copy, "w", encoding="utf-8") as f:
                f.write(with_flow(text, flowing))
            print_to(chrome, copy, pdf)
            found = stubs(pdf, chapters, flowing)
            if not found:
                break
            for c, i in found:
                print("print_pdf: %s: page %d is under half full; chapter '%s' follows on it" % (html, i, c))
            flowing += [c for c, _ in found]
        else:
            print("print_pdf: %s: still changing after %d prints; the last is kept" % (html, PASSES))
    finally:
        if os.path.exists(copy):
            os.remove(copy)
    print("print_pdf: %s -> %s (%d print%s, %d of %d chapters follow on a page)"
          % (html, pdf, n, "" if n == 1 else "s", len(flowing), len(chapters)))


if __name__ == "__main__":
    main()
