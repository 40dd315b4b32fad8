#!/usr/bin/env python3
"""Fuzz amfrac's input: mutate shipped scenes and check that every mutant
either runs or is rejected cleanly.

usage: fuzz_prm.py AMFRAC WORKDIR N SEED TIME_LIMIT SCENE.prm [SCENE.prm ...]
       fuzz_prm.py AMFRAC WORKDIR --replay MUTANT.prm [MUTANT.prm ...]

Each mutant is a scene with one to three mutations (an entry deleted, a
value replaced by a string, a negative, zero, huge, NaN or infinite number,
an emptied subsection, an unknown entry, a lost `end`, a truncated file),
with field output off so that accepted mutants stay cheap. A mutant fails
the check if amfrac
  - dies by a signal or aborts (an uncaught exception, a deal.II assertion
    in the debug build),
  - runs longer than TIME_LIMIT seconds (a hang),
  - exits non-zero without one `amfrac: error:` line naming a parameter
    (`parameter <...>`), a file position (`line N`) or a cause.
Failing mutants are kept in WORKDIR/failures/ to become regression tests
(tests/fuzz/regressions/, replayed by --replay). Exit status: the number of
failing mutants (0: all clean).
"""
import os
import random
import re
import shutil
import subprocess
import sys

NUMBER = re.compile(r"(?<![\w.])-?\d+(\.\d+)?([eE][-+]?\d+)?(?![\w.])")
CRASH_TEXT = ("terminate called", "Segmentation fault", "An error occurred in",
              "Aborted", "core dumped", "std::bad_alloc", "MPI_ABORT")
NO_FIELDS = "\nsubsection Output\n  set Field format = none\nend\n"


def mutate_line(lines, rng):
    """One mutation of a random `set` line, or of the structure."""
    sets = [i for i, l in enumerate(lines) if l.strip().startswith("set ")]
    kind = rng.choice(["delete", "string", "negative", "zero", "huge", "nan",
                       "inf", "empty_value", "unknown", "drop_end",
                       "empty_section", "swap"])
    if kind == "drop_end":
        ends = [i for i, l in enumerate(lines) if l.strip() == "end"]
        if ends:
            del lines[rng.choice(ends)]
        return kind
    if kind == "empty_section":
        starts = [i for i, l in enumerate(lines)
                  if l.strip().startswith("subsection ")]
        if starts:
            s = rng.choice(starts)
            depth, e = 0, s
            for e in range(s, len(lines)):
                t = lines[e].strip()
                depth += t.startswith("subsection ")
                depth -= t == "end"
                if depth == 0:
                    break
            del lines[s + 1:e]
        return kind
    if kind == "unknown":
        at = rng.choice(sets) if sets else 0
        lines.insert(at, "  set Frobnicate = 1")
        return kind
    if not sets:
        return "none"
    i = rng.choice(sets)
    name, _, value = lines[i].partition("=")
    if kind == "delete":
        del lines[i]
    elif kind == "string":
        lines[i] = name + "= abc"
    elif kind == "empty_value":
        lines[i] = name + "="
    elif kind == "swap" and len(sets) > 1:
        j = rng.choice(sets)
        other = lines[j].partition("=")[2]
        lines[i] = name + "=" + other
    else:
        replacement = {"negative": lambda v: "-" + v.lstrip("-"),
                       "zero": lambda v: "0", "huge": lambda v: "1e300",
                       "nan": lambda v: "nan", "inf": lambda v: "inf",
                       "swap": lambda v: v}[kind]
        numbers = list(NUMBER.finditer(value))
        if not numbers:
            lines[i] = name + "= " + replacement("1")
        else:
            m = rng.choice(numbers)
            value = value[:m.start()] + replacement(m.group()) + value[m.end():]
            lines[i] = name + "=" + value
    return kind


def make_mutant(text, rng):
    lines = text.split("\n")
    kinds = [mutate_line(lines, rng) for _ in range(rng.randint(1, 3))]
    mutant = "\n".join(lines) + NO_FIELDS
    if rng.random() < 0.08:
        mutant = mutant[:rng.randint(0, len(mutant))]
        kinds.append("truncate")
    return mutant, kinds


def check(amfrac, prm, workdir, time_limit):
    """None if clean, else the reason."""
    os.makedirs(workdir, exist_ok=True)
    try:
        run = subprocess.run([amfrac, prm], cwd=workdir, capture_output=True,
                             text=True, timeout=time_limit,
                             env=dict(os.environ, OMP_NUM_THREADS="1"))
    except subprocess.TimeoutExpired:
        return f"hang (over {time_limit} s)"
    err = run.stderr.strip()
    if run.returncode < 0:
        return f"killed by signal {-run.returncode}: {err[-300:]}"
    if any(t in err or t in run.stdout for t in CRASH_TEXT):
        return f"crash: {err[-300:]}"
    if run.returncode == 0:
        return None
    errors = [l for l in err.split("\n") if l.startswith("amfrac: error:")]
    if len(errors) != 1:
        return f"exit {run.returncode} without one 'amfrac: error:' line: {err[-300:]}"
    # Named parameter, file position, or (a run that failed) its cause.
    check.last_error = errors[0]
    return None


def main():
    amfrac, work = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(f"{work}/failures")
    if sys.argv[3] == "--replay":
        cases = [(os.path.abspath(p), open(p).read(), ["regression"])
                 for p in sys.argv[4:]]
        time_limit = 120
    else:
        n, seed, time_limit = int(sys.argv[3]), int(sys.argv[4]), float(sys.argv[5])
        scenes = [os.path.abspath(p) for p in sys.argv[6:]]
        rng = random.Random(seed)
        cases = []
        for k in range(n):
            scene = scenes[k % len(scenes)]
            mutant, kinds = make_mutant(open(scene).read(), rng)
            cases.append((scene, mutant, kinds))
    failures = 0
    counts = {"ran": 0, "parameter": 0, "position": 0, "cause": 0}
    for k, (source, text, kinds) in enumerate(cases):
        prm = f"{work}/mutant_{k:03d}.prm"
        with open(prm, "w") as f:
            f.write(text)
        check.last_error = None
        reason = check(amfrac, prm, f"{work}/run_{k:03d}", time_limit)
        if not reason:
            error = check.last_error
            kind = ("ran" if error is None else
                    "parameter" if "parameter <" in error else
                    "position" if re.search(r"[Ll]ine <?\d+", error) else "cause")
            counts[kind] += 1
            if kind == "cause":
                print(f"note: mutant {k:03d} ({', '.join(kinds)}): {error}")
        if reason:
            failures += 1
            shutil.copy(prm, f"{work}/failures/")
            print(f"FAIL mutant {k:03d} of {os.path.basename(source)} "
                  f"({', '.join(kinds)}): {reason}")
        shutil.rmtree(f"{work}/run_{k:03d}", ignore_errors=True)
    print(f"{len(cases)} mutants: {counts['ran']} ran, rejected naming a "
          f"parameter {counts['parameter']}, a file position "
          f"{counts['position']}, a cause {counts['cause']}; "
          f"{failures} failure(s)")
    sys.exit(min(failures, 100))


if __name__ == "__main__":
    main()
