#!/usr/bin/env python3
"""Pages of a printed report (Chromium's PDF) that stay mostly blank.

For every page the lowest point anything is drawn at (text, path, image) is found by
following the content stream's transformation matrices; the page's fill is the share of the
printable height above it.  Two rules, the last page exempt from both:
  - a page under a quarter full (MIN_FILL) fails: a stub is never a page, even at the end of
    a chapter (tests/report/print_pdf.py lets the next chapter follow on such a page);
  - a page more than LIMIT blank fails unless the next page opens a chapter (its first text is
    set at the size of a chapter title): inside a chapter only a figure that does not fit
    may leave that much of a page blank.
One line per failing page, then a summary with the fullest and emptiest page; exit 1 if any
(more than N with --allow N: a ratchet for a report whose layout still has them, which may
not gain one), 2 on a file that is not such a PDF.
usage: page_fill.py [--allow N] REPORT.pdf [LIMIT (default 0.6)] [MARGIN_PT (default 34, the 12 mm of paper/style.css)]
"""
import re
import sys
import zlib

CHAPTER_PT = 18.0  # an h1 is 2 em of the 10 pt body; an h2 (1.5 em) stays below this
MIN_FILL = 0.25   # no page but the last may be filled less than this


def fail_usage(msg):
    print("page_fill: " + msg, file=sys.stderr)
    sys.exit(2)


def objects(data):
    offs = {int(m.group(1)): m.end() for m in re.finditer(rb"(?m)^(\d+) 0 obj", data)}
    def body(n):
        i = offs[n]
        return data[i:data.index(b"endobj", i)]
    return offs, body


def stream(obj):
    i = obj.index(b"stream") + 6
    while obj[i:i + 1] in (b"\r", b"\n"):
        i += 1
    raw = obj[i:obj.rindex(b"endstream")]
    return zlib.decompress(raw) if b"FlateDecode" in obj[:i] else raw


def mul(m, n):  # m then n (PDF row-vector convention)
    a, b, c, d, e, f = m
    A, B, C, D, E, F = n
    return (a * A + b * C, a * B + b * D, c * A + d * C, c * B + d * D,
            e * A + f * C + E, e * B + f * D + F)


def scan(content):
    """Lowest page-space y drawn on, and the font size and height of the topmost text."""
    ctm, stack, ops = (1, 0, 0, 1, 0, 0), [], []
    low, top_text = None, None  # top_text: (y, size)
    tf, tm, path = 0.0, (1, 0, 0, 1, 0, 0), []
    tokens = re.findall(rb"/[^\s/<>\[\]()]+|<[0-9A-Fa-f]*>|\((?:\\.|[^\\)])*\)|[-+]?\d*\.?\d+|[A-Za-z'\"*]+|\[|\]", content)
    def mark(y):
        nonlocal low
        low = y if low is None else min(low, y)
    def point(x, y, m):
        return x * m[0] + y * m[2] + m[4], x * m[1] + y * m[3] + m[5]
    for t in tokens:
        if re.fullmatch(rb"[-+]?\d*\.?\d+", t):
            ops.append(float(t))
            continue
        if t in (b"[", b"]") or t[:1] in (b"/", b"<", b"("):
            if t[:1] == b"/":
                ops.append(t)
            continue
        nums = [x for x in ops if isinstance(x, float)]
        if t == b"q":
            stack.append(ctm)
        elif t == b"Q":
            ctm = stack.pop() if stack else ctm
        elif t == b"cm" and len(nums) >= 6:
            ctm = mul(tuple(nums[-6:]), ctm)
        elif t in (b"m", b"l") and len(nums) >= 2:
            path.append(point(nums[-2], nums[-1], ctm))
        elif t == b"c" and len(nums) >= 6:
            path.append(point(nums[-2], nums[-1], ctm))
        elif t == b"re" and len(nums) >= 4:
            x, y, w, h = nums[-4:]
            path += [point(x, y, ctm), point(x + w, y + h, ctm)]
        elif t in (b"W", b"W*"):
            path = []  # a clip path draws nothing
        elif t in (b"S", b"s", b"f", b"F", b"f*", b"B", b"B*", b"b", b"b*"):
            for _, y in path:
                mark(y)
            path = []
        elif t == b"n":
            path = []
        elif t == b"Do":
            for x, y in ((0, 0), (1, 0), (0, 1), (1, 1)):
                mark(point(x, y, ctm)[1])
        elif t == b"Tf" and nums:
            tf = nums[-1]
        elif t == b"BT":
            tm = (1, 0, 0, 1, 0, 0)
        elif t == b"Tm" and len(nums) >= 6:
            tm = tuple(nums[-6:])
        elif t == b"Td" and len(nums) >= 2:
            tm = mul((1, 0, 0, 1, nums[-2], nums[-1]), tm)
        elif t in (b"Tj", b"TJ", b"'", b'"'):
            m = mul(tm, ctm)
            y = m[5]
            mark(y)
            size = tf * abs(m[0] * m[3] - m[1] * m[2]) ** 0.5
            if top_text is None or y > top_text[0] + 0.5:
                top_text = (y, size)
            elif abs(y - top_text[0]) <= 0.5:
                top_text = (y, max(size, top_text[1]))
        ops = []
    return low, top_text


def page_refs(data, body):
    """The page objects in reading order: the page tree's /Kids, depth first."""
    root = re.search(rb"/Root (\d+) 0 R", data)
    if not root:
        fail_usage("no /Root in the PDF")
    pages = re.search(rb"/Pages (\d+) 0 R", body(int(root.group(1))))
    out = []
    def walk(n):
        o = body(n)
        if re.match(rb"\s*<</Type /Pages\b", o):
            for k in re.findall(rb"(\d+) 0 R", re.search(rb"/Kids \[([^\]]*)\]", o).group(1)):
                walk(int(k))
        else:
            out.append(n)
    walk(int(pages.group(1)))
    return out


def read_pages(path, margin=34.0):
    """Per page in order: its object number, fill (0..1), and (y, size) of its topmost text."""
    try:
        data = open(path, "rb").read()
    except OSError as e:
        fail_usage("cannot read '%s': %s" % (path, e.strerror))
    if not data.startswith(b"%PDF"):
        fail_usage("'%s' is not a PDF" % path)
    offs, body = objects(data)
    pages = []
    for n in page_refs(data, body):
        o = body(n)
        box = re.search(rb"/MediaBox \[([-\d.\s]+)\]", o)
        refs = re.search(rb"/Contents (?:(\d+) 0 R|\[([\d\s0R]+)\])", o)
        if not box or not refs:
            fail_usage("page object %d without MediaBox or Contents" % n)
        ids = [int(refs.group(1))] if refs.group(1) else [int(x) for x in re.findall(rb"(\d+) 0 R", refs.group(2))]
        content = b"\n".join(stream(body(i)) for i in ids)
        height = float(box.group(1).split()[3])
        low, top = scan(content)
        usable = height - 2 * margin
        fill = 0.0 if low is None else 1.0 - max(0.0, min(1.0, (low - margin) / usable))
        pages.append({"object": n, "fill": fill, "top": top, "height": height})
    if not pages:
        fail_usage("'%s' has no pages" % path)
    return data, body, pages


def destinations(data, body):
    """Named destinations (Chromium writes one per element id a link points at): name -> (page object, y)."""
    m = re.search(rb"/Dests (\d+) 0 R", data)
    if not m:
        return {}
    return {k.decode("latin-1"): (int(p), float(y)) for k, p, y in
            re.findall(rb"/([^\s/\[]+) \[(\d+) 0 R /XYZ [-\d.]+ ([-\d.]+)", body(int(m.group(1))))}


def failures(pages, limit):
    """(page number, why) for every page the rules reject."""
    out = []
    for i, p in enumerate(pages[:-1]):
        nxt = pages[i + 1]["top"]
        if p["fill"] < MIN_FILL:
            out.append((i + 1, "%.0f %% full, under a quarter" % (100 * p["fill"])))
        elif 1 - p["fill"] > limit and not (nxt is not None and nxt[1] >= CHAPTER_PT):
            out.append((i + 1, "%.0f %% blank, and the next page does not open a chapter" % (100 * (1 - p["fill"]))))
    return out


def main():
    args, allow = sys.argv[1:], 0
    if args[:1] == ["--allow"]:
        if len(args) < 2 or not args[1].isdigit():
            fail_usage("--allow needs a whole number")
        allow, args = int(args[1]), args[2:]
    if not args:
        fail_usage("usage: page_fill.py [--allow N] REPORT.pdf [LIMIT] [MARGIN_PT]")
    path = args[0]
    try:
        limit = float(args[1]) if len(args) > 1 else 0.6
        margin = float(args[2]) if len(args) > 2 else 34.0
    except ValueError:
        fail_usage("LIMIT and MARGIN_PT must be numbers")
    _, _, pages = read_pages(path, margin)
    bad = failures(pages, limit)
    for n, why in bad:
        print("BLANK PAGE %d: %s" % (n, why))
    body = pages[:-1] or pages
    full = max(range(len(body)), key=lambda i: body[i]["fill"])
    empty = min(range(len(body)), key=lambda i: body[i]["fill"])
    print("page_fill: %s: %d page(s), %d rejected%s; fullest page %d (%.0f %% full), emptiest page %d (%.0f %%)%s"
          % (path, len(pages), len(bad), " (%d allowed)" % allow if allow else "",
             full + 1, 100 * body[full]["fill"], empty + 1, 100 * body[empty]["fill"],
             ", the last page (%.0f %%) aside" % (100 * pages[-1]["fill"]) if len(pages) > 1 else ""))
    sys.exit(1 if len(bad) > allow else 0)


if __name__ == "__main__":
    main()
