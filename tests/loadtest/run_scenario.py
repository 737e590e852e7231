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
from cpu_wait import CpuWait  # noqa: E402

RAMP_S = 0.5
# The weather-front schedule's first change, from when its config is written: after the server's
# start, the ramp and the first frames (about 1 s on its link), so the clients see it streaming.
FIRST_CHANGE_S = 2.5

# Minimum frames_ok_pct per scenario for the size CMakeLists.txt runs it at, startup included.
# The impaired links lose frames by design; the floor is what the scenario should deliver with
# margin, see SCENARIOS.md. Measured figures are with today's codec.
OK_PCT_FLOOR = {
    # Measured with protocol 2 (modeled keys of a few bytes, lean frame records, adaptive jitter
    # buffer) at the CTest size on 2026-11-25; the floors leave room for a loaded CI machine.
    "mobile-3g": 95.0,      # measured 100
    "lossy-wifi": 95.0,     # measured 100
    "desktop-lan": 95.0,    # measured 97.6-100 (1 client, 6 s)
    "tcp-fallback": 95.0,   # measured 100
    "flaky-edge": 75.0,     # measured 99.1 (15 % loss, 128 kbit/s); 45-57 with protocol 1
    "edge-2g": 93.0,        # measured 99.6; 0.5 with protocol 1 (the key never fitted)
    "gprs": 93.0,           # measured 100; 22-25 with protocol 1
    "weather-front": 93.0,  # measured 100, 13 scene changes in 8 s and no re-key
    "old-epoch": 97.0,      # measured 100; 0 with protocol 1 (the 32-bit tick wrapped)
    # Vessels (2026-11-29, protocol 3): the wake lattice beside the sea, every frame checked with it.
    "harbour": 93.0,        # measured 97.2 (4 clients, 8 s on edge-2g's link)
    "regatta": 80.0,        # measured 92.1-96.5 (1 desktop-choppy client, 16 s: its first frame after 1.5-2.2 s,
                            # one to two epochs of 16 hulls' forcing computed on joining; 81-94 at 8 s)
    "man-overboard": 95.0,  # measured 99.6 (4 clients, 3 s)
    # WebSocket (2026-11-29): 1 % loss below TCP as retransmission delay that holds back what follows.
    "browser-3g": 95.0,     # measured 100 (20 clients, 20 s; 98.0 before the stream's buffer covered a retransmission)
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


SCENARIO_CHECKS = {"edge-2g": first_frame_checks, "gprs": first_frame_checks, "weather-front": weather_checks,
                   "harbour": first_frame_checks}


def check(scenario, summary, sanitized=False, starved=False):
    failures = []
    if summary["frames_bad"] != 0:
        failures.append(f"frames_bad = {summary['frames_bad']} (must be 0; max_err_m = {summary['max_err_m']})")
    if summary["frames_expected"] <= 0:
        failures.append("no frames were expected: the clients never got a Welcome")
    if sanitized:
        # A sanitizer build runs server and clients several times slower (desktop-lan: both at
        # 80-90 % of a core, 27-71 % on time): timing floors measure the instrumentation there, so
        # only correctness is asserted; CI's Release run asserts the floors.
        print(f"NOT ASSERTED under a sanitizer: frames_ok_pct = {summary['frames_ok_pct']:.2f} "
              f"(floor {OK_PCT_FLOOR[scenario]})", file=sys.stderr)
        return failures
    floor = OK_PCT_FLOOR[scenario]
    timing = []
    if summary["frames_ok_pct"] < floor:
        timing.append(f"frames_ok_pct = {summary['frames_ok_pct']:.2f} < {floor}")
    timing += SCENARIO_CHECKS.get(scenario, lambda s: [])(summary)
    if timing and starved:
        # Other programs held the cores (cpu_wait.py): a miss measures them, not the stream. Only a
        # miss is excused: a run that meets its floors on a busy machine still asserts them.
        print("NOT ASSERTED on a starved machine: " + "; ".join(timing), file=sys.stderr)
        return failures
    return failures + timing


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--server-bin", required=True)
    ap.add_argument("--loadtest-bin", required=True)
    ap.add_argument("--scenario", required=True)
    ap.add_argument("--clients", default="4")
    ap.add_argument("--duration", default="3")
    ap.add_argument("--sanitized", action="store_true", help="binaries built with a sanitizer: assert no timing")
    ap.add_argument("--profile", help="stream this profile instead of the scenario's (the server offers only it)")
    ap.add_argument("--sea", default="", help="more ocean-server flags for the scene, e.g. a storm's wind and choppiness")
    args = ap.parse_args()

    entry = local_server.scenario(args.loadtest_bin, args.scenario)
    with tempfile.TemporaryDirectory() as workdir:
        extra = local_server.scenario_server_args(entry, workdir, first_change_s=FIRST_CHANGE_S,
                                                  horizon_s=RAMP_S + float(args.duration) + 30)
        if args.profile:
            if "--profiles" in extra:
                at = extra.index("--profiles")
                del extra[at:at + 2]
            extra += ["--profiles", args.profile]
        extra += args.sea.split()
        port = local_server.free_port()
        client_port = local_server.client_port(entry["transport"], port, extra)
        try:
            # warn level: little output to buffer
            server = local_server.start(args.server_bin, ["--listen", f"127.0.0.1:{port}", "--metrics-listen", "off",
                                                          "--max-clients", str(max(64, 2 * int(args.clients))), "--log-level", "warn"] + extra, port)
        except RuntimeError as e:
            print(e, file=sys.stderr)
            return 1
        try:
            cmd = [args.loadtest_bin, "--server", f"127.0.0.1:{client_port}", "--scenario", args.scenario, "--clients",
                   args.clients, "--ramp", str(RAMP_S), "--duration", args.duration, "--json", "--quiet",
                   "--server-pid", str(server.pid)] + (["--profile", args.profile] if args.profile else [])
            print(" ".join(cmd), "# server:", " ".join(extra) or "defaults")
            wait = CpuWait([server.pid]).start()
            run = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
            wait.add(run.pid)
            try:
                stdout, stderr = run.communicate(timeout=float(args.duration) + 40)
            finally:
                wait.stop()
                if run.poll() is None:  # timed out: not left running behind the test
                    run.kill()
                    run.wait()
            sys.stderr.write(stderr)
            if server.poll() is not None:
                print(f"ocean-server died during the run (exit {server.returncode}):", server.stdout.read()[-2000:],
                      file=sys.stderr)
                return 1
            if run.returncode != 0:
                print(f"ocean-loadtest exited with {run.returncode}", file=sys.stderr)
                return 1
            summary = json.loads(stdout.strip().splitlines()[-1])
            print(json.dumps(summary))
            print(wait.describe(), file=sys.stderr)
            failures = check(args.scenario, summary, args.sanitized, wait.starved())
            for f in failures:
                print("FAIL:", f, file=sys.stderr)
            return 1 if failures else 0
        finally:
            local_server.stop(server)


if __name__ == "__main__":
    sys.exit(main())
