#!/usr/bin/env python3
"""Python overhead of ornithopter.simulate against the C++ benchmark
BM_TetheredRfw10Cycles_MstTd_theta0 (tests/bench/bench_tethered.cpp): 10 cycles of the rigid RFW
in the tunnel at U = 6 m/s, f = 4 Hz, theta = 0, MST-TD, default tolerances. No pytest; prints
the median and the minimum of N calls (docs/python.md, docs/speed.md).

  PYTHONPATH=build/python python3 python/bench/time_simulate.py [N]
  build/tests/orni_bench --benchmark_filter=BM_TetheredRfw10Cycles_MstTd_theta0
"""
import os
import statistics
import sys
import time

import ornithopter

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


def timed(call, n):
    """Median and minimum wall time, median CPU time (Google Benchmark's "CPU" column) of a call."""
    call()  # warm-up (the vehicle's core model is built once, as in the benchmark)
    wall, cpu = [], []
    for _ in range(n):
        t0, c0 = time.perf_counter(), time.process_time()
        call()
        wall.append(time.perf_counter() - t0)
        cpu.append(time.process_time() - c0)
    return statistics.median(wall), min(wall), statistics.median(cpu)


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 200
    v = ornithopter.load_vehicle(os.path.join(ROOT, "studies", "vehicles", "rfw_tunnel.toml"))
    assert v["aero.model"] == "mst-td", v["aero.model"]
    args = dict(speed=6.0, freq=4.0, theta=0.0, tail=0.0, cycles=10)
    for histories in (False, True):
        med, best, cpu = timed(lambda: ornithopter.simulate(v, histories=histories, **args), n)
        print("simulate(histories=%-5s): wall median %.3f ms, min %.3f ms; CPU median %.3f ms"
              " (%d calls)" % (histories, med * 1e3, best * 1e3, cpu * 1e3, n))


if __name__ == "__main__":
    main()
