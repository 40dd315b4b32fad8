"""Step 17's figure of the cracking beam under a loading nose: the force
against the load point's travel and the crack faces, for the prescribed
nose (prm/indented_beam_2d.prm) and the prescribed deflection of the same
beam (prm/cracked_beam_2d.prm).
usage: /usr/bin/python3 plot_indented_beam.py NOSE_HISTORY.csv
       DEFLECTION_HISTORY.csv OUT.png"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

nose = list(csv.DictReader(open(sys.argv[1])))
deflection = list(csv.DictReader(open(sys.argv[2])))
# The nose touches the top face (y = 1) with its centre at y = 6.
nose_travel = [0] + [6 - float(r["impactor_position"]) for r in nose]
nose_force = [0] + [float(r["contact_force"]) for r in nose]
nose_cracks = [0] + [int(r["crack_faces"]) for r in nose]
# The prescribed deflection is 1.5 t at the top face's mid-span node.
travel = [0] + [1.5 * float(r["time"]) for r in deflection]
force = [0] + [-float(r["reaction_y+_y"]) for r in deflection]
cracks = [0] + [int(r["crack_faces"]) for r in deflection]

fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
left.plot(travel, force, "k-", lw=1, label="prescribed deflection")
left.plot(nose_travel, nose_force, "o", ms=3, label="loading nose, R = 5 mm")
left.set_xlabel("travel of the load point [mm]")
left.set_ylabel("force per width [N/mm]")
left.legend()
left.set_title("[90_2/0_4/90_2] beam, three-point bending")
right.step(travel, cracks, "k-", where="post", lw=1,
           label="prescribed deflection")
right.step(nose_travel, nose_cracks, where="post", label="loading nose")
right.set_xlabel("travel of the load point [mm]")
right.set_ylabel("crack faces in plies 0 and 1")
right.legend()
fig.tight_layout()
fig.savefig(sys.argv[3], dpi=120)
