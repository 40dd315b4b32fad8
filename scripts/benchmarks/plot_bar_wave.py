"""Bar wave (prm/bar_wave.prm): end displacement against 1D wave theory and
the energy ledger. usage: /usr/bin/python3 plot_bar_wave.py history.csv out.png"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

E, RHO, L, P = 135300.0, 1.6e-9, 200.0, 10.0
C = (E / RHO) ** 0.5


def one_d(t):
    """End displacement of a fixed-free bar under a step end traction."""
    period = 4 * L / C
    s = t % period
    rise = P * C / E
    return rise * s if s <= 2 * L / C else rise * (period - s)


rows = list(csv.DictReader(open(sys.argv[1])))
t = [float(r["time"]) * 1e6 for r in rows]
fig, (a, b) = plt.subplots(1, 2, figsize=(10, 3.8))
a.plot(t, [-float(r["p0_ux"]) for r in rows], label="amfrac (explicit, Q2)")
a.plot(t, [one_d(x * 1e-6) for x in t], "--", label="1D wave theory")
a.set_xlabel("t [us]")
a.set_ylabel("end displacement [mm]")
a.legend()
for key, label in [("external_work", "external work"),
                   ("kinetic_energy", "kinetic"),
                   ("strain_energy", "strain"),
                   ("balance_error", "balance error")]:
    b.plot(t, [float(r[key]) for r in rows], label=label)
b.set_xlabel("t [us]")
b.set_ylabel("energy [N mm]")
b.legend()
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=110)
