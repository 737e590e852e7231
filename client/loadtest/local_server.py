"""A throwaway ocean-server on a free loopback port, for the load-test scripts (find_capacity.py,
tests/loadtest/run_scenario.py)."""
import socket
import subprocess
import time


def free_port():
    """A port free for both TCP and UDP (the server uses one number for both)."""
    for _ in range(50):
        t = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
        u = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        try:
            t.bind(("127.0.0.1", 0))
            port = t.getsockname()[1]
            u.bind(("127.0.0.1", port))
            return port
        except OSError:
            continue
        finally:
            t.close()
            u.close()
    raise RuntimeError("no free loopback port")


def start(server_bin, args, port):
    """Starts ocean-server with `args` (its --listen must use `port`) and waits until it accepts
    connections; raises RuntimeError with its output if it exits or does not listen in 10 s."""
    server = subprocess.Popen([server_bin] + args, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    deadline = time.time() + 10
    while True:
        if server.poll() is not None:
            raise RuntimeError("ocean-server exited early: " + server.stdout.read()[-2000:])
        try:
            socket.create_connection(("127.0.0.1", port), timeout=0.2).close()
            return server
        except OSError:
            if time.time() > deadline:
                stop(server)
                raise RuntimeError("ocean-server did not start listening in 10 s")
            time.sleep(0.05)


def stop(server):
    server.terminate()
    try:
        server.wait(timeout=10)
    except subprocess.TimeoutExpired:
        server.kill()
