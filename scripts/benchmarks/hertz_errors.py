"""Errors of a Hertz indentation run (prm/hertz_indentation.prm) against
Hertz's law, from its history.csv: the largest |F / F_Hertz - 1| over the
steps, that of the first step, alpha / alpha_Hertz and C of the
least-squares fit d = alpha F^(2/3) + C F, and the relative error of the peak
pressure (Penalty times the deepest penetration) against Hertz's p0 at the
last step, as one comma-separated line. The same formulas as
tests/app/hertz_indentation.cc; the constants are those of the scene.
usage: hertz_errors.py history.csv"""
import csv
import math
import sys

E, NU, RADIUS, PENALTY = 70000.0, 0.3, 5.0, 1e8
E_STAR = E / (1 - NU * NU)


def hertz_force(d):
    return 4.0 / 3 * E_STAR * math.sqrt(RADIUS) * d**1.5


def hertz_peak(force):
    return (6 * force * E_STAR**2 / (math.pi**3 * RADIUS**2)) ** (1.0 / 3)


def main(path):
    rows = list(csv.DictReader(open(path)))
    d = [float(r["time"]) for r in rows]
    force = [4 * float(r["contact_force"]) for r in rows]  # quarter model
    errors = [f / hertz_force(x) - 1 for f, x in zip(force, d)]
    # Normal equations of the fit.
    a = [f ** (2.0 / 3) for f in force]
    aa = sum(x * x for x in a)
    ab = sum(x * f for x, f in zip(a, force))
    bb = sum(f * f for f in force)
    ad = sum(x * y for x, y in zip(a, d))
    bd = sum(f * y for f, y in zip(force, d))
    det = aa * bb - ab * ab
    alpha = (ad * bb - ab * bd) / det
    c = (aa * bd - ab * ad) / det
    alpha_hertz = (9.0 / (16 * E_STAR**2 * RADIUS)) ** (1.0 / 3)
    peak = PENALTY * float(rows[-1]["penetration"])
    print(
        "%.5f,%.5f,%.5f,%.4g,%.5f"
        % (
            max(errors, key=abs),
            errors[0],
            alpha / alpha_hertz,
            c,
            peak / hertz_peak(force[-1]) - 1,
        )
    )


if __name__ == "__main__":
    main(sys.argv[1])
