#!/usr/bin/env bash
# Browser check of the report (issue: a report that prints): render REPORT_HTML in headless
# Chromium at the printable width of an A4 page (186 mm = 703 px at 96 dpi, the margins of
# paper/style.css's @page) and fail, one line per problem, on
#   * a figure that does not load or draws nothing (an SVG without path, line, rect, circle,
#     polyline, polygon or text),
#   * a table wider than the page (the print rules of style.css apply at this width),
#   * a formula that pandoc could not turn into MathML (a math span without <math>) or a
#     MathML <merror>.
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
n=$(printf '%s\n' "$result" | sed -n 's/^BROWSER-CHECK-END \([0-9]*\).*/\1/p')
printf '%s\n' "$result" | grep -v '^BROWSER-CHECK-END'
echo "browser_check: $html: $n problem(s) at the A4 printable width"
[ "$n" = 0 ]
