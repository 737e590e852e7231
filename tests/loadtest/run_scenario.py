#!/usr/bin/python3
"""Starts a real ocean-server on a free loopback port, runs a small ocean-loadtest scenario
against it and checks the JSON summary: no frame beyond the error bound, and at least the
scenario's on-time share (the floors leave room for the 2-core CI machine, not for bugs)."""
import argparse
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../client/loadtest"))
import local_server  # noqa: E402

# Minimum frames_ok_pct per scenario for 4 clients over 3 s (desktop-lan: 1 client, 6 s), startup
# included. The impaired links lose frames by design; the floor is what the scenario should deliver with margin, see SCENARIOS.md.
OK_PCT_FLOOR = {
    # Lowered from 95 when the clients began announcing the link's rate (256 kbit/s) in their Hello:
    # the server then paces the startup keyframe to that budget and skips about 3 deltas per
    # client behind it (a fixed startup cost, ~4 % of a 3 s run). Measured 95.0, 95.4, 95.8, 96.2,
    # 96.6 (100 before, with no bandwidth announced).
    "mobile-3g": 90.0,
    "lossy-wifi": 95.0,    # measured 100, 100
    "desktop-lan": 95.0,   # measured 98.1, 98.8 (1 client, 6 s)
    "tcp-fallback": 95.0,  # measured 100, 100
    # Lowered from 55 when the clients began announcing 128 kbit/s: with that budget the server
    # skips deltas behind every paced keyframe (15 % loss asks for several). Measured 54.4, 54.1,
    # 54.1, 45.6, 45.8 (71.3, 80.0 with the shared bottleneck and no bandwidth announced; 76.1,
    # 68.9 before either change).
    "flaky-edge": 40.0,
}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--server-bin", required=True)
    ap.add_argument("--loadtest-bin", required=True)
    ap.add_argument("--scenario", required=True)
    ap.add_argument("--clients", default="4")
    ap.add_argument("--duration", default="3")
    args = ap.parse_args()

    port = local_server.free_port()
    try:
        # warn level: little output to buffer
        server = local_server.start(args.server_bin, ["--listen", f"127.0.0.1:{port}", "--metrics-listen", "off",
                                                      "--max-clients", "64", "--log-level", "warn"], port)
    except RuntimeError as e:
        print(e, file=sys.stderr)
        return 1
    try:
        cmd = [args.loadtest_bin, "--server", f"127.0.0.1:{port}", "--scenario", args.scenario, "--clients",
               args.clients, "--ramp", "0.5", "--duration", args.duration, "--json", "--quiet",
               "--server-pid", str(server.pid)]
        print(" ".join(cmd))
        run = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=40)
        sys.stderr.write(run.stderr)
        if server.poll() is not None:
            print(f"ocean-server died during the run (exit {server.returncode}):", server.stdout.read()[-2000:],
                  file=sys.stderr)
            return 1
        if run.returncode != 0:
            print(f"ocean-loadtest exited with {run.returncode}", file=sys.stderr)
            return 1
        summary = json.loads(run.stdout.strip().splitlines()[-1])
        print(json.dumps(summary))
        floor = OK_PCT_FLOOR[args.scenario]
        failures = []
        if summary["frames_bad"] != 0:
            failures.append(f"frames_bad = {summary['frames_bad']} (must be 0; max_err_m = {summary['max_err_m']})")
        if summary["frames_expected"] <= 0:
            failures.append("no frames were expected: the clients never got a Welcome")
        if summary["frames_ok_pct"] < floor:
            failures.append(f"frames_ok_pct = {summary['frames_ok_pct']:.2f} < {floor}")
        for f in failures:
            print("FAIL:", f, file=sys.stderr)
        return 1 if failures else 0
    finally:
        local_server.stop(server)


if __name__ == "__main__":
    sys.exit(main())
