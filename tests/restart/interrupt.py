#!/usr/bin/env python3
"""Interrupted runs resume where they stopped.

usage: interrupt.py AMFRAC CHECKPOINT_DIFF WORKDIR SCENE.prm [APPEND.prm]

1. The scene runs to the end once (the reference).
2. SIGTERM: a second run gets SIGTERM in the middle; it must finish its
   step, write a checkpoint, say how to resume and exit with status 75;
   `amfrac --resume` must then end in the reference's state (checkpoint_diff
   to relative 1e-12: in fact bit for bit).
3. SIGKILL: a third run, writing fields and a checkpoint after every step,
   is killed with SIGKILL four times at random moments (seeded, within 0.2
   to 0.6 of the uninterrupted run's wall time), each time
   resumed from its newest complete checkpoint (or started again if it had
   none). After every kill, every output file that exists must parse (VTU,
   PVTU and PVD as XML, CSV tables with whole rows) and the newest
   checkpoint must read back; the last resume (with a checkpoint folder cut
   off while being written planted beside the others) runs to the end and
   must end in the reference's state.
Also: resumed once more from the older of its two checkpoints, the SIGTERM
run deletes the later one and ends exactly again; a checkpoint with a
flipped byte is refused (exit status 1, a message
naming the file).
Exit status 0 on success; the first failure is printed.
"""
import glob
import os
import random
import shutil
import signal
import subprocess
import sys
import time
import xml.etree.ElementTree as ElementTree


def scene_text(scene, append, directory, extra):
    text = open(scene).read()
    if append:
        text += "\n" + open(append).read()
    return (text + "\nsubsection Output\n  set Directory = %s\nend\n"
            "subsection Checkpoint\n%send\n" % (directory, extra))


def fail(message):
    print("FAILED: " + message)
    sys.exit(1)


def start(amfrac, args, log, cwd):
    return subprocess.Popen([amfrac] + args, cwd=cwd, stdout=open(log, "w"),
                            stderr=subprocess.STDOUT)


def wait_for_step(log, step, process, limit=120):
    """Wait until the log reports step `step` (or the run ends)."""
    started = time.time()
    while time.time() - started < limit and process.poll() is None:
        with open(log) as f:
            if "  step %d " % step in f.read():
                return
        time.sleep(0.02)


def check_outputs(directory, diff):
    """Every output file parses; the newest checkpoint reads back."""
    for path in glob.glob(os.path.join(directory, "*")):
        name = os.path.basename(path)
        if ".tmp" in name or os.path.isdir(path):
            continue
        if name.endswith((".vtu", ".pvtu", ".pvd")):
            try:
                ElementTree.parse(path)
            except ElementTree.ParseError as error:
                fail("%s does not parse: %s" % (path, error))
        if name.endswith(".csv"):
            text = open(path).read()
            if text and not text.endswith("\n"):
                fail("%s ends in a partial row" % path)
            rows = text.splitlines()
            width = rows[0].count(",") if rows else 0
            if any(row.count(",") != width for row in rows):
                fail("%s has a row of another width" % path)
    checkpoints = os.path.join(directory, "checkpoints")
    if glob.glob(os.path.join(checkpoints, "checkpoint-*[0-9]")):
        status = subprocess.run([diff, checkpoints, checkpoints, "0"],
                                stdout=subprocess.DEVNULL).returncode
        if status != 0:
            fail("the newest checkpoint in %s does not read back" %
                 checkpoints)


def compare(diff, reference, directory, what):
    status = subprocess.run([diff, reference, directory, "1e-12"]).returncode
    if status != 0:
        fail(what + " does not end in the state of the uninterrupted run")


def main():
    amfrac, diff, workdir, scene = sys.argv[1:5]
    append = sys.argv[5] if len(sys.argv) > 5 else None
    shutil.rmtree(workdir, ignore_errors=True)
    os.makedirs(workdir)
    rare = "  set Every n steps = 1000000\n"
    for name, extra in (("whole", rare), ("term", rare),
                        ("kill", "  set Every n steps = 1\n")):
        with open(os.path.join(workdir, name + ".prm"), "w") as f:
            f.write(scene_text(scene, append, name, extra))

    log = os.path.join(workdir, "whole.log")
    started = time.time()
    if start(amfrac, ["whole.prm"], log, workdir).wait() != 0:
        fail("the uninterrupted run failed (see %s)" % log)
    duration = time.time() - started
    with open(log) as f:
        n_steps = f.read().count("  step ")
    reference = os.path.join(workdir, "whole", "checkpoints")

    # SIGTERM in the middle.
    log = os.path.join(workdir, "term.log")
    process = start(amfrac, ["term.prm"], log, workdir)
    wait_for_step(log, n_steps // 2, process)
    process.send_signal(signal.SIGTERM)
    status = process.wait()
    text = open(log).read()
    if status != 75 or "stopped by SIGTERM" not in text \
            or "amfrac --resume" not in text:
        fail("SIGTERM: exit status %d, expected 75 with a message on how "
             "to resume (see %s)" % (status, log))
    check_outputs(os.path.join(workdir, "term"), diff)
    log = os.path.join(workdir, "term-resumed.log")
    if start(amfrac, ["--resume", "term/checkpoints"], log,
             workdir).wait() != 0:
        fail("resuming after SIGTERM failed (see %s)" % log)
    compare(diff, reference, os.path.join(workdir, "term", "checkpoints"),
            "the run resumed after SIGTERM")

    # Resumed again from the older checkpoint (the one SIGTERM wrote): the
    # later one goes, and the run ends in the same state once more.
    older = sorted(glob.glob(os.path.join(workdir, "term", "checkpoints",
                                          "checkpoint-*[0-9]")))[0]
    log = os.path.join(workdir, "term-again.log")
    if start(amfrac, ["--resume", os.path.relpath(older, workdir)], log,
             workdir).wait() != 0 \
            or "removed 1 later checkpoint" not in open(log).read():
        fail("resuming from an older checkpoint (see %s)" % log)
    compare(diff, reference, os.path.join(workdir, "term", "checkpoints"),
            "the run resumed from an older checkpoint")

    # A damaged checkpoint is refused with a message naming it.
    damaged = os.path.join(workdir, "damaged")
    shutil.copytree(os.path.join(workdir, "term", "checkpoints"), damaged)
    newest = sorted(glob.glob(os.path.join(damaged, "checkpoint-*")))[-1]
    part = os.path.join(newest, "rank-0000.h5")
    data = bytearray(open(part, "rb").read())
    data[int(0.6 * len(data))] ^= 0xFF
    open(part, "wb").write(data)
    result = subprocess.run([amfrac, "--resume", "damaged"], cwd=workdir,
                            capture_output=True, text=True)
    if result.returncode != 1 or "cannot resume from checkpoint" not in \
            result.stderr or "rank-0000.h5" not in result.stderr:
        fail("a damaged checkpoint: exit status %d, stderr %r" %
             (result.returncode, result.stderr))
    print("damaged checkpoint refused: " + result.stderr.strip())

    # SIGKILL at random moments, each time resumed.
    rng = random.Random(9)
    for trial in range(4):
        log = os.path.join(workdir, "kill-%d.log" % trial)
        checkpoints = os.path.join(workdir, "kill", "checkpoints")
        resumable = glob.glob(os.path.join(checkpoints, "checkpoint-*[0-9]"))
        args = ["--resume", "kill/checkpoints"] if resumable else ["kill.prm"]
        process = start(amfrac, args, log, workdir)
        # Within the run's length whatever the build (debug is slower).
        time.sleep(rng.uniform(0.2, 0.6) * duration)
        if process.poll() is not None:
            break
        process.send_signal(signal.SIGKILL)
        process.wait()
        check_outputs(os.path.join(workdir, "kill"), diff)
        print("SIGKILL %d: killed after %s" % (
            trial, sorted(glob.glob(os.path.join(checkpoints, "*")))[-1:]))
    if not glob.glob(os.path.join(workdir, "kill", "checkpoints",
                                  "checkpoint-*[0-9]")):
        fail("no checkpoint survived the kills: the resume after SIGKILL "
             "was not tested")
    # A checkpoint cut off while it was written (the folder keeps its
    # .tmp name) is passed over.
    partial = os.path.join(workdir, "kill", "checkpoints",
                           "checkpoint-99999999.tmp")
    os.makedirs(partial, exist_ok=True)
    open(os.path.join(partial, "run.h5"), "wb").write(b"\x89HDF\r\n")
    log = os.path.join(workdir, "kill-final.log")
    if start(amfrac, ["--resume", "kill/checkpoints"], log,
             workdir).wait() != 0:
        fail("the last resume after SIGKILL failed (see %s)" % log)
    check_outputs(os.path.join(workdir, "kill"), diff)
    compare(diff, reference, os.path.join(workdir, "kill", "checkpoints"),
            "the run resumed after SIGKILL")
    print("interrupted runs resume exactly")


if __name__ == "__main__":
    main()
