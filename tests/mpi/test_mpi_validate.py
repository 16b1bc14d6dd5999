#!/usr/bin/python3
"""`collide validate` under mpirun (docs/scaling.md), run by ctest as three tests:

  two_ranks_equal_serial  2 ranks give the same cases, outcomes and check values as a serial run
  resume_on_more_ranks    2 ranks killed part-way, resumed on 3, end equal to an uninterrupted
                          run, and no case finished before the kill runs again
  crash_on_rank_1         a case that aborts on rank 1 is recorded as crashed; the suite completes
  unshared_directories    each rank in its own directory (as on nodes without a shared file
                          system): rank 0's holds every record and, with --gather-hdf5, every
                          HDF5 file; the result equals the serial run

Each exits non-zero with a message when what it checks does not hold.
"""
import argparse
import glob
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time

ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1")


def fail(message):
    print("FAIL: " + message, file=sys.stderr)
    sys.exit(1)


def mpirun(args, ranks, command):
    return [args.mpiexec, "--oversubscribe", "-np", str(ranks)] + command


def run(command, expect_status=None):
    done = subprocess.run(command, env=ENV, capture_output=True, text=True, timeout=300)
    if expect_status is not None and done.returncode != expect_status:
        fail(f"{' '.join(command)} exited with {done.returncode}, expected {expect_status}\n"
             f"stdout:\n{done.stdout}\nstderr:\n{done.stderr}")
    return done


def summary(out):
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def verdicts(s):
    """What must not depend on how the cases were shared out: timings and hosts aside."""
    cases = {c["id"]: (c["status"], c["steps"], c["contacts"], c["disks"]) for c in s["cases"]}
    checks = {(c["subject"], c["check"]): (c["status"], c["value"]) for c in s["checks"]}
    return cases, checks


def expect_same(serial, parallel, what):
    a_cases, a_checks = verdicts(serial)
    b_cases, b_checks = verdicts(parallel)
    if a_cases != b_cases:
        fail(f"{what}: the cases differ from the serial run: "
             f"{sorted(set(a_cases.items()) ^ set(b_cases.items()))[:6]}")
    if a_checks != b_checks:
        diff = [k for k in a_checks.keys() | b_checks.keys() if a_checks.get(k) != b_checks.get(k)]
        fail(f"{what}: {len(diff)} checks differ from the serial run, e.g. "
             f"{[(k, a_checks.get(k), b_checks.get(k)) for k in sorted(diff)[:4]]}")


def two_ranks_equal_serial(args, tmp):
    serial, parallel = os.path.join(tmp, "serial"), os.path.join(tmp, "ranks2")
    run([args.collide, "validate", args.suite, "--out", serial], 0)
    run(mpirun(args, 2, [args.collide, "validate", args.suite, "--out", parallel]), 0)
    a, b = summary(serial), summary(parallel)
    expect_same(a, b, "2 ranks")
    if b["execution"].get("ranks") != "2" or a["execution"].get("ranks") != "1":
        fail(f"execution records: serial {a['execution']}, 2 ranks {b['execution']}")
    per_rank = [int(n) for n in b["execution"]["cases_per_rank"].split()]
    if sum(per_rank) != len(b["cases"]) or min(per_rank) == 0:
        fail(f"cases per rank {per_rank}: both ranks should have run cases, {len(b['cases'])} in all")
    if any("rank" not in c["provenance"] or "host" not in c["provenance"] for c in b["cases"]):
        fail("a case of the 2-rank run does not say on which rank and host it ran")
    # --plan under the launcher: rank 0 alone prints the plan, and nothing is written.
    planned = run(mpirun(args, 2, [args.collide, "validate", args.suite, "--plan", "--out",
                                   os.path.join(tmp, "plan")]), 0)
    if planned.stdout.count("cases planned") != 1 or f"{len(a['cases'])} cases planned" not in planned.stdout:
        fail(f"--plan on 2 ranks: expected one plan of {len(a['cases'])} cases, got:\n{planned.stdout}")
    if os.path.exists(os.path.join(tmp, "plan")):
        fail("--plan on 2 ranks wrote its output directory")


def finished_files(out):
    """Result records and logs of finished cases, with their modification times."""
    files = {}
    for record in glob.glob(os.path.join(out, "cases", "*.toml")):
        for path in (record, record[:-5] + ".log"):
            if os.path.exists(path):
                files[path] = os.stat(path).st_mtime_ns
    return files


def session_members(session):
    """Processes of a session: mpirun puts each rank in a process group of its own, but they
    all stay in the session of the mpirun that started them."""
    members = []
    for entry in os.listdir("/proc"):
        try:
            with open(f"/proc/{entry}/stat") as f:
                fields = f.read().rsplit(")", 1)[1].split()
        except (OSError, IndexError):
            continue  # not a process, or gone since the listing
        if fields[0] != "Z" and int(fields[3]) == session:  # state, ..., session id
            members.append(int(entry))
    return members


def kill_session(session):
    """SIGKILL to every process of the session, as a batch system ends a job, until none is left."""
    deadline = time.monotonic() + 30
    while (members := session_members(session)) and time.monotonic() < deadline:
        for pid in members:
            try:
                os.kill(pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
        time.sleep(0.05)
    if session_members(session):
        fail("processes of the killed run are still alive after 30 s")


def run_until_killed(command, out, after_records):
    """Starts `command` in its own session and kills all of it (SIGKILL, as at the end of an
    allocation) once `after_records` case records are in `out`."""
    process = subprocess.Popen(command, env=ENV, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                               start_new_session=True)
    deadline = time.monotonic() + 120
    while len(glob.glob(os.path.join(out, "cases", "*.toml"))) < after_records:
        if process.poll() is not None:
            fail(f"the run ended (status {process.returncode}) before {after_records} cases finished")
        if time.monotonic() > deadline:
            kill_session(process.pid)
            fail("no progress within 120 s")
        time.sleep(0.05)
    kill_session(process.pid)  # the ranks' cases die with their ranks too (PR_SET_PDEATHSIG)
    process.wait()


def resume_on_more_ranks(args, tmp):
    whole, broken = os.path.join(tmp, "whole"), os.path.join(tmp, "broken")
    run([args.driver, "slow", whole], 0)
    run_until_killed(mpirun(args, 2, [args.driver, "slow", broken]), broken, 3)
    kept = finished_files(broken)
    records = [p for p in kept if p.endswith(".toml")]
    total = len(summary(whole)["cases"])
    if not 3 <= len(records) < total:
        fail(f"{len(records)} of {total} cases finished before the kill; the test needs a part-way run")
    time.sleep(0.05)  # so that a file written again would show a later modification time
    run(mpirun(args, 3, [args.driver, "slow", broken, "--resume"]), 0)
    s = summary(broken)
    expect_same(summary(whole), s, "resumed on 3 ranks")
    rerun = [p for p, t in kept.items() if not os.path.exists(p) or os.stat(p).st_mtime_ns != t]
    if rerun:
        fail(f"cases finished before the kill ran again: {sorted(rerun)[:4]}")
    if s["cases_resumed"] != len(records) or s["cases_run"] != total - len(records):
        fail(f"resumed {s['cases_resumed']} and ran {s['cases_run']}, expected {len(records)} and "
             f"{total - len(records)}")
    if s["execution"].get("ranks") != "3":
        fail(f"execution record {s['execution']}")


def crash_on_rank_1(args, tmp):
    out = os.path.join(tmp, "crash")
    run(mpirun(args, 2, [args.driver, "crash", out, "--gather-hdf5"]), 1)  # 1: the run checks fail
    s = summary(out)
    if len(s["cases"]) != 8:
        fail(f"{len(s['cases'])} cases in the summary, expected 8")
    crashed = 0
    for c in s["cases"]:
        on_rank_1 = c["provenance"].get("rank") == "1"
        aborts = c["backend"] == "sleepy_a" and on_rank_1
        expected = "crashed" if aborts else "completed"
        if c["status"] != expected:
            fail(f"{c['id']} ran on rank {c['provenance'].get('rank')} and is {c['status']}, expected {expected}: "
                 f"{c['diagnostic']}")
        if aborts and "signal" not in c["diagnostic"]:
            fail(f"{c['id']}: the diagnostic does not name the signal: {c['diagnostic']}")
        if not aborts and c["provenance"].get("hdf5_host") != s["execution"]["hosts"].split()[0]:
            fail(f"{c['id']}: HDF5 not gathered to rank 0's host: {c['provenance']}")
        crashed += aborts
    if crashed == 0:
        fail("rank 1 ran no case of the aborting backend; the test proves nothing")
    runs = [c for c in s["checks"] if c["check"] == "run" and c["status"] == "fail"]
    if len(runs) != crashed:
        fail(f"{len(runs)} failed run checks for {crashed} crashed cases")


def unshared_directories(args, tmp):
    serial = os.path.join(tmp, "serial")
    run([args.collide, "validate", args.suite, "--out", serial], 0)
    homes = [os.path.join(tmp, f"node{k}") for k in range(2)]
    for home in homes:
        os.makedirs(home)
    command = [args.collide, "validate", args.suite, "--out", "results", "--gather-hdf5"]
    # MPMD form of mpirun: one rank per working directory, the same relative --out.
    run([args.mpiexec, "--oversubscribe", "-np", "1", "-wdir", homes[0]] + command +
        [":", "-np", "1", "-wdir", homes[1]] + command, 0)
    root, other = (os.path.join(h, "results") for h in homes)
    s = summary(root)
    expect_same(summary(serial), s, "2 ranks in separate directories")
    if os.path.exists(os.path.join(other, "summary.json")):
        fail("rank 1 wrote a summary; only rank 0 writes one")
    on_rank_1 = [c for c in s["cases"] if c["provenance"].get("rank") == "1"]
    if not on_rank_1:
        fail("rank 1 ran no case; the test proves nothing")
    for c in s["cases"]:
        for path in (c["result_file"], c["hdf5_file"]):
            if path and not os.path.exists(os.path.join(root, path)):
                fail(f"{c['id']} ran on rank {c['provenance'].get('rank')}: {path} is not in rank 0's directory")
    for c in on_rank_1:
        if not os.path.exists(os.path.join(other, c["hdf5_file"])):
            fail(f"{c['id']}: rank 1 did not write {c['hdf5_file']} in its own directory")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("test", choices=["two_ranks_equal_serial", "resume_on_more_ranks", "crash_on_rank_1",
                                           "unshared_directories"])
    parser.add_argument("--mpiexec", required=True)
    parser.add_argument("--collide", required=True)
    parser.add_argument("--driver", required=True)
    parser.add_argument("--suite", required=True)
    args = parser.parse_args()
    tmp = tempfile.mkdtemp(prefix="collide-mpi-")
    try:
        globals()[args.test](args, tmp)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    print(f"{args.test}: ok")


if __name__ == "__main__":
    main()
