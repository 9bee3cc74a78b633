#!/usr/bin/env python3
"""Recordings of MR rigs made by a simulator that shares no code with rheomag.

The diagnosis is proven on the bundled virtual rig, which is rheomag's own lumped code. This
script is a second, independent source: the same physics written again from the formulas (the
papers and shared/docs/recording-format.md), with its own integrator (classical Runge-Kutta on a
fine fixed step), its own conventions where a real rig would differ (the valve is the exact
Bingham slit flow with a pre-yield creep, not a Bingham line with a tanh switch; one recording has
a shear-thinning fluid; a play operator instead of a Duhem loop for the magnetic hysteresis; a
Coulomb friction switched by arctan over 0.5 mm/s; oil bulk modulus 1.6 GPa),
and a recorder with noise on every channel, held or instantaneous drive samples and channel skew.

Each recording is a CSV + TOML pair in the fixed recording format plus `truth.toml` (what was
concealed). Python 3 standard library only. Usage:

    scripts/independent-rig.py OUTDIR            # writes OUTDIR/<name>.csv/.toml, truth.toml
    scripts/independent-rig.py OUTDIR --list     # names and concealed effects only
    scripts/independent-rig.py OUTDIR --random 40 --seed 6 --diagnose build/app/rheomag
                                                 # 40 recordings drawn at random, scored
    scripts/independent-rig.py OUTDIR --diagnose build/app/rheomag   # and score its diagnoses
    LINE_VALVE=1 scripts/independent-rig.py ...  # the valve as a Bingham line (isolates its shape)

Scoring: "right" = every concealed effect named (eddy_currents and mr_response_time, one
first-order field lag in the lumped rig, count for each other); "false" = anything else named.
"""

FIELD_LAGS = {"eddy_currents", "mr_response_time"}


def score(concealed, named):
    """(every concealed effect named, the names that were not concealed)."""
    def same(a, b):
        return a == b or (a in FIELD_LAGS and b in FIELD_LAGS)

    right = all(any(same(c, n) for n in named) for c in concealed)
    false = [n for n in named if not any(same(c, n) for c in concealed)]
    lags = [n for n in named if n in FIELD_LAGS]
    if len(lags) > len([c for c in concealed if c in FIELD_LAGS]):
        false += lags[1:]  # two names for one lag
    return right, false


def diagnose_all(outdir, rheomag, cases):
    """Runs `rheomag diagnose --json` on each recording and prints the score table."""
    n_right = n_false = 0
    print("| recording | concealed | named (params) | baseline FIT | final FIT | unexplained | right | false |")
    print("|---|---|---|---|---|---|---|---|")
    for sc in cases:
        csv = os.path.join(outdir, sc.name + ".csv")
        run = subprocess.run([rheomag, "diagnose", csv, "--json", "--quiet"], capture_output=True, text=True)
        if run.returncode != 0:
            print("| %s | diagnose failed (exit %d): %s |" % (sc.name, run.returncode, run.stderr.strip()[:200]))
            n_false += 1
            continue
        d = json.loads(run.stdout)
        named = [m["name"] for m in d["missing_physics"]]
        right, false = score(sorted(sc.concealed), named)
        n_right += right
        n_false += bool(false)
        shown = "; ".join(
            "%s (%s)" % (m["name"], ", ".join("%s %.3g" % kv for kv in m["params"].items())) for m in d["missing_physics"]
        )
        truth = "; ".join(
            "%s (%s)" % (n, ", ".join("%s %.3g" % kv for kv in p.items())) for n, p in sorted(sc.concealed.items())
        )
        print("| %s | %s | %s | %.1f | %.1f | %.0f %% | %s | %s |" % (
            sc.name, truth or "none", shown or "none", d["baseline"]["fit_percent"], d["final"]["fit_percent"],
            100 * d["unexplained"]["share_of_residual"], "yes" if right else "**no**", ", ".join(false) or "-"))
    print("\n%d of %d named right; %d with a false finding" % (n_right, len(cases), n_false))

import argparse
import json
import math
import os
import random
import subprocess
import sys

P_ATM = 1.0e5  # Pa absolute: the chambers' air is at this pressure when no fluid is displaced
BULK_OIL = 1.6e9  # Pa: the truth's oil (the diagnosis assumes 1.5 GPa)
COPPER_ALPHA = 0.00393  # 1/K
LINE_VALVE = os.environ.get("LINE_VALVE") == "1"  # experiment: a Bingham line instead of the slit


def table(xs, ys, x):
    """Piecewise-linear interpolation, held constant beyond the ends."""
    if x <= xs[0]:
        return ys[0]
    for k in range(1, len(xs)):
        if x <= xs[k]:
            w = (x - xs[k - 1]) / (xs[k] - xs[k - 1])
            return ys[k - 1] + w * (ys[k] - ys[k - 1])
    return ys[-1]


def steps(levels, t0, period, rise):
    """A driver output that steps through `levels` every `period` s with a first-order rise."""

    def value(t):
        v = levels[0]
        for k in range(1, len(levels)):
            ts = t0 + k * period
            if t < ts:
                break
            v += (levels[k] - levels[k - 1]) * (1.0 - math.exp(-(t - ts) / rise))
        return v

    return value


class Valve:
    """Valve of a Bingham fluid in a slit, exact (Buckingham): no Bingham-line map, a plug that
    yields at p_y(I), flow growing as the plug shrinks, plus a slow creep below yield."""

    def __init__(self, currents, yields, resistance, creep_ratio=2000.0, flow_index=1.0, flow_ref=1e-5):
        self.currents, self.yields = currents, yields
        self.resistance = resistance  # Pa s/m3: the Newtonian slit (no field)
        self.creep = creep_ratio * resistance  # Pa s/m3: pre-yield creep
        self.flow_index, self.flow_ref = flow_index, flow_ref

    def flow(self, dp, i_field, guess=0.0):
        """Flow through the slit at pressure drop dp."""
        py = table(self.currents, self.yields, abs(i_field))
        q = dp / self.creep
        a = abs(dp)
        if LINE_VALVE and a > 1.5 * py:
            q += math.copysign((a - 1.5 * py) / self.resistance, dp)
        elif a > py and not LINE_VALVE:
            r = py / a
            shape = 1.0 - 1.5 * r + 0.5 * r * r * r
            newtonian = (a / (self.resistance * self.flow_ref)) ** (1.0 / self.flow_index) * self.flow_ref
            q += math.copysign(newtonian * shape, dp)
        return q

    def dp(self, q, i_field):
        """Pressure drop at flow q (the flow law inverted by safeguarded bisection/secant)."""
        py = table(self.currents, self.yields, abs(i_field))
        lo, hi = 0.0, abs(q) * self.creep
        x = abs(q)
        up = self.resistance * self.flow_ref * (x / self.flow_ref) ** self.flow_index + 1.5 * py + 1.0
        hi = min(hi, up) if hi > 0 else 0.0
        if hi <= 0.0:
            return 0.0
        for _ in range(80):
            mid = 0.5 * (lo + hi)
            if self.flow(mid, i_field) < x:
                lo = mid
            else:
                hi = mid
            if hi - lo <= 1e-9 * hi:
                break
        return math.copysign(0.5 * (lo + hi), q)


def chamber_pressure(stored, oil_volume, air_volume):
    """Absolute pressure of a chamber into which `stored` m3 of fluid has been pushed (isothermal air)."""
    a = oil_volume / BULK_OIL
    if air_volume <= 0.0:
        return P_ATM + stored / a
    b = air_volume - a * P_ATM - stored
    return (-b + math.sqrt(b * b + 4.0 * a * air_volume * P_ATM)) / (2.0 * a)


class Scenario:
    """One recording: rig, drives, concealed effects, recorder."""

    def __init__(self, name, kind, duration, rate, concealed, **kw):
        self.name, self.kind, self.duration, self.rate = name, kind, duration, rate
        self.concealed = concealed  # {effect name: {param: value}}
        self.kw = kw


def simulate(sc, rng):
    """Runs the truth on a fine step and returns (recorded columns dict, sidecar text)."""
    kw = sc.kw
    ts = 1.0 / sc.rate
    sub = kw.get("substeps", 40)
    dt = ts / sub
    held = kw.get("held", False)
    skew = kw.get("skew", 0.0)  # output read this many samples after the drives
    eff = sc.concealed

    motion = kw.get("motion")  # (x(t), v(t), a(t)) or None
    coil_in = kw.get("coil")  # function of t: current (A) or voltage (V)
    voltage_driven = kw.get("voltage_driven", False)

    def drive(t):
        return coil_in(math.floor(t / ts + 1e-9) * ts) if held else coil_in(t)

    hydraulic = sc.kind != "coil_bench"
    valve = kw.get("valve")
    area = kw.get("area", 0.0)
    oil = kw.get("chamber_volume", 0.0)
    air = eff.get("compressibility", {}).get("air_volume", 0.0) / 2.0
    inertance = eff.get("fluid_inertia", {}).get("inertance", 0.0)
    tau_e = eff.get("eddy_currents", {}).get("time_constant", 0.0)
    tau_mr = eff.get("mr_response_time", {}).get("time_constant", 0.0)
    play = eff.get("magnetic_hysteresis", {}).get("play_half_width", 0.0)
    coulomb = eff.get("friction", {}).get("coulomb_force", 0.0)
    resistance = kw.get("coil_resistance", 8.9)
    inductance = kw.get("inductance", 0.0) + eff.get("coil_inductance", {}).get("inductance", 0.0)
    heat = eff.get("coil_heating", {})
    gas = kw.get("gas_force", 0.0)

    # state: stored volume s, valve flow q (with inertance), coil current, temperature, two lags
    st = {"s": 0.0, "q": 0.0, "i": 0.0, "T": 20.0, "ie": 0.0, "im": 0.0}
    h_play = [0.0]

    def rhs(t, y, i_play):
        d = dict.fromkeys(y, 0.0)
        u = drive(t)
        if voltage_driven:
            r = resistance * (1.0 + COPPER_ALPHA * (y["T"] - 20.0))
            if inductance > 0:
                d["i"] = (u - r * y["i"]) / inductance
                i_coil = y["i"]
            else:
                i_coil = u / r
            if heat:
                c_th = heat["thermal_time_constant"] / heat["thermal_resistance"]
                d["T"] = (i_coil * i_coil * r - (y["T"] - 20.0) / heat["thermal_resistance"]) / c_th
        else:
            i_coil = u
        i_f = i_play if play > 0 else i_coil
        if tau_e > 0:
            d["ie"] = (i_f - y["ie"]) / tau_e
            i_f = y["ie"]
        if tau_mr > 0:
            d["im"] = (i_f - y["im"]) / tau_mr
            i_f = y["im"]
        out = {"i_coil": i_coil}
        if hydraulic:
            x, v, a = motion(t)
            p1 = chamber_pressure(y["s"], oil, air)
            p2 = chamber_pressure(-y["s"], oil, air)
            dp = p1 - p2
            if inertance > 0:
                d["q"] = (dp - valve.dp(y["q"], i_f)) / inertance
                q = y["q"]
            else:
                q = valve.flow(dp, i_f)
            d["s"] = area * v - q
            out["dp"] = dp
            out["force"] = area * dp + gas + coulomb * (2.0 / math.pi) * math.atan(v / 5e-4)
        return d, out

    def rk4(t, y, i_play):
        k1, out = rhs(t, y, i_play)
        y2 = {k: y[k] + 0.5 * dt * k1[k] for k in y}
        k2, _ = rhs(t + 0.5 * dt, y2, i_play)
        y3 = {k: y[k] + 0.5 * dt * k2[k] for k in y}
        k3, _ = rhs(t + 0.5 * dt, y3, i_play)
        y4 = {k: y[k] + dt * k3[k] for k in y}
        k4, _ = rhs(t + dt, y4, i_play)
        return {k: y[k] + dt / 6.0 * (k1[k] + 2 * k2[k] + 2 * k3[k] + k4[k]) for k in y}, out

    # settle the coil and lags at the first drive value
    u0 = drive(0.0)
    if voltage_driven:
        st["i"] = u0 / resistance
    st["ie"] = st["im"] = st["i"] if voltage_driven else u0
    h_play[0] = st["ie"]
    n_fine = int(round((sc.duration + 2 * ts) / dt)) + 1
    fine_t, fine_out = [], []
    y = st
    for j in range(n_fine):
        t = j * dt
        i_now = drive(t) if not voltage_driven else y["i"]
        if play > 0:
            h_play[0] = min(max(h_play[0], i_now - play), i_now + play)
        y_next, out = rk4(t, y, h_play[0])
        fine_t.append(t)
        fine_out.append(out)
        y = y_next

    def at(t, key):
        f = t / dt
        j = min(int(f), len(fine_t) - 2)
        w = f - j
        return (1 - w) * fine_out[j][key] + w * fine_out[j + 1][key]

    n = int(round(sc.duration * sc.rate))
    cols = {"t": [k * ts for k in range(n)]}
    out_key = {"pressure": "dp", "force": "force", "current": "i_coil"}[kw["output"]]
    cols[kw["output"]] = [at(k * ts + skew * ts, out_key) for k in range(n)]
    for name in kw["drives"]:
        if name in ("current", "voltage", "command"):
            cols[name] = [drive(k * ts) for k in range(n)]
        elif name == "velocity":
            cols[name] = [motion(k * ts)[1] for k in range(n)]
        elif name == "displacement":
            cols[name] = [motion(k * ts)[0] for k in range(n)]
    # recorder noise: a fraction of each channel's spread (a constant channel: of its level)
    for name, frac in [(kw["output"], kw.get("output_noise", 0.005))] + [
        (d, kw.get("drive_noise", 0.003)) for d in kw["drives"]
    ]:
        col = cols[name]
        mean = sum(col) / n
        spread = math.sqrt(sum((c - mean) ** 2 for c in col) / n) or abs(mean)
        cols[name] = [c + rng.gauss(0.0, frac * spread) for c in col]
    return cols


def sidecar(sc):
    """The TOML the user would write: what is known about the rig, maps a little off."""
    kw = sc.kw
    lines = ["# made by scripts/independent-rig.py (a simulator independent of rheomag)", "[recording]"]
    lines.append('description = "%s"' % sc.name)
    lines.append("drive = [%s]" % ", ".join('"%s"' % d for d in kw["drives"]))
    lines.append('output = "%s"' % kw["output"])
    lines += ["", "[rig]", 'kind = "%s"' % sc.kind]
    if sc.kind != "coil_bench":
        lines.append("piston_area = %.6g" % kw["area"])
        lines.append("chamber_volume = %.6g" % kw["chamber_volume"])
        if sc.kind == "damper":
            lines.append("gas_force = %.6g" % kw.get("gas_force", 0.0))
        v = kw["valve"]
        off_y, off_r = kw.get("map_error", (1.1, 0.9))
        lines += ["", "[valve]"]
        lines.append("yield_current = [%s]" % ", ".join("%.6g" % c for c in v.currents))
        # the Bingham line a user would fit to the slit's curve: intercept 1.5 p_y, slope R
        lines.append("yield_pressure = [%s]" % ", ".join("%.6g" % (1.5 * p * off_y) for p in v.yields))
        lines.append("viscous_resistance = %.6g" % (v.resistance * off_r))
    lines += ["", "[coil]", "resistance = %.6g" % (kw.get("coil_resistance", 8.9) * kw.get("resistance_error", 1.0))]
    if kw.get("inductance", 0.0) > 0:
        lines.append("inductance = %.6g" % kw["inductance"])
    return "\n".join(lines) + "\n"


def sine(amp_v, freq):
    """A velocity sine of amplitude amp_v at freq Hz, from rest at x = 0: (x(t), v(t), a(t))."""
    w = 2 * math.pi * freq
    return lambda t: (amp_v / w * (1 - math.cos(w * t)), amp_v * math.sin(w * t), amp_v * w * math.cos(w * t))


def constant(v):
    """A constant velocity v: (x(t), v(t), a(t))."""
    return lambda t: (v * t, v, 0.0)


def disp_sine(amp_x, freq):
    """A displacement sine of amplitude amp_x at freq Hz: (x(t), v(t), a(t))."""
    w = 2 * math.pi * freq
    return lambda t: (amp_x * math.sin(w * t), amp_x * w * math.cos(w * t), -amp_x * w * w * math.sin(w * t))


def scenarios():
    """The recordings: one or two concealed effects each, or none."""
    bypass = Valve([0.0, 0.25, 0.5, 0.75, 1.0], [0.0, 1.3e6, 2.4e6, 3.3e6, 3.9e6], 1.8e10)
    damper_valve = Valve([0.0, 0.25, 0.5, 0.75, 1.0], [0.07e6, 0.27e6, 0.53e6, 0.73e6, 0.87e6], 2.5e9)
    hb_valve = Valve([0.0, 0.25, 0.5, 0.75, 1.0], [0.0, 1.3e6, 2.4e6, 3.3e6, 3.9e6], 1.8e10, 2000.0, 0.85, 4e-6)
    a_bypass = 4.524e-4

    hyd = dict(drives=["velocity", "current"], output="pressure", area=a_bypass, chamber_volume=2e-5)
    dmp = dict(drives=["displacement", "velocity", "current"], output="force", area=7e-4,
               chamber_volume=1e-4, valve=damper_valve, gas_force=150.0)
    coil = dict(drives=["voltage"], output="current", voltage_driven=True)
    tri = [0.0, 0.3, 0.6, 1.0, 0.6, 0.3, 0.0, 0.45, 0.8, 0.45, 0.1, 0.6, 0.3]
    return [
        Scenario("bypass_air", "bypass_cylinder", 4.0, 1000.0, {"compressibility": {"air_volume": 4e-7}},
                 motion=sine(0.03, 1.0), coil=steps([0.0, 0.5, 1.0, 0.25], 0.0, 1.0, 2e-3), valve=bypass,
                 skew=0.3, **hyd),
        Scenario("pump_mr_lag", "constant_velocity_pump", 4.0, 500.0, {"mr_response_time": {"time_constant": 0.025}},
                 motion=constant(0.01), coil=steps([0.0, 0.5, 1.0, 0.25, 0.75, 0.0, 1.0, 0.5, 0.25, 0.0], 0.0, 0.4, 1e-3),
                 valve=bypass, held=True, skew=-0.5, **hyd),
        Scenario("damper_friction", "damper", 6.0, 500.0, {"friction": {"coulomb_force": 150.0}},
                 motion=disp_sine(0.012, 1.2), coil=steps([0.0, 0.5, 1.0, 0.25], 0.0, 1.5, 2e-3), **dmp),
        Scenario("coil_inductance", "coil_bench", 3.0, 1000.0, {"coil_inductance": {"inductance": 0.25}},
                 coil=steps([0.0, 9.0, 4.5, 0.0, 6.0, 2.0, 9.0, 0.0, 3.0, 7.0, 0.0, 5.0], 0.0, 0.25, 1e-4),
                 held=True, **coil),
        Scenario("coil_heating", "coil_bench", 60.0, 200.0,
                 {"coil_heating": {"thermal_resistance": 6.0, "thermal_time_constant": 30.0}},
                 coil=steps([12.0, 2.0] * 6, 0.0, 5.0, 1e-4), inductance=0.25, **coil),
        Scenario("damper_clean_voltage", "damper", 4.0, 500.0, {},
                 motion=disp_sine(0.01, 1.5), coil=steps([0.0, 2.5, 5.0, 1.0, 4.0, 0.0, 3.0, 5.0], 0.0, 0.5, 1e-4),
                 voltage_driven=True, coil_resistance=5.0, inductance=0.05, held=True, skew=0.5,
                 **dict(dmp, drives=["displacement", "velocity", "voltage"])),
        Scenario("bypass_inertia", "bypass_cylinder", 2.0, 2000.0, {"fluid_inertia": {"inertance": 1.0e9}},
                 motion=sine(0.05, 4.0), coil=steps([0.3, 0.6, 0.2, 0.5], 0.0, 0.5, 2e-3), valve=bypass, **hyd),
        Scenario("pump_hysteresis", "constant_velocity_pump", 8.0, 500.0,
                 {"magnetic_hysteresis": {"play_half_width": 0.06}},
                 motion=constant(0.01), coil=steps(tri, 0.0, 0.6, 2e-3), valve=bypass, **hyd),
        Scenario("damper_friction_eddy", "damper", 4.0, 1000.0,
                 {"friction": {"coulomb_force": 100.0}, "eddy_currents": {"time_constant": 0.02}},
                 motion=disp_sine(0.008, 2.0), coil=steps([0.0, 1.0, 0.3, 0.8, 0.0, 0.6, 1.0, 0.2], 0.0, 0.5, 1e-3),
                 held=True, skew=0.2, **dmp),
        Scenario("pump_clean_herschel_bulkley", "constant_velocity_pump", 4.0, 500.0, {},
                 motion=sine(0.012, 0.5), coil=steps([0.0, 0.5, 1.0, 0.25], 0.0, 1.0, 2e-3), valve=hb_valve,
                 map_error=(1.0, 1.0), **hyd),
    ]


RANDOM_CLASSES = ["none", "compressibility", "fluid_inertia", "mr_response_time", "eddy_currents", "friction",
                  "magnetic_hysteresis", "coil_inductance", "coil_heating", "pair"]
RANDOM_PAIRS = [("compressibility", "friction"), ("compressibility", "mr_response_time"),
                ("friction", "mr_response_time"), ("friction", "coil_inductance"),
                ("compressibility", "coil_inductance")]


def random_scenarios(seed, count):
    """`count` recordings drawn from `seed`: the classes of RANDOM_CLASSES in turn (two effects for
    "pair"), each effect's size, the rig's valve, the drive and the recorder (rate, held or
    instantaneous drive samples, channel skew, noise) at random within ranges a test rig shows."""
    rng = random.Random(seed)
    u = rng.uniform

    def valve(kind):
        ys, r = u(0.7, 1.3), u(0.7, 1.4)
        if kind == "damper":
            return Valve([0.0, 0.25, 0.5, 0.75, 1.0], [ys * p for p in (0.07e6, 0.27e6, 0.53e6, 0.73e6, 0.87e6)], r * 2.5e9)
        index = 0.85 if rng.random() < 0.3 else 1.0  # some fluids shear-thin
        return Valve([0.0, 0.25, 0.5, 0.75, 1.0], [ys * p for p in (0.0, 1.3e6, 2.4e6, 3.3e6, 3.9e6)], r * 1.8e10,
                     2000.0, index, 4e-6 if index < 1 else 1e-5)

    def levels(n, top):
        return [0.0] + [round(u(0.1, 1.0) * top, 3) for _ in range(n - 1)]

    def recorder(rates):
        return dict(sample_rate=rng.choice(rates), skew=u(-0.5, 0.5), held=rng.random() < 0.5,
                    output_noise=u(0.002, 0.008), drive_noise=u(0.001, 0.004))

    out = []
    for k in range(count):
        cls = RANDOM_CLASSES[k % len(RANDOM_CLASSES)]
        effects = list(rng.choice(RANDOM_PAIRS)) if cls == "pair" else ([] if cls == "none" else [cls])
        concealed = {}
        for e in effects:
            if e == "compressibility":
                concealed[e] = {"air_volume": u(1.5e-7, 8e-7) if cls != "pair" else u(1e-6, 4e-6)}
            elif e == "fluid_inertia":
                concealed[e] = {"inertance": u(4e8, 1.5e9)}
            elif e in ("mr_response_time", "eddy_currents"):
                concealed[e] = {"time_constant": u(0.01, 0.05)}
            elif e == "friction":
                concealed[e] = {"coulomb_force": u(60.0, 200.0)}
            elif e == "magnetic_hysteresis":
                concealed[e] = {"play_half_width": u(0.04, 0.1)}
            elif e == "coil_inductance":
                concealed[e] = {"inductance": u(0.1, 0.6)}
            elif e == "coil_heating":
                concealed[e] = {"thermal_resistance": u(3.0, 8.0), "thermal_time_constant": u(15.0, 40.0)}
        # the rig each class needs; "none" takes any of them
        rig = {"compressibility": "bypass", "fluid_inertia": "inertia", "mr_response_time": "pump",
               "eddy_currents": "pump", "friction": "damper", "magnetic_hysteresis": "hysteresis",
               "coil_inductance": "coil", "coil_heating": "heating", "pair": "damper_voltage"}.get(cls)
        if cls == "none":
            rig = rng.choice(["bypass", "pump", "damper", "damper_voltage", "coil"])
        if cls in ("mr_response_time", "eddy_currents") and rng.random() < 0.5:
            rig = "bypass"
        name = "random%d_%s" % (k, cls)
        period = u(0.4, 1.0)
        hyd = dict(drives=["velocity", "current"], output="pressure", area=4.524e-4, chamber_volume=2e-5)
        dmp = dict(drives=["displacement", "velocity", "current"], output="force", area=7e-4,
                   chamber_volume=1e-4, gas_force=u(50.0, 200.0))
        if rig == "bypass":
            sc = Scenario(name, "bypass_cylinder", 4.0, 0, concealed, motion=sine(u(0.02, 0.04), u(0.8, 1.5)),
                          coil=steps(levels(5, 1.0), 0.0, period, 2e-3), valve=valve("bypass"),
                          **dict(hyd, **recorder([500.0, 1000.0])))
        elif rig == "inertia":
            sc = Scenario(name, "bypass_cylinder", 2.0, 0, concealed, motion=sine(u(0.04, 0.06), u(3.0, 5.0)),
                          coil=steps(levels(4, 0.6), 0.0, 0.5, 2e-3), valve=valve("bypass"),
                          **dict(hyd, **dict(recorder([2000.0]), held=False)))
        elif rig == "pump":
            sc = Scenario(name, "constant_velocity_pump", 4.0, 0, concealed, motion=constant(u(0.006, 0.012)),
                          coil=steps(levels(10, 1.0), 0.0, 0.4, 1e-3), valve=valve("bypass"),
                          **dict(hyd, **recorder([500.0, 1000.0])))
        elif rig == "hysteresis":
            tri = [0.0, 0.3, 0.6, 1.0, 0.6, 0.3, 0.0, 0.45, 0.8, 0.45, 0.1, 0.6, 0.3]
            sc = Scenario(name, "constant_velocity_pump", 8.0, 0, concealed, motion=constant(u(0.006, 0.012)),
                          coil=steps(tri, 0.0, 0.6, 2e-3), valve=valve("bypass"), **dict(hyd, **recorder([500.0])))
        elif rig == "damper":
            sc = Scenario(name, "damper", 5.0, 0, concealed, motion=disp_sine(u(0.006, 0.015), u(1.0, 2.0)),
                          coil=steps(levels(6, 1.0), 0.0, period, 2e-3), valve=valve("damper"),
                          **dict(dmp, **recorder([500.0, 1000.0])))
        elif rig == "damper_voltage":
            sc = Scenario(name, "damper", 5.0, 0, concealed, motion=disp_sine(u(0.006, 0.015), u(1.0, 2.0)),
                          coil=steps(levels(8, 5.0), 0.0, period, 1e-4), voltage_driven=True, coil_resistance=5.0,
                          inductance=0.05, valve=valve("damper"),
                          **dict(dmp, drives=["displacement", "velocity", "voltage"], **recorder([500.0, 1000.0])))
        elif rig == "coil":
            sc = Scenario(name, "coil_bench", 3.0, 0, concealed, coil=steps(levels(12, 9.0), 0.0, 0.25, 1e-4),
                          drives=["voltage"], output="current", voltage_driven=True, **recorder([1000.0]))
        else:  # heating
            sc = Scenario(name, "coil_bench", 60.0, 0, concealed, coil=steps([12.0, 2.0] * 6, 0.0, 5.0, 1e-4),
                          inductance=0.25, drives=["voltage"], output="current", voltage_driven=True,
                          **recorder([200.0]))
        sc.rate = sc.kw.pop("sample_rate")
        out.append(sc)
    return out


def write_csv(path, cols):
    keys = ["t"] + [k for k in cols if k != "t"]
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(",".join(keys) + "\n")
        for k in range(len(cols["t"])):
            f.write(",".join("%.9g" % cols[c][k] for c in keys) + "\n")
    os.replace(tmp, path)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("outdir")
    ap.add_argument("--list", action="store_true", help="print the recordings and their concealed effects")
    ap.add_argument("--only", help="write only this recording")
    ap.add_argument("--seed", type=int, default=11)
    ap.add_argument("--diagnose", metavar="RHEOMAG", help="run this rheomag's diagnose on each and score it")
    ap.add_argument("--reuse", action="store_true", help="keep recordings already in OUTDIR (do not simulate again)")
    ap.add_argument("--random", type=int, metavar="N",
                    help="instead of the ten fixed recordings, N drawn at random from --seed (classes in turn)")
    args = ap.parse_args()
    os.makedirs(args.outdir, exist_ok=True)
    cases = random_scenarios(args.seed, args.random) if args.random else scenarios()
    truth = []
    for k, sc in enumerate(cases):
        names = sorted(sc.concealed) or ["none"]
        truth.append('[%s]\nconcealed = [%s]\n' % (sc.name, ", ".join('"%s"' % n for n in names)))
        for n, p in sc.concealed.items():
            truth.append("%s = { %s }\n" % (n, ", ".join("%s = %.6g" % kv for kv in p.items())))
        if args.list:
            print(sc.name, " ".join(names))
        if args.list or (args.only and args.only != sc.name):
            continue
        if args.reuse and os.path.exists(os.path.join(args.outdir, sc.name + ".csv")):
            continue
        rng = random.Random(args.seed * 1000 + k)
        cols = simulate(sc, rng)
        write_csv(os.path.join(args.outdir, sc.name + ".csv"), cols)
        with open(os.path.join(args.outdir, sc.name + ".toml"), "w") as f:
            f.write(sidecar(sc))
        print("wrote", sc.name, names, file=sys.stderr)
    with open(os.path.join(args.outdir, "truth.toml"), "w") as f:
        f.write("\n".join(truth))
    if args.diagnose:
        diagnose_all(args.outdir, args.diagnose, [sc for sc in cases if not args.only or sc.name == args.only])


if __name__ == "__main__":
    main()
