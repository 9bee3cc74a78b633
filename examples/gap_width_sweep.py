#!/usr/bin/env python3
"""Sweep the gap width of the bundled annular valve (cases/annular_valve.toml) and plot the gap's
mean flux density B_avg [T] and the valve's pressure drop [MPa] against it.

Each width is an edit through the case key API (Case.with_, metres), then one magnetostatic
solve and one valve-chain evaluation at the case's current (1 A) and flow rate ([valve] flow).

    PYTHONPATH=build/python python3 examples/gap_width_sweep.py [--points N] [--out FILE.png]

Headless (no display): MPLBACKEND=Agg, as CTest runs it (test python.example_gap_width_sweep).
"""

import argparse
import os

import matplotlib.pyplot as plt
import numpy as np

import rheomag

HERE = os.path.dirname(os.path.abspath(__file__))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--points", type=int, default=6, help="gap widths to solve (default 6)")
    parser.add_argument("--out", default="gap_width_sweep.png", help="figure to write")
    args = parser.parse_args()

    base = rheomag.Case.load(os.path.join(HERE, "..", "cases", "annular_valve.toml"))
    widths = np.linspace(0.6e-3, 1.4e-3, args.points)  # m, around the paper's 1.0 mm
    b_avg, dp = [], []
    for width in widths:
        design = base.with_({"geometry.gap_width": float(width)})
        b_avg.append(design.solve().gaps[0].B_avg)
        dp.append(design.valve()["points"][0]["dp_total"])
        print(f"gap {width * 1e3:.2f} mm: B_avg {b_avg[-1]:.3f} T, dp {dp[-1] / 1e6:.3f} MPa")

    fig, left = plt.subplots(figsize=(6, 4))
    left.plot(widths * 1e3, b_avg, "o-", color="tab:blue")
    left.set_xlabel("gap width [mm]")
    left.set_ylabel("B_avg in the gap [T]", color="tab:blue")
    right = left.twinx()
    right.plot(widths * 1e3, np.array(dp) / 1e6, "s--", color="tab:red")
    right.set_ylabel("pressure drop at 1 A [MPa]", color="tab:red")
    left.set_title(f"{base.name}: gap width sweep")
    fig.tight_layout()
    fig.savefig(args.out, dpi=120)
    print(f"wrote {args.out}")
    # A wider gap carries less flux at the same current and drops less pressure.
    if not (b_avg[0] > b_avg[-1] and dp[0] > dp[-1]):
        raise SystemExit("unexpected: B_avg and dp do not fall with the gap width")


if __name__ == "__main__":
    main()
