#!/usr/bin/env python3
"""Aero map and trims over a frequency range from Python (docs/python.md); run in CI as
the ctest python.example.

  PYTHONPATH=build/python python3 examples/python/aeromap_trim.py --out results/python_example

1. The rigid-wing tunnel model (studies/vehicles/rfw_tunnel.toml): mean lift FV and thrust FH over
   speed x pitch at 4 Hz (ornithopter.aeromap, 2 threads).
2. The magpie (studies/vehicles/efw_magpie.toml): level-flight trim at several flapping
   frequencies (ornithopter.trim); trim pitch, speed and hinge power against frequency.
Both figures go to OUT/aeromap.png and OUT/trim_vs_freq.png (matplotlib, Agg backend).
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import ornithopter  # noqa: E402

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


def aero_map_figure(out):
    rfw = ornithopter.load_vehicle(os.path.join(ROOT, "studies", "vehicles", "rfw_tunnel.toml"))
    speeds = np.array([4.0, 6.0, 8.0])   # m/s
    thetas = np.linspace(0.0, 20.0, 3)   # deg
    m = ornithopter.aeromap(rfw, speeds, [4.0], thetas, threads=2)
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for u in speeds:
        sel = m["speed_mps"] == u
        axes[0].plot(m["theta_deg"][sel], m["FV_mean_N"][sel], "o-", label="U = %g m/s" % u)
        axes[1].plot(m["theta_deg"][sel], m["FH_mean_N"][sel], "o-", label="U = %g m/s" % u)
    axes[0].set_ylabel("mean FV (N)")
    axes[1].set_ylabel("mean FH (N)")
    for a in axes:
        a.set_xlabel("theta (deg)")
        a.grid(True)
        a.legend()
    fig.suptitle("RFW aero map at 4 Hz (ornithopter %s)" % ornithopter.__version__)
    fig.savefig(os.path.join(out, "aeromap.png"), dpi=100)
    plt.close(fig)
    print("aero map: %d points, status %s" % (m["summary"]["points"], m["summary"]["status"]))


def trim_figure(out, freqs):
    magpie = ornithopter.load_vehicle(os.path.join(ROOT, "studies", "vehicles", "efw_magpie.toml"))
    rows = []
    for f in freqs:
        t = ornithopter.trim(magpie, freq=f)
        rows.append((f, t["converged"], t["theta_mean_deg"], t["speed_mps"],
                     t["mean"]["hinge_power_W"]))
        print("trim at %5.1f Hz: %-13s theta %6.2f deg, U %6.2f m/s" %
              (f, t["status"], t["theta_mean_deg"], t["speed_mps"]))
    r = np.array([(f, th, u, p) for f, ok, th, u, p in rows])
    ok = np.array([row[1] for row in rows], dtype=bool)
    fig, axes = plt.subplots(1, 3, figsize=(12, 4))
    for a, col, label in zip(axes, (1, 2, 3), ("theta (deg)", "U (m/s)", "hinge power (W)")):
        a.plot(r[:, 0], r[:, col], "-", color="0.6")
        a.plot(r[ok, 0], r[ok, col], "o", color="C0", label="converged")
        a.plot(r[~ok, 0], r[~ok, col], "o", mfc="none", color="C3", label="not converged")
        a.set_xlabel("flapping frequency (Hz)")
        a.set_ylabel(label)
        a.grid(True)
    axes[0].legend()
    fig.suptitle("Magpie level-flight trim against flapping frequency")
    fig.savefig(os.path.join(out, "trim_vs_freq.png"), dpi=100)
    plt.close(fig)
    return rows


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--out", default=os.path.join("results", "python_example"))
    p.add_argument("--freqs", default="11,12,13", help="trim frequencies, Hz, comma separated")
    args = p.parse_args()
    os.makedirs(args.out, exist_ok=True)
    aero_map_figure(args.out)
    rows = trim_figure(args.out, [float(x) for x in args.freqs.split(",")])
    for name in ("aeromap.png", "trim_vs_freq.png"):
        if os.path.getsize(os.path.join(args.out, name)) == 0:
            sys.exit("empty figure " + name)
    return 0 if any(ok for _, ok, *_ in rows) else 1


if __name__ == "__main__":
    sys.exit(main())
