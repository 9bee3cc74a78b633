#!/usr/bin/env python3
"""Transient accuracy per CPU second: rheomag against GetDP on the same eddy-current cylinder.

The model is bench/peer/eddy_cylinder_step.fem (rheomag reads it directly) and its GetDP twin,
bench/peer/getdp/cylinder.{geo,pro}: a conducting cylinder (mu_r 1000, 5 MS/m, a = 10 mm) in a
long 10-turn solenoid whose current steps from 0 to 1 A at t = 0, simulated for 1 s. The
reference is the series solution (docs/transient.md):
    Phi(t) = Phi_inf [1 - sum_n 4 / j_n^2 exp(-j_n^2 t / (mu sigma a^2))],
plus the winding's own (instantaneous) flux. Each run is scored on
  - the response times: the flux linkage's t63 and t90 (crossings of 63.2 % and 90 % of the
    tool's own static flux linkage, linear between steps, as `rheomag transient` reports them),
    relative to the series' values: `rt` = the larger of the two errors;
  - the trajectory: the largest |lambda - lambda_series| / lambda_inf over the tool's own steps
    from 1 ms on (`traj`).
CPU = user + system seconds of every process a run starts (Gmsh's meshing included for GetDP).
Each tool runs a grid of meshes and time-step settings; the table gives, for each CPU budget,
the lowest error any run of each tool reached within that budget.

Usage: transient_vs_getdp.py [--rheomag build/app/rheomag] [--out runs.jsonl] [--quick]
Needs Debian's getdp, gmsh, python3-numpy and python3-scipy.
"""
import argparse
import json
import os
import resource
import shutil
import subprocess
import sys
import tempfile

import numpy as np
from scipy.optimize import brentq
from scipy.special import jn_zeros

HERE = os.path.dirname(os.path.abspath(__file__))
MU0 = 4e-7 * np.pi
TURNS, HEIGHT, RADIUS, OUTER = 10, 2e-3, 10e-3, 10.5e-3
MU_R, SIGMA, DURATION = 1000.0, 5e6, 1.0


class Series:
    """The cylinder's flux linkage after the current step, from the Bessel series."""

    def __init__(self):
        h0 = TURNS / HEIGHT  # A/m inside the winding
        self.core_final = TURNS * MU0 * MU_R * h0 * np.pi * RADIUS**2
        r = np.linspace(RADIUS, OUTER, 200001)  # the winding: H falls linearly to 0 at OUTER
        d_phi = MU0 * h0 * (OUTER - r) / (OUTER - RADIUS) * 2 * np.pi * r
        phi = np.concatenate([[0.0], np.cumsum((d_phi[1:] + d_phi[:-1]) / 2 * np.diff(r))])
        self.winding = TURNS * np.trapz(phi, r) / (OUTER - RADIUS)
        self.final = self.core_final + self.winding
        self.tau = MU0 * MU_R * SIGMA * RADIUS**2
        self.zeros = jn_zeros(0, 4000)

    def __call__(self, t):
        t = np.atleast_1d(np.asarray(t, float))
        tail = np.array([np.sum(4 / self.zeros**2 * np.exp(-self.zeros**2 * x / self.tau))
                         if x > 0 else 1.0 for x in t])
        return self.core_final * (1 - tail) + self.winding

    def rise(self, fraction):
        return brentq(lambda x: self(x)[0] - fraction * self.final, 1e-7, 10 * self.tau)


def crossing(t, y, target):
    k = int(np.argmax(y >= target))
    return t[k - 1] + (target - y[k - 1]) / (y[k] - y[k - 1]) * (t[k] - t[k - 1])


def score(series, t, y, final):
    """Errors of one run's (t, lambda) against the series; `final`: the tool's static lambda."""
    out = {}
    for name, fraction in (("e63", 1 - np.exp(-1)), ("e90", 0.9)):
        out[name] = crossing(t, y, fraction * final) / series.rise(fraction) - 1
    late = t >= 1e-3
    out["rt"] = max(abs(out["e63"]), abs(out["e90"]))
    out["traj"] = float(np.max(np.abs(y[late] - series(t[late])) / series.final))
    out["steps"] = len(t) - 1
    return out


def child_cpu():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def timed(cmd, cwd, stdout=subprocess.DEVNULL):
    start = child_cpu()
    subprocess.run(cmd, cwd=cwd, check=True, stdout=stdout, stderr=subprocess.PIPE, timeout=300)
    return child_cpu() - start


def fem_model(size, skin):
    """The .fem with its blocks' mesh size `size` [mm]; with `skin`, the iron's outer 2 mm and
    the winding are a separate block of size `skin` (FEMM grades by blocks)."""
    text = open(os.path.join(HERE, "eddy_cylinder_step.fem")).read()
    head, labels = text.split("[NumPoints]")[0], text.split("[NumBlockLabels] = 2")[1]
    if not skin:
        iron, winding = labels.strip().splitlines()
        iron, winding = iron.split("\t"), winding.split("\t")
        iron[3] = winding[3] = str(size)
        return text.split("[NumBlockLabels]")[0] + "[NumBlockLabels] = 2\n" + "\n".join(
            ["\t".join(iron), "\t".join(winding)]) + "\n"
    points = [(0, 0), (8, 0), (10, 0), (10.5, 0), (10.5, 2), (10, 2), (8, 2), (0, 2)]
    segments = [(k, (k + 1) % 8) for k in range(8)] + [(2, 5), (1, 6)]
    out = [head, f"[NumPoints] = {len(points)}\n"]
    out += [f"{x}\t{y}\t0\t0\n" for x, y in points]
    out += [f"[NumSegments] = {len(segments)}\n"] + [f"{a}\t{b}\t-1\t0\t0\t0\n" for a, b in segments]
    out += ["[NumArcSegments] = 0\n[NumHoles] = 0\n[NumBlockLabels] = 3\n",
            f"4\t1\t1\t{size}\t0\t0\t0\t1\t0\n", f"9\t1\t1\t{skin}\t0\t0\t0\t1\t0\n",
            f"10.25\t1\t2\t{skin}\t1\t0\t0\t10\t0\n"]
    return "".join(out)


def run_rheomag(exe, work, series, size, skin, tolerance):
    model = os.path.join(work, "cylinder.fem")
    open(model, "w").write(fem_model(size, skin))
    result = os.path.join(work, "rheomag.json")
    with open(result, "w") as out:
        cpu = timed([exe, "transient", model, "--current", "1", "--duration", str(DURATION),
                     "--tolerance", str(tolerance), "--json", "--quiet"], work, stdout=out)
    d = json.load(open(result))
    s = score(series, np.array(d["time"]), np.array(d["flux_linkage"]), d["final_flux_linkage"])
    return dict(tool="rheomag", mesh=size, skin=skin, order=2, method=f"adaptive, tolerance {tolerance:g}",
                dofs=d["dofs"], cpu=cpu, **s)


def run_getdp(work, series, size, skin, order, method, value):
    cpu = timed(["gmsh", os.path.join(work, "cylinder.geo"), "-2", "-format", "msh22", "-o",
                 os.path.join(work, "c.msh"), "-setnumber", "lc", str(size * 1e-3), "-setnumber",
                 "ls", str((skin or size) * 1e-3), "-v", "0"], work)
    for f in ("lambda.txt", "final.txt"):
        if os.path.exists(os.path.join(work, f)):
            os.remove(os.path.join(work, f))
    base = ["getdp", "cylinder.pro", "-msh", "c.msh", "-setnumber", "order", str(order),
            "-setnumber", "tmax", str(DURATION), "-v", "0"]
    if method == "gear2":
        args = ["-solve", "Adaptive", "-setnumber", "reltol", str(value), "-setnumber", "dt",
                str(DURATION * 1e-4)]
        name = f"Gear_2 adaptive, reltol {value:g}"
    else:
        theta, first_euler = {"cn": (0.5, 0), "cn+be": (0.5, 1), "be": (1, 0)}[method]
        args = ["-solve", "FixedSteps", "-setnumber", "dt", str(value), "-setnumber", "theta",
                str(theta), "-setnumber", "first_euler", str(first_euler)]
        name = {"cn": "Crank-Nicolson", "cn+be": "Crank-Nicolson, 1st step implicit Euler",
                "be": "implicit Euler"}[method] + f", dt {value:g} s"
    cpu += timed(base + args, work)
    g = np.vstack([[0.0, 0.0], np.loadtxt(os.path.join(work, "lambda.txt"))])
    final = float(np.loadtxt(os.path.join(work, "final.txt")).reshape(-1)[-1])
    pre = subprocess.run(base + ["-pre", "FixedSteps", "-v", "4"], cwd=work, text=True,
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT).stdout
    dofs = int(pre.split("System 1/2: ")[1].split()[0]) if "System 1/2: " in pre else None
    return dict(tool="getdp", mesh=size, skin=skin, order=order, method=name, dofs=dofs, cpu=cpu,
                **score(series, g[:, 0], g[:, 1], final))


MESHES = [(2, None), (1, None), (0.5, None), (0.25, None), (0.1, None), (2, 0.25), (1, 0.125),
          (0.5, 0.0625)]
RHEOMAG_TOLERANCES = [1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10]
GETDP_METHODS = [("cn+be", 1e-2), ("cn+be", 3e-3), ("cn+be", 1e-3), ("cn+be", 3e-4),
                 ("cn+be", 1e-4), ("cn+be", 3e-5), ("cn", 1e-3), ("cn", 1e-4), ("be", 1e-3),
                 ("be", 1e-4), ("gear2", 1e-3), ("gear2", 1e-4), ("gear2", 1e-5)]
BUDGETS = [0.1, 0.2, 0.5, 1, 2, 5, 10, 20, 30]


def table(rows, metric):
    lines = [f"| CPU budget | rheomag `{metric}` | GetDP `{metric}` | rheomag's run | GetDP's run |",
             "|---|---|---|---|---|"]
    for budget in BUDGETS:
        cells, runs = [], []
        for tool in ("rheomag", "getdp"):
            fit = [r for r in rows if r["tool"] == tool and r["cpu"] <= budget]
            best = min(fit, key=lambda r: r[metric]) if fit else None
            cells.append(f"{best[metric]:.1e}" if best else "none")
            runs.append("none within the budget" if not best else
                        f"P{best['order']}, {best['dofs']} dofs ({best['mesh']} mm"
                        + (f", {best['skin']} mm at the surface" if best["skin"] else "")
                        + f"), {best['method']}: {best['cpu']:.2f} s")
        lines.append(f"| {budget:g} s | {cells[0]} | {cells[1]} | {runs[0]} | {runs[1]} |")
    return "\n".join(lines)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--rheomag", default="build/app/rheomag")
    p.add_argument("--out", default="transient_vs_getdp.jsonl", help="one JSON line per run")
    p.add_argument("--quick", action="store_true", help="two meshes only")
    a = p.parse_args()
    exe = os.path.abspath(a.rheomag)
    for tool in ("getdp", "gmsh"):
        if not shutil.which(tool):
            sys.exit(f"transient_vs_getdp.py: '{tool}' not found (apt-get install getdp gmsh)")
    meshes = MESHES[:2] if a.quick else MESHES
    series = Series()
    rows = []
    with tempfile.TemporaryDirectory() as work, open(a.out, "w") as out:
        for f in ("cylinder.geo", "cylinder.pro"):
            shutil.copy(os.path.join(HERE, "getdp", f), work)
        jobs = [(run_rheomag, (exe, work, series, m, s, tol))
                for m, s in meshes for tol in RHEOMAG_TOLERANCES]
        jobs += [(run_getdp, (work, series, m, s, order, method, value))
                 for order in (2, 1) for m, s in meshes for method, value in GETDP_METHODS]
        for k, (fn, args) in enumerate(jobs):
            try:
                row = fn(*args)
            except (subprocess.CalledProcessError, subprocess.TimeoutExpired) as e:
                row = dict(tool=fn.__name__[4:], failed=type(e).__name__, args=[str(x) for x in args[3:]])
            rows.append(row)
            out.write(json.dumps(row) + "\n")
            out.flush()
            print(f"[{k + 1}/{len(jobs)}] {json.dumps(row)}", file=sys.stderr, flush=True)
    ok = [r for r in rows if "failed" not in r]
    print(f"Series: t63 = {series.rise(1 - np.exp(-1)) * 1e3:.4f} ms, "
          f"t90 = {series.rise(0.9) * 1e3:.4f} ms, lambda_inf = {series.final:.9g} Wb\n")
    print(table(ok, "rt") + "\n\n" + table(ok, "traj"))


if __name__ == "__main__":
    main()
