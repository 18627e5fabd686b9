#!/usr/bin/env python3
"""The audit's errors by part (line type, heading band, extreme tension), from
`towdb audit --json` output, as docs/audit.md and db/README.md tabulate them.

Percentiles as towdb audit computes them (linear between order statistics, the
same as numpy's default). Heading bands: [0, 30), [30, 60), [60, 120), [120, 180].
Usage: audit_parts.py audit.json
"""
import json
import sys


def quantile(values, f):
    v = sorted(values)
    if not v:
        return float("nan")
    pos = f * (len(v) - 1)
    i = int(pos)
    if i + 1 >= len(v):
        return v[-1]
    return v[i] + (pos - i) * (v[i + 1] - v[i])


def row(name, qs, key="rel_error_999"):
    errs = [q[key] for q in qs if q.get(key) is not None]
    cov = [q["covered"] for q in qs if q.get("covered") is not None]
    if not errs:
        return f"| {name} | 0 | - | - | - | - |"
    return (f"| {name} | {len(errs)} | {100 * quantile(errs, 0.5):.1f} % | {100 * quantile(errs, 0.9):.1f} % | "
            f"{100 * max(errs):.1f} % | {sum(cov)} of {len(cov)} |")


def main():
    with open(sys.argv[1]) as f:
        data = json.load(f)
    qs = data["questions"]
    print("| questions | n | median | 90th pct | worst | +/- covers |")
    print("|---|---:|---:|---:|---:|---:|")
    print(row("all", qs))
    for line in ("fiber", "wire"):
        print(row(line, [q for q in qs if q["line"] == line]))
    for lo, hi in ((0, 30), (30, 60), (60, 120), (120, 180.0001)):
        band = [q for q in qs if lo <= q["heading_deg"] < hi]
        print(row(f"heading {lo}-{int(hi)} deg", band))
    print(row("extreme tension (mean + dynamic)", qs, "rel_error_extreme"))
    refused = [q for q in qs if not q["answered"]]
    print(f"\nanswered {len(qs) - len(refused)} of {len(qs)}")


if __name__ == "__main__":
    main()
