#!/usr/bin/python3
"""Starts a real ocean-server on a free loopback port, as the scenario needs it (tick rate, epoch,
weather schedule, profiles: local_server.scenario_server_args), runs a small ocean-loadtest
scenario against it and checks the JSON summary: no frame beyond the error bound, at least the
scenario's on-time share (the floors leave room for the 2-core CI machine, not for bugs), and
the scenario's own checks (first frame on thin links, busiest second under weather changes)."""
import argparse
import json
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../client/loadtest"))
import local_server  # noqa: E402

RAMP_S = 0.5
# The weather-front schedule's first change, from when its config is written: after the server's
# start, the ramp and the first frames (about 1 s on its link), so the clients see it streaming.
FIRST_CHANGE_S = 2.5

# Minimum frames_ok_pct per scenario for the size CMakeLists.txt runs it at, startup included.
# The impaired links lose frames by design; the floor is what the scenario should deliver with
# margin, see SCENARIOS.md. Measured figures are with today's codec.
OK_PCT_FLOOR = {
    # Lowered from 95 when the clients began announcing the link's rate (256 kbit/s) in their Hello:
    # the server then paces the startup keyframe to that budget and skips about 3 deltas per
    # client behind it (a fixed startup cost, ~4 % of a 3 s run). Measured 95.0-96.6 in 8 runs
    # (100 before, with no bandwidth announced).
    "mobile-3g": 90.0,
    "lossy-wifi": 95.0,    # measured 100, 100; again 100 x3 with the shared bottleneck
    "desktop-lan": 95.0,   # measured 98.1, 98.8 (1 client, 6 s); again 97.6, 100, 98.1
    "tcp-fallback": 95.0,  # measured 100, 100; again 100 x3 announcing 1 Mbit/s, shared bottleneck
    # Lowered from 55 when the clients began announcing 128 kbit/s: with that budget the server
    # skips deltas behind every paced keyframe (15 % loss asks for several). Measured 45.6-57.4 in
    # 8 runs (71.3, 80.0 with the shared bottleneck and no bandwidth announced; 76.1, 68.9 before
    # either change).
    "flaky-edge": 40.0,
    # The thin-link targets: what a phone on 2G / GPRS should get once a keyframe fits the link
    # (3 % and 2 % loss, 50 ms jitter against a 100 ms interpolation delay). Today's codec fails.
    "edge-2g": 80.0,
    "gprs": 80.0,
    "weather-front": 90.0,  # 2 % loss at 256 kbit/s, as mobile-3g, while the weather changes
    "old-epoch": 95.0,      # a light link: only the 64-bit tick is under test
}

TTFF_MAX_S = 2.0  # thin links: every client's first frame within this of its connection attempt
PEAK_OVER_CALM_MAX = 2.0  # weather-front: busiest second (from the first frame on) over kbps_calm


def first_frame_checks(s):
    failures = []
    if s["clients_without_frame"] != 0:
        failures.append(f"clients_without_frame = {s['clients_without_frame']} (every client must get a frame)")
    if s["ttff_max_s"] is None or s["ttff_max_s"] > TTFF_MAX_S:
        failures.append(f"ttff_max_s = {s['ttff_max_s']} > {TTFF_MAX_S}")
    return failures


def weather_checks(s):
    # Calm = the same run's kbps_calm: the median client's median 100 ms rate from its first frame
    # on, the stream between bursts. Not kbps_mean: that includes the startup keyframe and every
    # re-key, so a weather change costing a keyframe every 2.5 s would raise its own yardstick
    # (today: peak 141 against a mean of 76, which would pass). The scenes count proves the
    # schedule reached the clients.
    failures = []
    if s["scenes"] < 3:
        failures.append(f"scenes = {s['scenes']}: the clients saw fewer than 2 weather changes")
    if s["kbps_peak_1s"] > PEAK_OVER_CALM_MAX * s["kbps_calm"]:
        failures.append(f"kbps_peak_1s = {s['kbps_peak_1s']:.1f} > {PEAK_OVER_CALM_MAX} x kbps_calm "
                        f"({s['kbps_calm']:.1f})")
    return failures


SCENARIO_CHECKS = {"edge-2g": first_frame_checks, "gprs": first_frame_checks, "weather-front": weather_checks}


def check(scenario, summary):
    failures = []
    if summary["frames_bad"] != 0:
        failures.append(f"frames_bad = {summary['frames_bad']} (must be 0; max_err_m = {summary['max_err_m']})")
    if summary["frames_expected"] <= 0:
        failures.append("no frames were expected: the clients never got a Welcome")
    floor = OK_PCT_FLOOR[scenario]
    if summary["frames_ok_pct"] < floor:
        failures.append(f"frames_ok_pct = {summary['frames_ok_pct']:.2f} < {floor}")
    return failures + SCENARIO_CHECKS.get(scenario, lambda s: [])(summary)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--server-bin", required=True)
    ap.add_argument("--loadtest-bin", required=True)
    ap.add_argument("--scenario", required=True)
    ap.add_argument("--clients", default="4")
    ap.add_argument("--duration", default="3")
    args = ap.parse_args()

    entry = local_server.scenario(args.loadtest_bin, args.scenario)
    with tempfile.TemporaryDirectory() as workdir:
        extra = local_server.scenario_server_args(entry, workdir, first_change_s=FIRST_CHANGE_S,
                                                  horizon_s=RAMP_S + float(args.duration) + 30)
        port = local_server.free_port()
        try:
            # warn level: little output to buffer
            server = local_server.start(args.server_bin, ["--listen", f"127.0.0.1:{port}", "--metrics-listen", "off",
                                                          "--max-clients", str(max(64, 2 * int(args.clients))), "--log-level", "warn"] + extra, port)
        except RuntimeError as e:
            print(e, file=sys.stderr)
            return 1
        try:
            cmd = [args.loadtest_bin, "--server", f"127.0.0.1:{port}", "--scenario", args.scenario, "--clients",
                   args.clients, "--ramp", str(RAMP_S), "--duration", args.duration, "--json", "--quiet",
                   "--server-pid", str(server.pid)]
            print(" ".join(cmd), "# server:", " ".join(extra) or "defaults")
            run = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                                 timeout=float(args.duration) + 40)
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
            failures = check(args.scenario, summary)
            for f in failures:
                print("FAIL:", f, file=sys.stderr)
            return 1 if failures else 0
        finally:
            local_server.stop(server)


if __name__ == "__main__":
    sys.exit(main())
