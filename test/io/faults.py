#!/usr/bin/python3
"""Fault injection (ctest label faults). Each case damages a run on purpose and
checks what it leaves: a checkpoint that restarts, no *.tmp file once the
directory is used again, and a run.json whose status says what happened.

  term_checkpoint, term_snapshot   SIGTERM while checkpoint.h5.tmp / a snapshot's
                                   .tmp is being written: the write finishes, the
                                   run checkpoints and stops, status
                                   "signal-checkpoint", exit 0
  kill_checkpoint, kill_snapshot   SIGKILL during that write: the .tmp stays and
                                   run.json says "running" (the run had no chance
                                   to say more); the previous checkpoint is intact;
                                   a restart into the directory removes the .tmp,
                                   records previous_status "running", completes
  blocked_snapshot, blocked_checkpoint
                                   the temporary name is taken by a directory: the
                                   run stops naming it (exit 1), status "error",
                                   the previous checkpoint unchanged and restartable
  truncated, flipped               checkpoint.h5 cut in half / one byte flipped:
                                   the restart is refused naming the file (exit 1),
                                   status "error", the directory's snapshots kept,
                                   an intact copy restarts

  faults.py DMHS WORKDIR CASE
"""
import hashlib
import json
import os
import shutil
import signal
import subprocess
import sys
import time

import h5py

# big enough that a checkpoint (11 MB) or snapshot takes tens of ms to write
BOX = ["-scene", "box", "-box_nx", "300", "-box_ny", "300", "-dt", "2.5e-6", "-quiet"]
# small and fast, for the cases that need no timing
SMALL = ["-scene", "poiseuille", "-channel_width", "1e-3", "-channel_length", "5e-4", "-channel_nx", "10",
         "-channel_ny", "20", "-sph_h", "1.5e-4", "-body_force", "2e-4,0", "-dt", "2.5e-5", "-quiet"]


def fail(msg):
    print("FAIL:", msg)
    sys.exit(1)


def run_json(d):
    with open(os.path.join(d, "run.json")) as f:
        return json.load(f)


def tmp_files(d):
    return sorted(f for f in os.listdir(d) if f.endswith(".tmp") and os.path.isfile(os.path.join(d, f)))


def md5(path):
    with open(path, "rb") as f:
        return hashlib.md5(f.read()).hexdigest()


def attr(path, key):
    with h5py.File(path, "r") as f:
        return f.attrs[key][0]


def run(exe, args, log, expect):
    with open(log, "w") as out:
        rc = subprocess.call([exe] + args, stdout=out, stderr=subprocess.STDOUT)
    if rc != expect:
        print(open(log).read()[-2000:])
        fail(f"{' '.join(args[-6:])}: exit status {rc}, expected {expect}")
    return open(log).read()


def restarts(exe, opts, ckpt, outdir, log, steps=4):
    """The checkpoint continues for a few steps."""
    t, dt, step = attr(ckpt, "t"), attr(ckpt, "dt"), attr(ckpt, "step")
    run(exe, opts + ["-t_end", repr(t + steps * dt), "-restart", ckpt, "-output_dir", outdir], log, 0)
    if run_json(outdir)["status"] != "completed":
        fail(f"the restart from {ckpt} did not complete")
    print(f"  {ckpt} (step {step}) restarts")


def start_and_catch(exe, args, d, log, is_target, sig):
    """Starts a run, waits for a complete checkpoint, then for the write that
    is_target(names) recognises, and sends sig while it is under way.
    Returns the process and the checksum of the previous checkpoint."""
    out = open(log, "w")
    proc = subprocess.Popen([exe] + args, stdout=out, stderr=subprocess.STDOUT)
    ckpt = os.path.join(d, "checkpoint.h5")
    t0 = time.time()

    def wait(pred, what):
        while not pred():
            if proc.poll() is not None:
                fail(f"the run ended (status {proc.returncode}) before {what}")
            if time.time() - t0 > 120:
                proc.kill()
                fail(f"timed out waiting for {what}")

    wait(lambda: os.path.exists(ckpt), "a first checkpoint")
    # the write of the next one must not be the one in progress: wait for no .tmp first
    wait(lambda: not any(is_target(f) for f in (os.listdir(d) if os.path.isdir(d) else [])), "the end of a write")
    before = md5(ckpt)
    wait(lambda: any(is_target(f) for f in os.listdir(d)), "the write")
    proc.send_signal(sig)
    proc.wait()
    out.close()
    return proc, before


def signal_case(exe, w, target, sig):
    d = os.path.join(w, "run")
    if target == "checkpoint":
        args = BOX + ["-t_end", "1", "-output_snapshots", "false", "-checkpoint_interval", "1.25e-5"]
        is_target = lambda f: f == "checkpoint.h5.tmp"
    else:
        args = BOX + ["-t_end", "1", "-output_interval", "1.25e-5", "-checkpoint_interval", "5e-5"]
        is_target = lambda f: f.startswith("snap_") and f.endswith(".h5.tmp")
    for attempt in range(5):
        shutil.rmtree(w, ignore_errors=True)
        os.makedirs(w)
        proc, before = start_and_catch(exe, args + ["-output_dir", d], d, os.path.join(w, "run.log"), is_target, sig)
        caught = any(is_target(f) for f in tmp_files(d))
        if sig == signal.SIGTERM or caught:
            break
        print(f"  attempt {attempt + 1}: the write had finished when the signal arrived; again")
    else:
        fail("could not kill the run during the write")
    ckpt = os.path.join(d, "checkpoint.h5")
    status = run_json(d)["status"]
    print(f"  {signal.Signals(sig).name} during a {target} write: exit {proc.returncode}, run.json {status}, "
          f".tmp {tmp_files(d)}")
    if sig == signal.SIGTERM:
        log = open(os.path.join(w, "run.log")).read()
        if proc.returncode != 0 or "received SIGTERM" not in log:
            fail("SIGTERM: not a clean stop")
        if status != "signal-checkpoint" or tmp_files(d):
            fail("SIGTERM: run.json or .tmp files wrong")
        for f in sorted(os.listdir(d)):
            if f.endswith(".h5"):
                h5py.File(os.path.join(d, f), "r").close()  # every file complete
        shutil.copy(ckpt, os.path.join(w, "last.h5"))
        restarts(exe, BOX, os.path.join(w, "last.h5"), os.path.join(w, "again"), os.path.join(w, "again.log"))
    else:
        if proc.returncode != -signal.SIGKILL or status != "running":
            fail("SIGKILL: expected a killed run whose run.json still says running")
        if md5(ckpt) != before:
            fail("SIGKILL: the previous checkpoint changed")
        # continue in the same directory: the leftovers go, run.json tells the story
        restarts(exe, BOX, ckpt, d, os.path.join(w, "again.log"))
        j = run_json(d)
        if tmp_files(d) or j["previous_status"] != "running":
            fail(f"after the restart: .tmp {tmp_files(d)}, previous_status {j['previous_status']}")
        print(f"  restarted in place: no .tmp, run.json completed, previous_status {j['previous_status']}")


def blocked_case(exe, w, target):
    shutil.rmtree(w, ignore_errors=True)
    os.makedirs(w)
    d = os.path.join(w, "run")
    if target == "snapshot":
        os.makedirs(os.path.join(d, "snap_000003.h5.tmp"))  # output every 0.005 s: snapshot 3 at t = 0.015 s
        blocker = os.path.join(d, "snap_000003.h5.tmp")
        args = SMALL + ["-t_end", "0.05", "-output_interval", "0.005", "-checkpoint_interval", "0.01"]
        log = run(exe, args + ["-output_dir", d], os.path.join(w, "run.log"), 1)
        before = None
    else:
        run(exe, SMALL + ["-t_end", "0.01", "-output_dir", d], os.path.join(w, "first.log"), 0)
        before = md5(os.path.join(d, "checkpoint.h5"))
        blocker = os.path.join(d, "checkpoint.h5.tmp")
        os.makedirs(blocker)
        args = SMALL + ["-t_end", "0.05", "-checkpoint_interval", "0.005", "-restart", os.path.join(d, "checkpoint.h5")]
        log = run(exe, args + ["-output_dir", d], os.path.join(w, "run.log"), 1)
    line = next((l for l in log.splitlines() if l.startswith("dmhs: error")), "")
    print(f"  {line}")
    if blocker not in line:
        fail("the error does not name the blocked temporary name")
    j = run_json(d)
    if j["status"] != "error" or blocker not in j.get("message", ""):
        fail(f"run.json: status {j['status']}, message {j.get('message')}")
    if tmp_files(d):
        fail(f".tmp files left: {tmp_files(d)}")
    ckpt = os.path.join(d, "checkpoint.h5")
    if before and md5(ckpt) != before:
        fail("the previous checkpoint changed")
    os.rmdir(blocker)
    shutil.copy(ckpt, os.path.join(w, "last.h5"))
    restarts(exe, SMALL, os.path.join(w, "last.h5"), os.path.join(w, "again"), os.path.join(w, "again.log"))


def damaged_case(exe, w, how):
    shutil.rmtree(w, ignore_errors=True)
    os.makedirs(w)
    d = os.path.join(w, "run")
    run(exe, SMALL + ["-t_end", "0.01", "-output_dir", d], os.path.join(w, "first.log"), 0)
    ckpt = os.path.join(d, "checkpoint.h5")
    shutil.copy(ckpt, os.path.join(w, "intact.h5"))
    snaps = sorted(f for f in os.listdir(d) if f.startswith("snap_"))
    if how == "truncated":
        size = os.path.getsize(ckpt)
        with open(ckpt, "r+b") as f:
            f.truncate(size // 2)
        expect = ckpt
    else:
        with h5py.File(ckpt, "r") as f:
            at = f["particles/x"].id.get_offset() + 100
        with open(ckpt, "r+b") as f:
            f.seek(at)
            b = f.read(1)
            f.seek(at)
            f.write(bytes([b[0] ^ 0x01]))
        expect = "dataset /particles/x fails its checksum"
    log = run(exe, SMALL + ["-t_end", "0.02", "-restart", ckpt, "-output_dir", d], os.path.join(w, "run.log"), 1)
    line = next((l for l in log.splitlines() if l.startswith("dmhs: error")), "")
    print(f"  {line}")
    if ckpt not in line or expect not in line:
        fail(f"the error does not name {ckpt} / '{expect}'")
    j = run_json(d)
    if j["status"] != "error" or tmp_files(d):
        fail(f"run.json status {j['status']}, .tmp {tmp_files(d)}")
    if sorted(f for f in os.listdir(d) if f.startswith("snap_")) != snaps:
        fail("the refused restart removed snapshots")
    restarts(exe, SMALL, os.path.join(w, "intact.h5"), os.path.join(w, "again"), os.path.join(w, "again.log"))


def main(exe, w, case):
    print(f"fault: {case}")
    kind, _, target = case.partition("_")
    if kind in ("term", "kill"):
        signal_case(exe, w, target, signal.SIGTERM if kind == "term" else signal.SIGKILL)
    elif kind == "blocked":
        blocked_case(exe, w, target)
    elif case in ("truncated", "flipped"):
        damaged_case(exe, w, case)
    else:
        fail(f"unknown case {case}")
    print(f"fault {case}: OK")


if __name__ == "__main__":
    main(*sys.argv[1:4])
