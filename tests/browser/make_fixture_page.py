#!/usr/bin/python3
"""Builds a standalone HTML page from a crux-replay JSON, report.css and replay.bundle.js,
embedded the way `crux report` embeds them, so the viewer is tested without the C++ report:

  <style>report.css</style>
  <div id="crux-replay"></div>
  <script type="application/json" id="crux-replay-data">JSON with every '<' written as \\u003c</script>
  <script>replay.bundle.js</script>

The page also holds a table and two inline SVG figures in #figures (for --expect-figures).
Usage: make_fixture_page.py --data FIXTURE.json --bundle replay.bundle.js --css report.css -o PAGE.html
"""
import argparse
import html
import json
import re


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--data", required=True)
    ap.add_argument("--bundle", required=True)
    ap.add_argument("--css", required=True)
    ap.add_argument("-o", "--output", required=True)
    a = ap.parse_args()

    with open(a.data) as f:
        data = json.load(f)
    with open(a.bundle) as f:
        bundle = f.read()
    with open(a.css) as f:
        css = f.read()
    # Inline <script> and <style> end at the first "</script" / "</style": neither may occur inside.
    if re.search(r"</script", bundle, re.I) or re.search(r"</style", css, re.I):
        raise SystemExit("bundle or stylesheet contains a closing tag and cannot be inlined")
    data_text = json.dumps(data, separators=(",", ":")).replace("<", "\\u003c")

    moves = data.get("moves", [])
    reached = sum(1 for m in moves if m.get("success"))
    title = html.escape(data.get("title", "crux replay"))
    rows = "\n".join(
        f"<tr><td class=\"num\">{k + 1}</td><td>{html.escape(m['limb'])}</td><td class=\"num\">{m['hold']}</td>"
        f"<td class=\"{'good' if m['success'] else 'bad'}\">{'reached' if m['success'] else 'unreachable'}</td>"
        f"<td class=\"num\">{m['reward']:.3f}</td></tr>"
        for k, m in enumerate(moves[:8]))
    bars = "".join(
        f"<rect x=\"{20 + 22 * k}\" y=\"{110 - 80 * (m['reward'] + 1) / 2:.1f}\" width=\"16\" "
        f"height=\"{80 * (m['reward'] + 1) / 2:.1f}\" fill=\"{'#1f9e3a' if m['success'] else '#d62728'}\"/>"
        for k, m in enumerate(moves[:12]))
    points = " ".join(f"{20 + 22 * k},{110 - 4 * (m['last_frame'] - m['first_frame'] + 1)}"
                      for k, m in enumerate(moves[:12]))
    page = f"""<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<link rel="icon" href="data:,">
<title>{title}</title>
<style>
{css}
</style>
</head>
<body>
<h1>{title}</h1>
<p class="muted">A test page made from a fixture by tests/browser/make_fixture_page.py: {len(moves)} moves, {reached} reached, {data['frames']['count']} frames.</p>
<h2>Replay</h2>
<div id="crux-replay"></div>
<h2>Moves</h2>
<div class="table-wrap"><table>
<caption>The first moves of the fixture</caption>
<thead><tr><th class="num">move</th><th>limb</th><th class="num">hold</th><th>result</th><th class="num">reward</th></tr></thead>
<tbody>
{rows}
</tbody>
</table></div>
<h2>Figures</h2>
<div id="figures">
<figure><svg viewBox="0 0 300 120" width="300" height="120" role="img" aria-label="Reward per move">
<line x1="15" y1="110" x2="290" y2="110" stroke="#1d232b"/>{bars}</svg>
<figcaption>Figure 1. Reward per move (green: reached, red: unreachable).</figcaption></figure>
<figure><svg viewBox="0 0 300 120" width="300" height="120" role="img" aria-label="Frames per move">
<polyline fill="none" stroke="#1c6fd1" stroke-width="2" points="{points}"/>
<line x1="15" y1="110" x2="290" y2="110" stroke="#1d232b"/></svg>
<figcaption>Figure 2. Frames per move.</figcaption></figure>
</div>
<script type="application/json" id="crux-replay-data">{data_text}</script>
<script>{bundle}</script>
</body>
</html>
"""
    with open(a.output, "w") as f:
        f.write(page)


if __name__ == "__main__":
    main()
