"""The figure of tutorial step 17: force against indentation of
prm/hertz_indentation.prm against Hertz's law (left), and the benchmark's
errors against run time (right, from scripts/benchmarks/hertz_indentation.sh).
Runs with Debian's Python (matplotlib): /usr/bin/python3.
usage: plot_hertz.py history.csv benchmark.csv out.png"""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

E, NU, RADIUS = 70000.0, 0.3, 5.0
E_STAR = E / (1 - NU * NU)


def main(history, benchmark, out):
    rows = list(csv.DictReader(open(history)))
    d = [float(r["time"]) * 1e3 for r in rows]  # um
    force = [4 * float(r["contact_force"]) for r in rows]
    fine = [0.018 * i / 100 for i in range(101)]
    hertz = [4.0 / 3 * E_STAR * math.sqrt(RADIUS) * x**1.5 for x in fine]

    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
    left.plot([x * 1e3 for x in fine], hertz, "k-", label="Hertz")
    left.plot(d, force, "o", label="amfrac, Q1, 7 refinements")
    left.set_xlabel("indentation d [um]")
    left.set_ylabel("force F [N] (whole sphere)")
    left.legend()
    left.set_title("Rigid sphere R = 5 mm on aluminium")

    runs = list(csv.DictReader(open(benchmark)))
    for degree, marker in (("1", "o-"), ("2", "s-")):
        chosen = [r for r in runs if r["degree"] == degree and r["grading"] == "2"]
        time = [float(r["wall_s"]) for r in chosen]
        right.loglog(
            time,
            [abs(float(r["max_force_error"])) for r in chosen],
            marker,
            label="Q%s: max |F/F_Hertz - 1|" % degree,
        )
        right.loglog(
            time,
            [abs(float(r["peak_pressure_error"])) for r in chosen],
            marker,
            fillstyle="none",
            label="Q%s: |p_max/p0 - 1| at the end" % degree,
        )
    right.set_xlabel("wall time, one core [s]")
    right.set_ylabel("relative error")
    right.legend(fontsize=8)
    right.set_title("Refinements 5 to 8 of the contact zone")
    fig.tight_layout()
    fig.savefig(out, dpi=100)


if __name__ == "__main__":
    main(*sys.argv[1:4])
