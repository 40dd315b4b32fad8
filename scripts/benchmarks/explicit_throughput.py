#!/usr/bin/python3
"""Explicit dynamics throughput: time per DoF per step and element updates
per second for a [0/90]s plate (Q1 or Q2, with or without cohesive
interfaces between all plies) on 1 or 2 ranks, median of three runs of
amfrac (Release). The step time is TimerOutput's "time steps" section
(bulk force, interfaces, loads and the vector updates; no output).

usage: explicit_throughput.py AMFRAC [MAX_US_PER_DOF]
With MAX_US_PER_DOF, exits non-zero if elastic Q1 on one rank is slower.
"""
import os
import re
import statistics
import subprocess
import sys
import tempfile

amfrac = sys.argv[1]
limit = float(sys.argv[2]) if len(sys.argv) > 2 else None

SCENE = """set Dimension = 3
subsection Geometry
  set Stacking sequence     = [0/90]s
  set Ply thickness         = 0.5
  set Length                = 60
  set Width                 = 60
  set Elements along length = {n}
  set Elements along width  = {n}
end
subsection Materials
  set Density = 1.6e-9
end
subsection Discretization
  set Finite element degree = {degree}
end
subsection Cohesive interfaces
  set Interfaces       = {interfaces}
  set Normal stiffness = 1e6
end
subsection Boundary conditions
  subsection x-
    set Type = displacement
  end
end
subsection Time
  set Time integration = explicit
  set Initial velocity = 0; 0; 1e3*sin(pi*x/120)
  set End time         = {end}
  set Number of steps  = 1
end
subsection Output
  set Directory    = {out}
  set Field format = none
end
"""


def run(n, degree, interfaces, ranks, steps=500):
    with tempfile.TemporaryDirectory() as work:
        prm = os.path.join(work, "plate.prm")
        # a first run finds the step; the timed runs take `steps` of it
        text = SCENE.format(n=n, degree=degree, interfaces=interfaces,
                            end=1e-9, out=os.path.join(work, "out"))
        open(prm, "w").write(text)
        launcher = (["mpirun", "--allow-run-as-root", "--oversubscribe",
                     "-np", str(ranks)] if ranks > 1 else [])
        log = subprocess.run(launcher + [amfrac, prm], capture_output=True,
                             text=True, check=True).stdout
        dt = float(re.search(r"stable time step (\S+) s", log).group(1))
        open(prm, "w").write(SCENE.format(
            n=n, degree=degree, interfaces=interfaces,
            end=0.8 * dt * steps, out=os.path.join(work, "out")))
        times = []
        for _ in range(3):
            log = subprocess.run(launcher + [amfrac, prm], capture_output=True,
                                 text=True, check=True).stdout
            times.append(float(re.search(
                r"\| time steps\s+\|\s+\d+ \|\s+\S+s\s+\d+ \|\s+(\S+)s", log)
                .group(1)))
            n_steps = int(re.search(r"(\d+) steps", log).group(1))
        dofs = int(re.search(r"(\d+) unknowns", log).group(1))
        cells = int(re.search(r"(\d+) cells", log).group(1))
        step = statistics.median(times) / n_steps
        return dofs, cells, step


print("| element | interfaces | ranks | DoFs | elements | us/step | "
      "us/DoF/step | element updates/s/core |")
print("|---|---|---|---|---|---|---|---|")
failed = False
for degree, n in ((1, 80), (2, 40)):
    for interfaces in ("", "all"):
        for ranks in (1, 2):
            dofs, cells, step = run(n, degree, interfaces, ranks)
            per_dof = step / dofs * 1e6
            print(f"| Q{degree} | {interfaces or 'none'} | {ranks} | {dofs} | "
                  f"{cells} | {step * 1e6:.0f} | {per_dof:.4f} | "
                  f"{cells / step / ranks:.3g} |", flush=True)
            if (limit is not None and degree == 1 and not interfaces
                    and ranks == 1 and per_dof > limit):
                failed = True
if failed:
    print(f"elastic Q1 on one rank slower than {limit} us per DoF per step")
sys.exit(1 if failed else 0)
