#!/usr/bin/python3
"""find_capacity.py end to end at a small N: one try against a real ocean-server, unpinned (CI
machines differ), must print a row whose server view was read from the server's /metrics and log
(a capacity figure that says nothing of the server would hide an overload), and the graceful
verdict must hold for a try that was not overloaded and fail for rows that were."""
import argparse
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "../../client/loadtest"))
import find_capacity  # noqa: E402
from cpu_wait import CpuWait  # noqa: E402


def fail(why):
    print("FAIL: " + why, file=sys.stderr)
    sys.exit(1)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    ap.add_argument("--sanitized", action="store_true",
                    help="a sanitizer build: its slow server may be loaded by 12 viewers, and may say so")
    args = ap.parse_args()
    script = os.path.join(HERE, "../../client/loadtest/find_capacity.py")
    wait = CpuWait(tree=True).start()
    run = subprocess.run(["/usr/bin/python3", script, "--build", args.build, "--at", "12", "--duration", "3",
                          "--join-rate", "20", "--server-cpus", "", "--loadtest-cpus", "", "--target", "0"],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=120)
    wait.stop()
    print(wait.describe())
    if run.returncode != 0:
        fail(f"find_capacity.py exited {run.returncode}: {run.stderr[-2000:]}")
    row = json.loads(run.stdout.strip().splitlines()[-1])
    server = row["server"]
    print(json.dumps(server))
    if row["clients_welcomed"] != 12 or row["frames_bad"] != 0:
        fail(f"12 clients, none wrong, expected: {row}")
    if server["keys_per_s"] <= 0 or server["key_bytes_per_s"] <= 0:
        fail("no keys read from /metrics: every client gets at least one")
    if not 0.0 < server["busy_ratio"] <= 1.0 or not 0.0 <= server["cpu_wait_ratio"] <= server["busy_ratio"]:
        fail("busy and CPU-wait shares not read from /metrics")
    # Under 32 sessions admission never refuses (AdmissionBudget's floor).
    if server["server_full_refusals"] != 0 or row["refusals"]:
        fail("12 clients refused")
    # Starved (other programs on the cores), the server is loaded by the wait it measures, and a
    # try may not be graceful; what must hold whatever the machine is the above and below.
    verdict = find_capacity.graceful(row, 0.0)
    timing = []
    if server["overload_warnings"] != 0 and not args.sanitized:
        timing.append(f"12 clients reported as an overload ({server['overload_warnings']} warnings)")
    if not all(verdict.values()):
        timing.append(f"an unloaded try is not graceful: {verdict}")
    if timing and wait.starved():
        print("NOT ASSERTED on a starved machine: " + "; ".join(timing))
    elif timing:
        fail("; ".join(timing))
    # The same row as if it had been overloaded: each failure must show in its own line.
    cases = {"admitted_ok": dict(row, admitted_ok_pct=50.0),
             "every_other_refused_with_reason": dict(row, not_welcomed={"no Welcome within idle_timeout_s": 3}),
             "no_tcp_fallbacks": dict(row, transport_fallbacks=1),
             "keys_within_budget": dict(row, server=dict(server, key_bytes_per_s=2 * server["key_budget_bytes_per_s"])),
             "overload_shown": dict(row, not_welcomed={"refused: server_full": 3})}
    for line, bad in cases.items():
        verdict = find_capacity.graceful(bad, 50.5 if line == "admitted_ok" else 0.0)
        if verdict[line]:
            fail(f"{line} holds for a row where it should not: {verdict}")
    print("find_capacity: row, server view and graceful verdict as expected")


if __name__ == "__main__":
    main()
