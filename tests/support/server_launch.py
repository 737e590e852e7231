"""Starting ocean-server for a script's test: it listens on a port the kernel picks, which its log
names; the script reads it from there."""

import os
import re
import subprocess
import sys
import time


def start_server(build, args, log_path, timeout_s=30):
    """ocean-server with `args` after --listen 127.0.0.1:0 --metrics-listen off; returns (process,
    TCP port). Exits the script with the log when the server does not report its port."""
    command = [os.path.join(build, "server", "ocean-server"), "--listen", "127.0.0.1:0", "--metrics-listen", "off"] + args
    log = open(log_path, "w")
    server = subprocess.Popen(command, stdout=log, stderr=subprocess.STDOUT)
    deadline = time.time() + timeout_s
    while time.time() < deadline:
        match = re.search(r"listening tcp=\S+:(\d+) ", open(log_path).read())
        if match:
            return server, int(match.group(1))
        if server.poll() is not None:
            break
        time.sleep(0.1)
    server.kill()
    sys.exit(f"FAIL: ocean-server did not report its port:\n{open(log_path).read()}")
