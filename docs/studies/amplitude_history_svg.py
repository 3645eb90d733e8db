"""The amplitude per period of a time-domain run (disc_time_domain_sweep's csv) as an SVG:
max |x(t)| of the mid-blade DOF against the period, one line per frequency.
Usage: python3 amplitude_history_svg.py history.csv out.svg [title]"""
import csv
import sys

rows = list(csv.DictReader(open(sys.argv[1])))
title = sys.argv[3] if len(sys.argv) > 3 else "amplitude per period"
runs = {}
for r in rows:
    runs.setdefault(r["frequency_hz"], []).append((int(r["period"]), float(r["amplitude_mm"])))
W, H, L, R, T, B = 720, 380, 70, 20, 40, 50
pmax = max(p for run in runs.values() for p, _ in run)
amax = max(a for run in runs.values() for _, a in run) * 1.05
x = lambda p: L + (W - L - R) * p / pmax
y = lambda a: H - B - (H - T - B) * a / amax
out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" font-family="sans-serif" font-size="12">',
       f'<rect width="{W}" height="{H}" fill="white"/>',
       f'<text x="{W / 2}" y="22" text-anchor="middle" font-size="14">{title}</text>',
       f'<line x1="{L}" y1="{H - B}" x2="{W - R}" y2="{H - B}" stroke="black"/>',
       f'<line x1="{L}" y1="{T}" x2="{L}" y2="{H - B}" stroke="black"/>',
       f'<text x="{(W + L) / 2}" y="{H - 12}" text-anchor="middle">period</text>',
       f'<text x="16" y="{(H - B + T) / 2}" text-anchor="middle" transform="rotate(-90 16 {(H - B + T) / 2})">max |x(t)| over the period (mm)</text>']
for k in range(6):
    p, a = pmax * k / 5, amax * k / 5
    out.append(f'<text x="{x(p)}" y="{H - B + 16}" text-anchor="middle">{p:.0f}</text>')
    out.append(f'<text x="{L - 6}" y="{y(a) + 4}" text-anchor="end">{a:.3f}</text>')
    out.append(f'<line x1="{L}" y1="{y(a)}" x2="{W - R}" y2="{y(a)}" stroke="#ddd"/>')
colours = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#7f7f7f", "#17becf"]
for i, (hz, run) in enumerate(sorted(runs.items(), key=lambda kv: float(kv[0]))):
    pts = " ".join(f"{x(p):.1f},{y(a):.1f}" for p, a in run)
    c = colours[i % len(colours)]
    out.append(f'<polyline points="{pts}" fill="none" stroke="{c}" stroke-width="0.8"/>')
    out.append(f'<text x="{W - R - 4}" y="{T + 14 * (i + 1)}" text-anchor="end" fill="{c}">{float(hz):.0f} Hz</text>')
out.append("</svg>")
open(sys.argv[2], "w").write("\n".join(out))
