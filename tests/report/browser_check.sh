#!/usr/bin/env bash
# Browser check of the report (issue: a report that prints): render REPORT_HTML in headless
# Chromium at the printable width of an A4 page (186 mm = 703 px at 96 dpi, the margins of
# paper/style.css's @page) and fail, one line per problem, on
#   * a figure that does not load or draws nothing (an SVG without path, line, rect, circle,
#     polyline, polygon or text),
#   * a table wider than the page (the print rules of style.css apply at this width),
#   * a formula that pandoc could not turn into MathML (a math span without <math>) or a
#     MathML <merror>,
#   * text in a figure that prints below 8 pt (the base size of each SVG <text>, scaled by
#     the width the figure takes on the page; 1 px = 0.75 pt at the A4 printable width),
#   * a table cell in which a word, a number or an identifier wraps onto a second line,
#   * a number with more than 10 significant digits in a table cell (outside code, a command
#     line or a file name);
#   * plain-text math in a table cell (V_i, rho, lambda0, 2pi) outside code, a command line or
#     a file name, or a raw identifier (piecewise_cubic_polynomial) outside code there,
#   * a sub- or superscript in a figure below 6 pt (gnuplot's <tspan> with its own size),
#   * a raw caret exponent (2^-8, ^{...}) or a bare nan in the text outside code, where the
#     reader should see a superscript, or a word saying what failed.
# The checks run as a script injected into a copy of the page; Chromium's --dump-dom brings
# their result back.  Exit 0 when nothing is wrong, 1 otherwise, 2 on a usage error.
# usage: browser_check.sh REPORT_HTML
export LC_ALL=C  # numbers are read and printed with '.' whatever the user's locale
set -u
html=${1:-}
[ -f "$html" ] || { echo "browser_check: no file '$html'" >&2; exit 2; }
chrome=$(command -v chromium || command -v chromium-browser || true)
[ -n "$chrome" ] || { echo "browser_check: chromium not installed (make deps installs it)" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cat > "$tmp/check.js" <<'JS'
window.addEventListener('load', function () {
  var out = [], W = document.documentElement.clientWidth;
  var flat = function (s) { return s.replace(/\s+/g, ' ').trim(); };
  // The caption of the table a cell stands in, as a problem line names it.
  var captionOf = function (cell) {
    var t = cell.closest('table'), c = t && t.querySelector('caption');
    return flat(c ? c.textContent : '').slice(0, 60);
  };
  var name = function (el) {
    var f = el.closest('figure'), c = f && f.querySelector('figcaption');
    return flat(c ? c.textContent : (el.alt || el.src.slice(0, 50))).slice(0, 70);
  };
  document.querySelectorAll('img').forEach(function (im) {
    if (!im.complete || im.naturalWidth === 0) { out.push('FIGURE does not load: ' + name(im)); return; }
    var s = im.getAttribute('src') || '';
    if (s.indexOf('data:image/svg+xml') === 0) {
      var body = s.slice(s.indexOf(',') + 1), txt = '';
      try { txt = s.indexOf(';base64,') > 0 ? atob(body) : decodeURIComponent(body); } catch (e) {}
      if (!/<(path|polyline|polygon|line|rect|circle|text)\b/.test(txt)) out.push('FIGURE draws nothing: ' + name(im));
    }
  });
  document.querySelectorAll('table').forEach(function (t, i) {
    var r = t.getBoundingClientRect();
    if (r.right > W + 1) {
      var c = t.querySelector('caption');
      out.push('TABLE wider than the page (' + Math.round(r.width) + ' px, page ' + W + ' px): ' +
               flat(c ? c.textContent : 'table ' + i).slice(0, 70));
    }
  });
  // Text below 8 pt in a figure: the SVG's own font sizes times the scale it is drawn at.
  var MIN_PT = 8, MIN_SCRIPT_PT = 6, PT_PER_PX = 0.75;
  document.querySelectorAll('img').forEach(function (im) {
    var s = im.getAttribute('src') || '';
    if (s.indexOf('data:image/svg+xml') !== 0 || !im.complete) return;
    var body = s.slice(s.indexOf(',') + 1), txt = '';
    try {
      txt = s.indexOf(';base64,') < 0 ? decodeURIComponent(body) :
        new TextDecoder().decode(Uint8Array.from(atob(body), function (c) { return c.charCodeAt(0); }));
    } catch (e) { return; }
    var svg = new DOMParser().parseFromString(txt, 'image/svg+xml').documentElement;
    var vb = (svg.getAttribute('viewBox') || '').split(/[\s,]+/).map(Number);
    var vw = vb.length === 4 && vb[2] > 0 ? vb[2] : parseFloat(svg.getAttribute('width'));
    var shown = im.getBoundingClientRect().width;
    if (!(vw > 0) || !(shown > 0)) return;
    var size = function (el) {  // the font size a <text> inherits (attribute or style), in SVG units
      for (var e = el; e && e.getAttribute; e = e.parentNode) {
        var st = (e.getAttribute('style') || '').match(/font-size:\s*([0-9.]+)/);
        if (st) return parseFloat(st[1]);
        if (e.getAttribute('font-size')) return parseFloat(e.getAttribute('font-size'));
      }
      return 16;  // the SVG default
    };
    // The smallest printed size among the elements of one tag, reported when under `min`:
    // <text> for the text itself, <tspan> for a sub- or superscript (gnuplot's enhanced text
    // sets it with its own, smaller font size), so an exponent of an axis label stays legible.
    var check = function (tag, min, what) {
      var smallest = Infinity, sample = '';
      Array.prototype.forEach.call(svg.getElementsByTagName(tag), function (t) {
        if (!flat(t.textContent)) return;
        var pt = size(t) * shown / vw * PT_PER_PX;
        if (pt < smallest) { smallest = pt; sample = flat(t.textContent).slice(0, 20); }
      });
      if (smallest < min)
        out.push(what + ' in figure ' + (im.dataset.figure || '?') + ' (' + smallest.toFixed(1) + ' pt, "' +
                 sample + '"): ' + name(im));
    };
    check('text', MIN_PT, 'SMALL TEXT');
    check('tspan', MIN_SCRIPT_PT, 'SMALL SCRIPT');
  });
  // A word or number that wraps inside a table cell: its text range has boxes on two lines.
  document.querySelectorAll('td, th').forEach(function (cell) {
    var walker = document.createTreeWalker(cell, NodeFilter.SHOW_TEXT), node;
    while ((node = walker.nextNode())) {
      var re = /[^\s\u200b]+/g, m;
      while ((m = re.exec(node.data))) {
        var r = document.createRange();
        r.setStart(node, m.index); r.setEnd(node, m.index + m[0].length);
        var boxes = r.getClientRects(), top = null, split = false;
        for (var i = 0; i < boxes.length; i++) {
          if (boxes[i].width === 0) continue;
          if (top === null) top = boxes[i].top; else if (Math.abs(boxes[i].top - top) > 2) split = true;
        }
        if (split) {
          out.push('TABLE CELL splits "' + m[0].slice(0, 30) + '": ' + captionOf(cell));
          return;
        }
      }
    }
  });
  // Raw notation in the text a reader sees (code and formulas aside).
  var walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT), node;
  while ((node = walker.nextNode())) {
    var p = node.parentNode;
    if (p.closest('code, pre, script, style, math, .math')) continue;
    // nan as a program prints it (lower case); the word NaN in a sentence is the reader's term.
    [/\w\^[-(\w]|\^\{/, /(^|[^\w.-])[-+]?nan([^\w]|$)/].forEach(function (re) {
      var raw = node.data.match(re);
      if (raw) out.push('RAW TEXT "' + raw[0] + '": ' + flat(node.data).slice(0, 60));
    });
  }
  // Plain-text math in a table cell ("V_i = rho_i/m_i", "lambda0", "2pi"): the tables' filter
  // (paper/tsv-tables.lua, ascii_math) sets it as symbols; a command line or a file name stays.
  document.querySelectorAll('td, th').forEach(function (cell) {
    if (cell.querySelector('code')) return;
    var t = cell.textContent.replace(/\u200B/g, '');
    if (/--|\.[a-z]{2,3}\b/.test(t)) return;
    var raw = t.match(/(^|[^A-Za-z])(rho|lambda|eps|epsilon|theta|kappa|delta|sigma|mu|Omega|\d*pi)([^A-Za-z]|$)/) ||
              t.match(/(^|[^\w])[A-Za-z]_[a-z0-9]([^\w]|$)/);
    if (raw) {
      out.push('RAW MATH "' + raw[0].trim() + '" in a table: ' + captionOf(cell));
    }
    // A raw identifier (piecewise_cubic_polynomial, h15_cell_exact) in a cell's prose: the
    // tables' filter names it for a reader (human_names) or sets it as code.
    var plain = '';
    var tw = document.createTreeWalker(cell, NodeFilter.SHOW_TEXT), tn;
    while ((tn = tw.nextNode())) if (!tn.parentNode.closest('code')) plain += tn.data;
    var ident = plain.replace(/\u200B/g, '').match(/[A-Za-z0-9]{2,}_[A-Za-z0-9_]*[A-Za-z0-9]/);
    if (ident) out.push('RAW IDENTIFIER "' + ident[0] + '" in a table: ' + captionOf(cell));
    // A number with more than 10 significant digits (a double printed in full).
    var nums = t.match(/\d+\.\d+/g) || [];
    for (var k = 0; k < nums.length; k++) {
      if (nums[k].replace('.', '').replace(/^0+/, '').length > 10) {
        out.push('LONG NUMBER "' + nums[k] + '" in a table: ' + captionOf(cell));
        break;
      }
    }
  });
  document.querySelectorAll('span.math').forEach(function (m) {
    if (!m.querySelector('math')) out.push('FORMULA not converted to MathML: ' + flat(m.textContent).slice(0, 60));
  });
  document.querySelectorAll('merror').forEach(function (m) { out.push('FORMULA MathML error: ' + flat(m.textContent).slice(0, 60)); });
  var pre = document.createElement('pre');
  pre.id = 'browser-check';
  var tag = 'BROWSER-CHECK-';  // split, so that the script's own text holds no marker
  pre.textContent = tag + 'BEGIN\n' + out.join('\n') + '\n' + tag + 'END ' + out.length;
  document.body.appendChild(pre);
});
JS
# The copy: the check script just before </body>.
awk -v js="$tmp/check.js" '/<\/body>/ && !done { print "<script>"; while ((getline l < js) > 0) print l; print "</script>"; done = 1 } { print }' \
  "$html" > "$tmp/page.html"
"$chrome" --headless --no-sandbox --disable-gpu --hide-scrollbars --window-size=703,1000 \
  --virtual-time-budget=10000 --dump-dom "file://$tmp/page.html" > "$tmp/dom.html" 2> "$tmp/chrome.log"
result=$(awk '/BROWSER-CHECK-BEGIN/ { on = 1; next } /BROWSER-CHECK-END/ { print; exit } on && NF { print "  " $0 }' "$tmp/dom.html" |
  sed 's/&gt;/>/g; s/&lt;/</g; s/&amp;/\&/g')
if [ -z "$result" ]; then
  echo "browser_check: $html: Chromium returned no result (see its log below)" >&2
  tail -5 "$tmp/chrome.log" >&2
  exit 1
fi
# Every problem counts: no figure is exempt from the 8 pt rule (the list of figures drawn
# before the rule emptied when the last of them was redrawn at print size).
problems=$(printf '%s\n' "$result" | grep -v '^BROWSER-CHECK-END' |
  awk 'NF { print; n++ } END { print "COUNT " n + 0 }')
n=$(printf '%s\n' "$problems" | sed -n 's/^COUNT //p')
printf '%s\n' "$problems" | grep -v '^COUNT '
echo "browser_check: $html: $n problem(s) at the A4 printable width"
[ "$n" = 0 ]
