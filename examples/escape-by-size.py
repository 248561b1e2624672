#!/usr/bin/env python3
"""Peripheral leaving, measured: reads a `swarmagg compare` folder of a Bayindir world and prints,
per engine, the final mean member spacing, the LEAVE attempts from the rim and from inside with
the fraction of each that got out, and the escape rate per aggregate of size m (escapes /
aggregate_time, from summary.json's pooled `leave_by_size`) beside the two leave laws of the
models (docs/models.md): every member may leave, m p/dt, and only the periphery may, periph(m) p/dt
with periph(m) = min(m, pi (1.20 m^0.48 - 1)).

It also checks that compare.json and escape_rate.csv say the same as the engines' summary.json
(exit 1 when they do not), and fits rate = c m^b over the sizes with at least MIN_ESCAPES
escapes (weighted least squares on log rate, weight = escapes): b = 1 is the every-member law,
b near 0.5 the periphery law. Standard library only.

    build/swarmagg compare worlds/examples/compact.yaml --set robots.count=200 \\
        --set run.duration=3000 --replicates 6 --out runs/dense-compare
    /usr/bin/python3 examples/escape-by-size.py runs/dense-compare
"""
import csv
import json
import math
import re
import sys
from pathlib import Path

MIN_ESCAPES = 20  # sizes with fewer escapes are listed but not fitted: their rates are noise
ENGINES = ("kinematic", "box2d")


def world_value(folder, key):
    """A scalar of world.resolved.yaml (`  key: value`), without a YAML library."""
    text = (folder / "world.resolved.yaml").read_text()
    match = re.search(r"^\s*" + re.escape(key) + r":\s*([^\s#]+)", text, re.M)
    if not match:
        sys.exit(f"{folder}/world.resolved.yaml: no key {key}")
    return match.group(1)


def periph(m):
    return min(m, math.pi * (1.20 * m**0.48 - 1.0))


def fit_power(rows):
    """Weighted least squares of log(rate) = log(c) + b log(m); returns (c, b)."""
    pts = [(math.log(r["size"]), math.log(r["rate"]), r["escapes"]) for r in rows]
    w = sum(p[2] for p in pts)
    mx = sum(p[0] * p[2] for p in pts) / w
    my = sum(p[1] * p[2] for p in pts) / w
    sxx = sum(p[2] * (p[0] - mx) ** 2 for p in pts)
    sxy = sum(p[2] * (p[0] - mx) * (p[1] - my) for p in pts)
    b = sxy / sxx
    return math.exp(my - b * mx), b


def main(folder):
    folder = Path(folder)
    compare = json.loads((folder / "compare.json").read_text())
    table = {int(r["size"]): r for r in csv.DictReader(open(folder / "escape_rate.csv"))}
    problems = []
    for arm_key, engine in zip(("a", "b"), ENGINES):
        run = folder / engine
        summary = json.loads((run / "summary.json").read_text())
        pooled = summary["pooled"]
        p = float(world_value(run, "p_leave"))
        dt = float(summary["dt"])
        tried, out = pooled["leave_attempts"], pooled["escapes"]
        print(f"== {engine}: {summary['world']}, {len(summary['replicates'])} replicates, "
              f"{summary['duration']} tu, N = {summary['agents']}, p = {p}, dt = {dt}")
        spacing = pooled["final"]["mean_member_spacing"]
        print(f"final mean member spacing: {spacing:.4f}" if spacing is not None
              else "final mean member spacing: none (no aggregate at the end)")
        for where in ("rim", "inside"):
            n, k = tried[where], out[where]
            print(f"{where:6s} attempts {n:6d}, escapes {k:6d}, fraction out "
                  + (f"{k / n:.3f}" if n else "-"))
        print(f"total  attempts {tried['total']:6d}, escapes {out['total']:6d}, fraction out "
              + (f"{out['total'] / tried['total']:.3f}" if tried["total"] else "-"))

        # compare.json and escape_rate.csv against summary.json
        cj = compare[arm_key]["leave_attempts"]
        for where in ("rim", "inside"):
            if (cj[f"{where}_attempts"], cj[f"{where}_got_out"]) != (tried[where], out[where]):
                problems.append(f"{engine} compare.json {where} differs from summary.json")
        rows = []
        for entry in pooled["leave_by_size"]:
            m, t, k = entry["size"], entry["aggregate_time"], entry["escapes"]
            if t <= 0:
                continue
            all_law, periph_law = m * p / dt, periph(m) * p / dt
            rows.append({"size": m, "time": t, "attempts": entry["attempts"], "escapes": k,
                         "rate": k / t, "all": all_law, "periph": periph_law})
            csv_row = table.get(m)
            if (csv_row is None or int(csv_row[f"{engine}_escapes"]) != k
                    or not math.isclose(float(csv_row[f"{engine}_rate"]), k / t, rel_tol=1e-4)
                    or not math.isclose(float(csv_row["all_members_law"]), all_law, rel_tol=1e-4)
                    or not math.isclose(float(csv_row["periphery_law"]), periph_law,
                                        rel_tol=1e-4)):
                problems.append(f"{engine} escape_rate.csv size {m} differs from summary.json")
        print("size  aggregate_tu  attempts  escapes  escape/tu  exact 95% interval   m p/dt"
              "  periph p/dt  rate/(m p/dt)  rate/(periph p/dt)")
        for r in rows:
            csv_row = table.get(r["size"], {})
            low = float(csv_row.get(f"{engine}_ci95_low", "nan"))
            high = float(csv_row.get(f"{engine}_ci95_high", "nan"))
            print(f"{r['size']:4d}  {r['time']:12.1f}  {r['attempts']:8d}  {r['escapes']:7d}"
                  f"  {r['rate']:9.5f}  [{low:7.5f}, {high:7.5f}]  {r['all']:7.4f}"
                  f"  {r['periph']:11.4f}  {r['rate'] / r['all']:13.3f}"
                  f"  {r['rate'] / r['periph']:18.3f}")
        fitted = [r for r in rows if r["escapes"] >= MIN_ESCAPES]
        for label, sizes in (("all sizes", fitted),
                             ("sizes >= 6 (where the laws differ)",
                              [r for r in fitted if r["size"] >= 6])):
            observed = sum(r["escapes"] for r in sizes)
            if not observed:
                continue
            ratios = ", ".join(f"{law} {observed / sum(r[key] * r['time'] for r in sizes):.3f}"
                               for key, law in (("all", "m p/dt"), ("periph", "periph(m) p/dt")))
            print(f"{label} with >= {MIN_ESCAPES} escapes: observed / expected escapes under "
                  f"{ratios}")
        big = [r for r in fitted if r["size"] >= 3]
        if len(big) >= 2:
            c, b = fit_power(big)
            _, b_periph = fit_power([dict(r, rate=r["periph"]) for r in big])
            print(f"fit over sizes 3..{big[-1]['size']} (weights: escapes): escape rate = "
                  f"{c:.5f} m^{b:.3f} per tu; the same fit gives exponent 1 for m p/dt and "
                  f"{b_periph:.3f} for periph(m) p/dt")
        print()
    for problem in problems:
        print("MISMATCH:", problem)
    return 1 if problems else 0


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1]))
