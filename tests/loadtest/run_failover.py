#!/usr/bin/python3
"""--server A,B end to end: two real ocean-server replicas (one epoch, seed and scene, so either
one's frames pass the load test's sim check), ocean-loadtest given both as `--server A,B`, and
replica A SIGKILLed mid-run. The run must reconnect (to B: A is gone) and go on streaming - the
per-second CSV rows well after the kill still carry frames, none of them wrong.

With --viewer-bin, the same for ocean-viewer's --server A,B (headless): it must connect again,
render every frame it was asked for and exit 0, and the ticks it recorded (--record) must go on
well past the kill - frames only B can have sent."""
import argparse
import csv
import json
import os
import signal
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../client/loadtest"))
import local_server  # noqa: E402

DURATION_S = 7.0
KILL_AFTER_S = 2.0       # from the load test's start: A has streamed for a while
RECOVERED_AFTER_S = 2.0  # CSV rows this long after the kill must show B's stream


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--server-bin", required=True)
    parser.add_argument("--loadtest-bin")
    parser.add_argument("--viewer-bin")
    args = parser.parse_args()
    if bool(args.loadtest_bin) == bool(args.viewer_bin):
        parser.error("give one of --loadtest-bin and --viewer-bin")

    now_ms = int(time.time() * 1000)
    epoch_ms = now_ms - now_ms % local_server.DAY_MS  # the same for both: they are replicas
    servers, ports = [], []
    try:
        for _ in range(2):
            port = local_server.free_port()
            servers.append(local_server.start(args.server_bin, [
                "--listen", f"127.0.0.1:{port}", "--metrics-listen", "off", "--size", "64", "--patch", "64",
                "--seed", "7", "--epoch", str(epoch_ms), "--profiles", "mobile", "--log-level", "warn"], port))
            ports.append(port)
        if args.viewer_bin:
            return check_viewer(args.viewer_bin, ports, servers, epoch_ms)
        with tempfile.TemporaryDirectory() as work:
            csv_path = os.path.join(work, "series.csv")
            started = time.time()
            run = subprocess.Popen([args.loadtest_bin, "--server", f"127.0.0.1:{ports[0]},127.0.0.1:{ports[1]}",
                                    "--clients", "1", "--ramp", "0", "--duration", str(DURATION_S), "--profile", "mobile",
                                    "--json", "--quiet", "--csv", csv_path],
                                   stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
            time.sleep(KILL_AFTER_S)
            servers[0].send_signal(signal.SIGKILL)
            servers[0].wait()
            killed_at = time.time() - started
            out, err = run.communicate(timeout=DURATION_S + 20)
            if run.returncode != 0:
                print(f"ocean-loadtest exited {run.returncode}: {err}")
                return 1
            summary = json.loads(out.strip().splitlines()[-1])
            with open(csv_path, newline="") as f:
                rows = list(csv.DictReader(f))
    finally:
        for s in servers:
            if s.poll() is None:
                local_server.stop(s)

    failures = []
    if summary["reconnects"] < 1:
        failures.append(f"reconnects = {summary['reconnects']}: the client never left the killed server")
    if summary["frames_bad"] != 0:
        failures.append(f"frames_bad = {summary['frames_bad']}")
    # The load test's clock starts after ours, so its t_s is never ahead of the real time since start.
    # The last row is the run's end, whose frames are not judged yet: left out.
    after = [r for r in rows if killed_at + RECOVERED_AFTER_S <= float(r["t_s"]) < DURATION_S]
    if not after:
        failures.append(f"no CSV row {RECOVERED_AFTER_S} s after the kill at {killed_at:.1f} s: {rows}")
    for r in after:
        if float(r["kbps_mean"]) <= 0 or float(r["ok_pct"]) < 50 or int(r["bad"]) != 0:
            failures.append(f"after the kill at {killed_at:.1f} s, second {r['t_s']}: kbps {r['kbps_mean']}, "
                            f"ok {r['ok_pct']} %, bad {r['bad']} (B's stream should be flowing)")
    print(json.dumps({"killed_at_s": round(killed_at, 2), "reconnects": summary["reconnects"],
                      "rows_after": [(r["t_s"], r["kbps_mean"], r["ok_pct"]) for r in after]}))
    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


VIEWER_FRAMES = 1000      # about 6-9 s headless at 320x180 on llvmpipe here; longer on a busy machine
VIEWER_KILL_AFTER_S = 1.5
TICK_HZ = 30


def check_viewer(viewer_bin, ports, servers, epoch_ms):
    import numpy
    with tempfile.TemporaryDirectory() as work:
        record = os.path.join(work, "heights.npy")
        started = time.time()
        run = subprocess.Popen([viewer_bin, "--server", f"127.0.0.1:{ports[0]},127.0.0.1:{ports[1]}", "--headless",
                                "--frames", str(VIEWER_FRAMES), "--size", "320x180", "--profile", "mobile", "--json",
                                "--record", record], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        time.sleep(VIEWER_KILL_AFTER_S)
        servers[0].send_signal(signal.SIGKILL)
        servers[0].wait()
        kill_tick = (int(time.time() * 1000) - epoch_ms) * TICK_HZ // 1000
        out, err = run.communicate(timeout=120)
        elapsed = time.time() - started
        ticks = numpy.load(record[:-4] + ".ticks.npy") if os.path.exists(record[:-4] + ".ticks.npy") else numpy.array([])
    failures = []
    if run.returncode != 0:
        failures.append(f"ocean-viewer exited {run.returncode}: {err[-2000:]}")
    lines = [l for l in out.splitlines() if l.startswith("{")]
    summary = json.loads(lines[-1]) if lines else {}
    if summary.get("frames") != VIEWER_FRAMES:
        failures.append(f"rendered {summary.get('frames')} of {VIEWER_FRAMES} frames")
    if summary.get("connects", 0) < 2:
        failures.append(f"connects = {summary.get('connects')}: the viewer never left the killed server")
    after = int((ticks > kill_tick + TICK_HZ).sum()) if ticks.size else 0
    if elapsed > VIEWER_KILL_AFTER_S + 2.5 and after == 0:
        failures.append(f"no frame recorded 1 s after the kill (tick {kill_tick}); newest "
                        f"{int(ticks.max()) if ticks.size else None}")
    print(json.dumps({"killed_at_tick": kill_tick, "seconds": round(elapsed, 2), "connects": summary.get("connects"),
                      "frames_recorded": int(ticks.size), "recorded_1s_after_kill": after,
                      "last_close_reason": summary.get("last_close_reason")}))
    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
