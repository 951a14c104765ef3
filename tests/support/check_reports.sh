#!/usr/bin/env bash
# Checks the HTML reports (index.html) under each DIR in a real browser: headless Chromium loads
# every report in a frame of a checker page and fails on
#   - a console message of a report (a failed resource load is one: Chromium logs it),
#   - an image that did not load (naturalWidth 0: missing or not an image),
#   - a link whose target cannot be read (file missing),
#   - a report that did not load, or a checker that did not finish (timeout).
#   usage: bash check_reports.sh <scratch-dir> DIR...
# CHROMIUM names the browser (default: chromium). Exit 0 ok, 1 a problem, 77 no browser.
set -u
scratch=${1:?}; shift
browser=${CHROMIUM:-chromium}
if ! command -v "$browser" >/dev/null 2>&1; then
  echo "SKIP no Chromium ($browser): apt-get install chromium"; exit 77
fi
mkdir -p "$scratch"
scratch=$(cd "$scratch" && pwd)
pages=()
for d in "$@"; do
  while IFS= read -r f; do pages+=("$f"); done < <(find "$(cd "$d" && pwd)" -name index.html | sort)
done
if [[ ${#pages[@]} -eq 0 ]]; then echo "FAIL no index.html under $*"; exit 1; fi
list=""
for p in "${pages[@]}"; do list+="\"file://$p\","; done
cat >"$scratch/check.html" <<HTML
<!DOCTYPE html><html><head><meta charset="utf-8"><title>report check</title></head><body>
<pre id="result">RUNNING</pre>
<script>
const pages = [${list%,}];
const problems = [];
let images = 0, links = 0, done = 0;
function readable(url) {
  try {
    const x = new XMLHttpRequest();
    x.open("GET", url, false);
    x.send();
    return (x.status === 0 || x.status === 200) && x.responseText !== null;
  } catch (e) { return false; }
}
function waitImages(doc) {
  return Promise.all(Array.from(doc.images).map(img => img.complete ? null :
    new Promise(r => { img.addEventListener("load", r); img.addEventListener("error", r); })));
}
async function check(url) {
  const frame = document.createElement("iframe");
  frame.style.width = "1200px"; frame.style.height = "900px";
  const loaded = new Promise(r => frame.addEventListener("load", r));
  frame.src = url;
  document.body.appendChild(frame);
  await loaded;
  const doc = frame.contentDocument;
  if (!doc || !doc.body || !doc.title) { problems.push("FAIL not loaded: " + url); return; }
  await waitImages(doc);
  for (const img of doc.images) {
    images++;
    if (!img.complete || img.naturalWidth === 0)
      problems.push("FAIL image not shown: " + img.getAttribute("src") + " in " + url);
  }
  for (const a of doc.querySelectorAll("a[href]")) {
    const href = a.getAttribute("href");
    if (href.startsWith("#") || /^[a-z]+:/.test(href)) {
      if (/^(https?|ftp):/.test(href)) problems.push("FAIL network link " + href + " in " + url);
      continue;
    }
    links++;
    if (!readable(a.href)) problems.push("FAIL broken link: " + href + " in " + url);
  }
  frame.remove();
  done++;
}
(async () => {
  for (const p of pages) await check(p);
  document.getElementById("result").textContent = problems.join("\n") + (problems.length ? "\n" : "") +
    "CHECKED pages=" + done + " of " + pages.length + " images=" + images + " links=" + links;
})();
</script></body></html>
HTML
# --enable-logging=stderr: the reports' console messages appear as "CONSOLE(...)" lines.
timeout 300 "$browser" --headless --no-sandbox --disable-gpu --allow-file-access-from-files \
  --enable-logging=stderr --v=0 --virtual-time-budget=600000 --user-data-dir="$scratch/profile" \
  --dump-dom "file://$scratch/check.html" >"$scratch/dom.html" 2>"$scratch/browser.log"
rc=$?
fail=0
if [[ $rc -ne 0 ]]; then echo "FAIL chromium exited $rc (log: $scratch/browser.log)"; fail=1; fi
result=$(sed -n '/<pre id="result">/,/<\/pre>/p' "$scratch/dom.html" | sed 's/<[^>]*>//g')
if grep -q "CONSOLE" "$scratch/browser.log"; then
  echo "FAIL console messages of the reports:"; grep "CONSOLE" "$scratch/browser.log" | head -20
  fail=1
fi
if ! grep -q "^CHECKED pages=${#pages[@]} of ${#pages[@]} " <<<"$result"; then
  echo "FAIL the checker did not finish: ${result:-no result} (log: $scratch/browser.log)"; fail=1
fi
if grep -q "^FAIL" <<<"$result"; then grep "^FAIL" <<<"$result" | head -30; fail=1; fi
if [[ $fail -eq 0 ]]; then echo "ok   reports in Chromium: $(grep '^CHECKED' <<<"$result")"; fi
exit $fail
