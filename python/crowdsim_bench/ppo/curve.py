"""The learning curve as an SVG drawn with the standard library alone (no matplotlib on the
Debian machines): success, collision and timeout rates of the last 200 training episodes, and
their mean return, against environment steps, from learning_curve.csv's rows."""
from __future__ import annotations

import math
from typing import Dict, List
from xml.sax.saxutils import escape

WIDTH, HEIGHT = 720, 360
LEFT, RIGHT, TOP, BOTTOM = 60, 150, 30, 45
SERIES = [("success", "#2a9d3a"), ("collision", "#d62728"), ("timeout", "#7f7f7f"),
          ("mean_return", "#1f77b4")]


def _number(text: str) -> float:
    try:
        return float(text)
    except (TypeError, ValueError):
        return float("nan")


def write_svg(rows: List[Dict[str, str]], path: str, title: str) -> None:
    steps = [_number(r["steps"]) for r in rows]
    last = max(steps) if steps else 1.0
    plot_w, plot_h = WIDTH - LEFT - RIGHT, HEIGHT - TOP - BOTTOM

    def x(s: float) -> float:
        return LEFT + plot_w * s / max(last, 1.0)

    def y(v: float) -> float:  # rates and the return share the axis [-0.25, 1]
        v = min(1.0, max(-0.25, v))
        return TOP + plot_h * (1.0 - (v + 0.25) / 1.25)

    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{WIDTH}" height="{HEIGHT}" '
           f'font-family="sans-serif" font-size="12">',
           f'<rect width="{WIDTH}" height="{HEIGHT}" fill="white"/>',
           f'<text x="{LEFT}" y="18" font-size="14">{escape(title)}: PPO, last 200 training '
           'episodes</text>']
    for v in (-0.25, 0.0, 0.25, 0.5, 0.75, 1.0):
        out.append(f'<line x1="{LEFT}" x2="{LEFT + plot_w}" y1="{y(v):.1f}" y2="{y(v):.1f}" '
                   f'stroke="#ddd"/>')
        out.append(f'<text x="{LEFT - 6}" y="{y(v) + 4:.1f}" text-anchor="end">{v:g}</text>')
    for i in range(5):
        s = last * i / 4
        label = f"{s / 1e6:.1f}M" if last >= 1e6 else f"{s / 1e3:.0f}k"
        out.append(f'<text x="{x(s):.1f}" y="{TOP + plot_h + 16}" text-anchor="middle">'
                   f'{label}</text>')
    out.append(f'<text x="{LEFT + plot_w / 2}" y="{HEIGHT - 8}" text-anchor="middle">'
               'environment steps</text>')
    out.append(f'<rect x="{LEFT}" y="{TOP}" width="{plot_w}" height="{plot_h}" fill="none" '
               'stroke="#444"/>')
    for i, (key, colour) in enumerate(SERIES):
        points = [(x(s), y(_number(r.get(key)))) for s, r in zip(steps, rows)
                  if not math.isnan(_number(r.get(key)))]
        if points:
            d = " ".join(f"{px:.1f},{py:.1f}" for px, py in points)
            out.append(f'<polyline points="{d}" fill="none" stroke="{colour}" '
                       'stroke-width="1.5"/>')
        ly = TOP + 10 + 18 * i
        out.append(f'<line x1="{WIDTH - RIGHT + 12}" x2="{WIDTH - RIGHT + 32}" y1="{ly}" '
                   f'y2="{ly}" stroke="{colour}" stroke-width="2"/>')
        out.append(f'<text x="{WIDTH - RIGHT + 38}" y="{ly + 4}">{key.replace("_", " ")}</text>')
    out.append("</svg>\n")
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(out))
