#!/usr/bin/python3
"""ocean-loadtest's exit table (load_run.hpp kExitTable) against real servers: no server is 3,
a server that refuses every client (it offers lite, they ask for mobile) is 4, --expect-ok-pct
met is 0, and a link that loses frames fails --expect-ok-pct 100 with 5. Each failure names
its reason on stderr."""
import argparse
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../client/loadtest"))
import local_server  # noqa: E402


def run(loadtest_bin, port, *extra):
    r = subprocess.run([loadtest_bin, "--server", f"127.0.0.1:{port}", "--clients", "2", "--ramp", "0",
                        "--duration", "2", "--quiet", *extra], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                       text=True, timeout=60)
    return r.returncode, r.stderr


def expect(name, got, want, stderr, needle):
    ok = got == want and (needle is None or needle in stderr)
    print(f"{'ok' if ok else 'FAIL'}: {name}: exit {got} (want {want}){'' if ok else ': ' + stderr[-500:]}")
    return ok


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--server-bin", required=True)
    parser.add_argument("--loadtest-bin", required=True)
    args = parser.parse_args()
    good = True
    code, err = run(args.loadtest_bin, local_server.free_port())
    good &= expect("no server", code, 3, err, "no client ever connected")
    for profiles, cases in (("lite", [("refused", ["--profile", "mobile"], 4, "profile_unavailable")]),
                            ("mobile", [("checks met", ["--profile", "mobile", "--expect-ok-pct", "50"], 0, None),
                                        ("checks failed", ["--profile", "mobile", "--link", "loss=60%",
                                                           "--expect-ok-pct", "100"], 5, "checks failed")])):
        port = local_server.free_port()
        server = local_server.start(args.server_bin, ["--listen", f"127.0.0.1:{port}", "--metrics-listen", "off",
                                                      "--size", "64", "--profiles", profiles, "--log-level", "warn"], port)
        try:
            for name, extra, want, needle in cases:
                code, err = run(args.loadtest_bin, port, *extra)
                good &= expect(name, code, want, err, needle)
        finally:
            local_server.stop(server)
    return 0 if good else 1


if __name__ == "__main__":
    sys.exit(main())
