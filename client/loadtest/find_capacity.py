#!/usr/bin/python3
"""Finds the largest number of clients one ocean-server holds with >= --target % of frames on
time and none wrong, with the server and the load test pinned to different cores (taskset), so
that neither measures the other: a fresh server per try, N doubled from --start until a try
fails, then bisected to --resolution; then one try at twice the largest N shows what happens
beyond capacity. Prints one JSON object per try and a summary last (one line each).

  client/loadtest/find_capacity.py --build build --profile mobile --server-cpus 0 --loadtest-cpus 1
  client/loadtest/find_capacity.py --build build --at 1000      # one try: cost per datagram at 1000

Each try starts the clients at --join-rate per second, then measures --duration seconds. Passing
a try needs frames_ok_pct >= target and frames_bad == 0 (ground truth, every frame); with
--repeat R, the median of R runs must reach the target and none may have a bad frame. Per try:
server_us_per_datagram is the server's CPU time over the datagrams the clients received (on
loopback with no --link, what it sent); at twice capacity, admitted_ok_pct is the on-time share
of the clients that got a Welcome, refusals the reasons the others were given, and not_welcomed
how every client without a Welcome ended (a refusal's reason, still connecting, or a timeout).
Every try also reads the server's /metrics and log at its end ("server" in its row): server_full
refusals, the admission capacity, the network thread's busy and CPU-wait shares, loop lag, and key
bytes per second against the key budget. The try at twice capacity is "graceful" when the admitted
clients stay at the target with no bad frame, every client without a Welcome was refused with a
reason, no session fell back to TCP, keys kept within their budget, and a refusal shows in
/metrics and in a warn line.

--server-hog runs a busy loop on the server's CPUs during each try: the server gets about half of
its core, as beside a noisy neighbour or under a CPU limit, and twice its capacity comes within
reach of one load-test core (on one core alone the server holds more than one core of load test
can offer twice over).

--scenario NAME runs an ocean-loadtest scenario instead of --profile/--transport/--link, with the
server started as the scenario needs (tick rate, epoch, weather schedule: local_server.py)."""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
import urllib.request

import local_server


def pinned(cpus, argv):
    return ["taskset", "-c", cpus] + argv if cpus else argv


# SessionCoreOptions::key_bytes_per_s, and its burst of half a second.
KEY_BYTES_PER_S = 2_000_000.0


def run_once(args, clients):
    with tempfile.TemporaryDirectory() as workdir:
        hog = None
        if args.server_hog:
            hog = subprocess.Popen(pinned(args.server_cpus, ["sh", "-c", "while :; do :; done"]))
        try:
            return run_in(args, clients, workdir)
        finally:
            if hog:
                hog.kill()
                hog.wait()


def metric(text, name, labels=""):
    """The value of one series in Prometheus text, or 0 if absent."""
    m = re.search(r"^" + re.escape(name + labels) + r" (\S+)$", text, re.M)
    return float(m.group(1)) if m else 0.0


def server_view(metrics, log, elapsed_s):
    """What the operator sees at the end of a try."""
    return {"server_full_refusals": metric(metrics, "ocean_rejects_total", '{reason="server_full"}'),
            "admission_capacity": metric(metrics, "ocean_admission_capacity"),
            "busy_ratio": round(metric(metrics, "ocean_network_busy_ratio"), 3),
            "cpu_wait_ratio": round(metric(metrics, "ocean_network_cpu_wait_ratio"), 3),
            "loop_lag_p99_s": metric(metrics, "ocean_loop_lag_seconds", '{quantile="0.99"}'),
            "keys_per_s": round(metric(metrics, "ocean_keyframes_sent_total") / elapsed_s, 1),
            "key_bytes_per_s": round(metric(metrics, "ocean_key_bytes_sent_total") / elapsed_s),
            "key_budget_bytes_per_s": KEY_BYTES_PER_S, "elapsed_s": round(elapsed_s, 1),
            "overload_warnings": sum(1 for line in log.splitlines() if "overload:" in line)}


def stream_args(args, ramp, workdir):
    """(server flags, load-test flags, transport) for the stream under test."""
    if not args.scenario:
        return (["--profiles", args.profile],
                ["--profile", args.profile, "--transport", args.transport] + (["--link", args.link] if args.link else []),
                args.transport)
    entry = local_server.scenario(os.path.join(args.build, "client/loadtest/ocean-loadtest"), args.scenario)
    server_args = local_server.scenario_server_args(entry, workdir, first_change_s=ramp + 2.0,
                                                    horizon_s=ramp + args.duration + 60)
    if "--profiles" not in server_args:
        server_args += ["--profiles", entry["profile"]]
    return server_args, ["--scenario", args.scenario], entry["transport"]


def run_in(args, clients, workdir):
    loadtest = os.path.join(args.build, "client/loadtest/ocean-loadtest")
    ramp = max(0.5, clients / args.join_rate)
    port = local_server.free_port()
    metrics_port = local_server.free_port()
    server_args, loadtest_args, transport = stream_args(args, ramp, workdir)
    client_port = local_server.client_port(transport, port, server_args)
    # --max-clients above N: the limit under test is what the server can serve, not a setting
    # (admission control, where the server has it, decides by itself). Every client comes from
    # this host's one address: no per-address limits.
    # taskset execs the server, so the pid the load test reads /proc for is the server's.
    argv = pinned(args.server_cpus, [os.path.join(args.build, "server/ocean-server"), "--listen", f"127.0.0.1:{port}",
                                     "--metrics-listen", f"127.0.0.1:{metrics_port}", "--max-clients", str(clients + 16),
                                     "--max-connections-per-ip", "0", "--connect-rate-per-ip", "0", "--log-level", "warn"] + server_args + args.server_arg)
    server = local_server.start(argv[0], argv[1:], port, ready_url=f"http://127.0.0.1:{metrics_port}/readyz")
    started = time.monotonic()
    metrics = ""
    try:
        cmd = pinned(args.loadtest_cpus, [loadtest, "--server", f"127.0.0.1:{client_port}", "--clients", str(clients),
                                          "--ramp", f"{ramp:g}", "--duration", str(args.duration), "--threads",
                                          str(args.threads), "--json", "--quiet", "--server-pid", str(server.pid)]
                     + loadtest_args)
        run = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                             timeout=ramp + args.duration + 120)
        if run.returncode != 0:
            raise RuntimeError(f"ocean-loadtest exited {run.returncode}: {run.stderr[-2000:]}\n"
                               + local_server.exit_report(server))
        summary = json.loads(run.stdout.strip().splitlines()[-1])
        summary["alive"] = server.poll() is None
        if summary["alive"]:
            with urllib.request.urlopen(f"http://127.0.0.1:{metrics_port}/metrics", timeout=10) as r:
                metrics = r.read().decode()
        elapsed_s = time.monotonic() - started
    finally:
        local_server.stop(server)
    summary["server"] = server_view(metrics, server.stdout.read(), elapsed_s)
    return summary


def row_of(s, clients, target):
    datagrams = s["parts"]["udp_datagrams"]
    server_cpu_s = (s.get("server_cpu_pct") or 0.0) / 100.0 * s["duration_s"]
    ok = s["alive"] and s["frames_bad"] == 0 and s["frames_ok_pct"] >= target
    return {"clients": clients, "pass": ok, "frames_ok_pct": s["frames_ok_pct"],
            "admitted_ok_pct": s["frames_ok_pct_welcomed"], "frames_bad": s["frames_bad"],
            "clients_welcomed": s["clients_welcomed"], "clients_connected": s["clients_connected"],
            "refusals": s["refusals"], "not_welcomed": s["not_welcomed"], "transport_fallbacks": s["transport_fallbacks"], "keyframes": s["keyframes"],
            "server_cpu_pct": s.get("server_cpu_pct"), "loadtest_cpu_pct": s["loadtest_cpu_pct"],
            "server_us_per_datagram": round(server_cpu_s / datagrams * 1e6, 2) if datagrams else None,
            "datagrams_per_s": round(datagrams / s["duration_s"]) if s["duration_s"] else 0,
            "latency_p99_ms": s["latency_p99_ms"], "kbps_mean": s["kbps_mean"], "server_alive": s["alive"],
            "server": s["server"]}


def graceful(row, target):
    """Beyond capacity: the admitted keep their service, the rest are told why, and it shows."""
    server = row["server"]
    # The key bucket's burst (half a second of its rate) is the most it can run ahead of it.
    key_allowance = server["key_budget_bytes_per_s"] * (1.0 + 0.5 / server["elapsed_s"])
    return {"admitted_ok": row["admitted_ok_pct"] >= target and row["frames_bad"] == 0,
            "every_other_refused_with_reason": all(k.startswith("refused: ") for k in row["not_welcomed"]),
            "no_tcp_fallbacks": row["transport_fallbacks"] == 0,
            "keys_within_budget": server["key_bytes_per_s"] <= key_allowance,
            "overload_shown": (server["server_full_refusals"] > 0 and server["overload_warnings"] > 0)
                              or not row["not_welcomed"]}


def median_row(rows, target):
    """On a noisy machine one try decides nothing: the run with the median on-time share stands,
    and a bad frame in any run fails N."""
    row = dict(sorted(rows, key=lambda r: r["frames_ok_pct"])[len(rows) // 2])
    row["frames_bad"] = sum(r["frames_bad"] for r in rows)
    row["pass"] = row["server_alive"] and row["frames_bad"] == 0 and row["frames_ok_pct"] >= target
    return row


def search(args, attempt):
    """Doubling, then bisection: (largest passing N, first failing N)."""
    lo, hi = 0, None
    n = args.start
    while n <= args.max:
        if attempt(n)["pass"]:
            lo = n
            n *= 2
        else:
            hi = n
            break
    if hi is not None and lo > 0:
        while hi / lo - 1 > args.resolution:
            mid = (lo + hi) // 2
            if attempt(mid)["pass"]:
                lo = mid
            else:
                hi = mid
    return lo, hi


def parse_args():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default="build", help="build tree holding server/ and client/loadtest/")
    ap.add_argument("--profile", default="mobile")
    ap.add_argument("--transport", default="udp", help="udp, tcp, or ws (WebSocket clients, on the server's --ws-listen)")
    ap.add_argument("--link", default="", help="ocean-loadtest --link, e.g. rate=256kbit,delay=80ms,loss=5%%")
    ap.add_argument("--scenario", default="", help="an ocean-loadtest scenario (replaces --profile/--transport/--link)")
    ap.add_argument("--start", type=int, default=250)
    ap.add_argument("--max", type=int, default=8000)
    ap.add_argument("--at", type=int, default=0, help="run one try at this N instead of searching")
    ap.add_argument("--target", type=float, default=99.0, help="frames_ok_pct a try must reach")
    ap.add_argument("--duration", type=float, default=20.0, help="measured seconds after the ramp")
    ap.add_argument("--join-rate", type=float, default=100.0, help="clients started per second")
    ap.add_argument("--resolution", type=float, default=0.1,
                    help="stop bisecting when hi/lo - 1 is below this: a fraction in (0, 1), e.g. 0.1 for 10 %%")
    ap.add_argument("--server-cpus", default="0", help="taskset -c list for the server ('' = not pinned)")
    ap.add_argument("--loadtest-cpus", default="1", help="taskset -c list for the load test ('' = not pinned)")
    ap.add_argument("--threads", type=int, default=0, help="ocean-loadtest --threads (default: one per load-test CPU)")
    ap.add_argument("--repeat", type=int, default=1, help="runs per N; the median run decides (a noisy machine)")
    ap.add_argument("--no-double", action="store_true", help="skip the try at twice the largest passing N")
    ap.add_argument("--server-hog", action="store_true",
                    help="a busy loop on the server's CPUs during each try (about half a core left to the server)")
    ap.add_argument("--server-arg", action="append", default=[], help="extra ocean-server argument (repeatable)")
    args = ap.parse_args()
    if not 0.0 < args.resolution < 1.0:
        ap.error(f"--resolution {args.resolution:g}: must be a fraction in (0, 1) (hi/lo - 1), not a client count")
    if (args.server_cpus or args.loadtest_cpus) and not shutil.which("taskset"):
        ap.error("taskset (util-linux) is needed to pin the server and the load test; or pass --server-cpus '' --loadtest-cpus ''")
    if args.threads <= 0:
        args.threads = max(1, len(cpu_list(args.loadtest_cpus))) if args.loadtest_cpus else 1
    return args


def cpu_list(text):
    """taskset's list syntax: 1,3-5 -> [1, 3, 4, 5]."""
    cpus = []
    for part in filter(None, text.split(",")):
        first, _, last = part.partition("-")
        cpus += list(range(int(first), int(last or first) + 1))
    return cpus


def main():
    args = parse_args()
    tries = []

    def attempt(n):
        rows = [row_of(run_once(args, n), n, args.target) for _ in range(args.repeat)]
        for r in rows:
            print(json.dumps(r), flush=True)
        row = median_row(rows, args.target)
        if args.repeat > 1:
            print(json.dumps(dict(row, median_of=args.repeat)), flush=True)
        tries.append(row)
        return row

    if args.at:
        return 0 if attempt(args.at)["pass"] else 1
    lo, hi = search(args, attempt)
    best = next((t for t in tries if t["clients"] == lo), None)
    double = attempt(2 * lo) if lo > 0 and not args.no_double else None
    if double:
        double["graceful"] = graceful(double, args.target)
    print(json.dumps({"largest_passing_clients": lo, "first_failing_clients": hi, "target_pct": args.target,
                      "scenario": args.scenario, "profile": args.profile, "transport": args.transport, "link": args.link,
                      "duration_s": args.duration, "server_cpus": args.server_cpus, "loadtest_cpus": args.loadtest_cpus,
                      "loadtest_threads": args.threads, "server_hog": args.server_hog,
                      "server_cpu_pct_at_largest": best and best["server_cpu_pct"],
                      "server_us_per_datagram_at_largest": best and best["server_us_per_datagram"],
                      "at_double": double, "tries": len(tries)}))
    return 0 if lo > 0 else 1


if __name__ == "__main__":
    sys.exit(main())
