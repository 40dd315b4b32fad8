"""Step 13's figure of the line impact that cracks a beam
(prm/impact_beam_2d.prm): the cylinder's velocity and mean contact force,
the crack faces inserted, and the energy ledger over time.
usage: /usr/bin/python3 plot_impact_beam.py HISTORY.csv OUT.png"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

rows = list(csv.DictReader(open(sys.argv[1])))


def column(name, scale=1.0):
    return [scale * float(r[name]) for r in rows]


t = column("time", 1e6)  # us
fig, (force, cracks, energy) = plt.subplots(1, 3, figsize=(14, 4))
force.plot(t, column("mean_contact_force"), label="mean contact force [N/mm]")
force.plot(t, column("impactor_velocity", 1e-2),
           label="cylinder velocity [0.1 m/s]")
force.set_xlabel("time [us]")
force.legend()
force.set_title("the cylinder")
cracks.plot(t, column("crack_faces"))
cracks.set_xlabel("time [us]")
cracks.set_ylabel("crack faces inserted")
cracks.set_title("matrix cracks in the bottom 90-degree plies")
for name, label in [("impactor_kinetic", "cylinder kinetic"),
                    ("strain_energy", "beam strain"),
                    ("kinetic_energy", "beam kinetic"),
                    ("dissipated_cracks", "dissipated by the cracks"),
                    ("balance_error", "balance error")]:
    energy.plot(t, column(name), label=label)
energy.set_xlabel("time [us]")
energy.set_ylabel("energy [N mm per mm of width]")
energy.legend()
energy.set_title("energy ledger")
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=100)
