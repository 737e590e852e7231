#!/usr/bin/python3
"""The fleet timeline's latency (issue 37): one etcd and three ocean-server replicas following it on
loopback; N weather changes through replica A with ocean-admin, one a second (the admin rate); for
each, the time from ocean-admin's start to the last replica's log line saying it applied the entry
(the moment it announces it to its viewers). Prints one JSON object: median, p99 and max in ms, and
how many changes were not answered 0 by ocean-admin.

Usage: tests/replica/timeline_latency.py --build build [--changes 100]
Not a CTest: 100 changes take about two minutes; test_timeline_fleet asserts the lead and prints
the latency of its eight."""
import argparse
import datetime
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "client", "loadtest"))
import local_server  # noqa: E402


def applied_at(log_path, index):
    """Unix seconds of the log line 'timeline entry <index> applied', or None."""
    needle = f"timeline entry {index} applied"
    with open(log_path) as log:
        for line in log:
            if needle in line:
                stamp = line[1:24]  # [YYYY-MM-DD HH:MM:SS.mmm]
                return datetime.datetime.strptime(stamp, "%Y-%m-%d %H:%M:%S.%f").timestamp()
    return None


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    ap.add_argument("--changes", type=int, default=100)
    args = ap.parse_args()
    server_bin = os.path.join(args.build, "server", "ocean-server")
    admin_bin = os.path.join(args.build, "tools", "admin", "ocean-admin")
    work = tempfile.mkdtemp(prefix="timeline-latency-")
    client_port, peer_port = local_server.free_port(), local_server.free_port()
    etcd = subprocess.Popen(["etcd", "--data-dir", os.path.join(work, "etcd"),
                             "--listen-client-urls", f"http://127.0.0.1:{client_port}",
                             "--advertise-client-urls", f"http://127.0.0.1:{client_port}",
                             "--listen-peer-urls", f"http://127.0.0.1:{peer_port}",
                             "--initial-advertise-peer-urls", f"http://127.0.0.1:{peer_port}",
                             "--initial-cluster", f"default=http://127.0.0.1:{peer_port}"],
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    servers, logs, ports = [], [], []
    try:
        time.sleep(2.0)
        token = os.path.join(work, "token")
        with open(token, "w") as f:
            f.write("latency-token\n")
        for i in range(3):
            port = local_server.free_port()
            logs.append(os.path.join(work, f"replica-{i}.log"))
            ports.append(port)
            servers.append(subprocess.Popen(
                [server_bin, "--listen", f"127.0.0.1:{port}", "--metrics-listen", "off", "--size", "64",
                 "--profiles", "mobile,lite", "--admin-token-file", token,
                 "--timeline", f"etcd://127.0.0.1:{client_port}/ocean/latency"],
                stdout=open(logs[-1], "w"), stderr=subprocess.STDOUT))
        time.sleep(3.0)
        latencies, failed = [], 0
        for n in range(1, args.changes + 1):
            start = time.time()
            run = subprocess.run([admin_bin, "--server", f"127.0.0.1:{ports[0]}", "--token-file", token,
                                  "--wind-speed", str(8 + n % 10)], capture_output=True, text=True)
            if run.returncode != 0:
                failed += 1
                print(f"change {n}: ocean-admin exited {run.returncode}: {run.stderr.strip()}", file=sys.stderr)
            stamps = []
            deadline = time.time() + 3.0
            while time.time() < deadline:
                stamps = [applied_at(log, n) for log in logs]  # an aborted change keeps its place too
                if all(stamps):
                    break
                time.sleep(0.02)
            if run.returncode == 0 and all(stamps):
                latencies.append(1000.0 * (max(stamps) - start))
            time.sleep(max(0.0, 1.05 - (time.time() - start)))
    finally:
        for s in servers:
            local_server.stop(s)
        etcd.terminate()
        etcd.wait()
        shutil.rmtree(work, ignore_errors=True)
    latencies.sort()
    if not latencies:
        print(json.dumps({"changes": args.changes, "answered": 0, "not_answered_0": failed}))
        return 1
    p99 = latencies[min(len(latencies) - 1, int(0.99 * len(latencies)))]
    print(json.dumps({"changes": args.changes, "measured": len(latencies), "not_answered_0": failed,
                      "median_ms": round(latencies[len(latencies) // 2], 1), "p99_ms": round(p99, 1),
                      "max_ms": round(latencies[-1], 1), "min_ms": round(latencies[0], 1)}))
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
