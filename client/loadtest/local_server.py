"""A throwaway ocean-server on a free loopback port, for the load-test scripts (find_capacity.py,
tests/loadtest/run_scenario.py), started as a scenario needs it.

Some scenarios need the server run a certain way (ocean-loadtest cannot configure a server it
did not start): a tick rate, an epoch some days back, a weather schedule, extra profiles. The
scenario table in client/loadtest/scenario.cpp says which (`ocean-loadtest --list-scenarios
--json`, "server"); scenario_server_args() turns that into ocean-server flags and, for a
schedule, a TOML config file. The schedule generators live here, and only here (SCHEDULES).

Ticks in a [[schedule]] are absolute: tick = (now_ms - epoch_ms) * tick_rate // 1000. So that
the generator knows both, a scenario with any of tick rate, epoch or schedule always gets
--tick-rate (its own, else 30, the server's default) and --epoch (midnight UTC today, moved back
by the scenario's epoch_days_ago) as flags."""
import json
import os
import random
import socket
import subprocess
import time
import urllib.request

DEFAULT_TICK_RATE_HZ = 30  # ocean-server's default --tick-rate
DAY_MS = 86_400_000


def _ephemeral_range():
    try:
        with open("/proc/sys/net/ipv4/ip_local_port_range") as f:
            low, high = (int(v) for v in f.read().split())
            return low, high
    except (OSError, ValueError):
        return 32768, 60999  # Linux's default


_handed_out = set()


def free_port():
    """A port free for both TCP and UDP (the server uses one number for both), and not handed out
    before by this process.

    It lies outside the kernel's ephemeral range: a port from that range can be taken, between
    this check and the server's bind, by any socket's automatic local port - a connect() (the
    probe in start() included: to its own port on loopback it connects to itself), a UDP client
    - and the server then exits after start() saw a listener. Outside it only an explicit bind
    can take the port."""
    low, high = _ephemeral_range()
    candidates = [p for p in range(10000, 65536) if not low <= p <= high and p not in _handed_out]
    for _ in range(200):
        port = random.choice(candidates)
        t = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
        u = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        try:
            t.bind(("127.0.0.1", port))
            u.bind(("127.0.0.1", port))
            _handed_out.add(port)
            return port
        except OSError:
            continue
        finally:
            t.close()
            u.close()
    raise RuntimeError("no free loopback port outside the ephemeral range")


def client_port(transport, port, server_args):
    """The port the load test's clients connect to: `port` (--listen's), or for WebSocket clients
    (transport "ws") a free one, given to the server as --ws-listen (appended to server_args)."""
    if transport != "ws":
        return port
    ws_port = free_port()
    server_args += ["--ws-listen", f"127.0.0.1:{ws_port}"]
    return ws_port


def start(server_bin, args, port, ready_url=None):
    """Starts ocean-server with `args` (its --listen must use `port`, its UDP the same port) and
    waits until that process itself holds the TCP listener and the UDP socket on `port` - a probe
    that connects proves neither: another process may hold the port, and the server then exits -
    and, given `ready_url` (its /readyz), until it says it is ready: a first frame made. Raises
    RuntimeError with its output if it exits first or is not ready in 10 s."""
    server = subprocess.Popen([server_bin] + args, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    deadline = time.time() + 10
    while True:
        if server.poll() is not None:
            raise RuntimeError(f"ocean-server exited early (status {server.returncode}): " + server.stdout.read()[-2000:])
        if _holds(server.pid, port) and (ready_url is None or _ready(ready_url)):
            return server
        if time.time() > deadline:
            stop(server)
            raise RuntimeError(f"ocean-server was not ready in 10 s: {server.stdout.read()[-2000:]}")
        time.sleep(0.05)


def _socket_inodes(table, port, state=None):
    """Inodes of the sockets in /proc/net/<table> bound to `port` (in `state`, hex, if given)."""
    inodes = set()
    for name in (table, table + "6"):
        try:
            with open(f"/proc/net/{name}") as f:
                next(f)
                for line in f:
                    fields = line.split()
                    if int(fields[1].rsplit(":", 1)[1], 16) == port and (state is None or fields[3] == state):
                        inodes.add(fields[9])
        except OSError:
            continue
    return inodes


def _holds(pid, port):
    """Whether process `pid` holds a listening TCP socket (state 0A) and a UDP socket on `port`."""
    try:
        fd_dir = f"/proc/{pid}/fd"
        held = {os.readlink(os.path.join(fd_dir, fd)) for fd in os.listdir(fd_dir)}
    except OSError:
        return False
    return all(any(f"socket:[{inode}]" in held for inode in inodes)
               for inodes in (_socket_inodes("tcp", port, "0A"), _socket_inodes("udp", port)))


def _ready(url):
    try:
        with urllib.request.urlopen(url, timeout=0.5) as reply:
            return reply.status == 200
    except OSError:  # refused, or 503 while starting (HTTPError is an OSError)
        return False


def exit_report(server):
    """For a failure seen by a client: whether the server still runs, else how it ended and the
    end of its output (whatever a dead server said is the likeliest cause)."""
    if server.poll() is None:
        return "ocean-server still running"
    return f"ocean-server exited with status {server.returncode}: {server.stdout.read()[-2000:]}"


def stop(server):
    server.terminate()
    try:
        server.wait(timeout=10)
    except subprocess.TimeoutExpired:
        server.kill()


def scenario(loadtest_bin, name):
    """The scenario's entry of `ocean-loadtest --list-scenarios --json`; KeyError when unknown."""
    listed = subprocess.run([loadtest_bin, "--list-scenarios", "--json"], stdout=subprocess.PIPE, text=True, check=True)
    for entry in json.loads(listed.stdout.strip().splitlines()[-1]):
        if entry["name"] == name:
            return entry
    raise KeyError(f"ocean-loadtest knows no scenario '{name}'")


# --- schedule generators: (tick_rate_hz, now_tick, first_change_s, horizon_s) -> (base scene, entries)

WEATHER_FRONT_PERIOD_S = 2.5

# Cycles of different lengths: consecutive states differ in every key. State 0 is the scene the
# server starts with (deploy/ocean-server.toml's weather); entry k of the schedule sets state k.
_WEATHER = {
    "spectrum": ["jonswap", "phillips"],
    "spreading": ["donelan-banner", "cos2s", "hasselmann"],
    "wind-speed": [12.0, 6.0, 18.0, 9.0],
    "fetch": [100000.0, 20000.0, 400000.0, 50000.0],
    "amplitude": [1.0, 0.6, 1.5, 0.8],
    "depth": ["deep", 8.0, 30.0],
    "choppiness": [0.0, 1.0, 0.5, 1.5],
    "small-wave": [0.0, 0.5, 0.25],
}


def weather_state(k):
    state = {key: values[k % len(values)] for key, values in _WEATHER.items()}
    state["wind-dir"] = float(k * 75 % 360)
    return state


def weather_front(tick_rate_hz, now_tick, first_change_s, horizon_s):
    """Every schedulable scene key (server/net/config/config_options.cpp: spectrum, spreading,
    wind-speed, wind-dir, fetch, amplitude, depth, choppiness, small-wave) changes every
    WEATHER_FRONT_PERIOD_S, the first change first_change_s from now, until horizon_s."""
    period = round(WEATHER_FRONT_PERIOD_S * tick_rate_hz)
    first = now_tick + round(first_change_s * tick_rate_hz)
    count = max(1, int((horizon_s - first_change_s) / WEATHER_FRONT_PERIOD_S) + 1)
    entries = [dict(tick=first + k * period, **weather_state(k + 1)) for k in range(count)]
    return weather_state(0), entries


SCHEDULES = {"weather-front": weather_front}


def _toml_value(v):
    if isinstance(v, str):
        return json.dumps(v)  # a TOML basic string for ASCII text
    if isinstance(v, float):
        return repr(v)
    return str(v)


def config_toml(base, entries):
    """A config file: the base scene as top-level keys, then one [[schedule]] table per entry."""
    lines = ["# written by client/loadtest/local_server.py"]
    lines += [f"{key} = {_toml_value(value)}" for key, value in base.items()]
    for entry in entries:
        lines += ["", "[[schedule]]"] + [f"{key} = {_toml_value(value)}" for key, value in entry.items()]
    return "\n".join(lines) + "\n"


def scenario_server_args(entry, workdir, first_change_s=2.5, horizon_s=600.0, now_ms=None):
    """ocean-server flags for a scenario entry (scenario() above); a schedule's config file goes
    into workdir. [] for a scenario that needs nothing of the server."""
    needs = entry["server"]
    args = []
    if needs["profiles"]:
        args += ["--profiles", needs["profiles"]]
    if needs.get("fleet"):  # a scenario's vessels: a config file of [[vessel]] tables (fleets/)
        args += ["--config", os.path.join(os.path.dirname(os.path.abspath(__file__)), "fleets", needs["fleet"] + ".toml")]
    if not (needs["tick_rate_hz"] or needs["epoch_days_ago"] or needs["schedule"]):
        return args
    now_ms = int(time.time() * 1000) if now_ms is None else now_ms
    rate = needs["tick_rate_hz"] or DEFAULT_TICK_RATE_HZ
    epoch_ms = now_ms - now_ms % DAY_MS - needs["epoch_days_ago"] * DAY_MS
    args += ["--tick-rate", str(rate), "--epoch", str(epoch_ms)]
    if needs["schedule"]:
        generator = SCHEDULES[needs["schedule"]]
        now_tick = (now_ms - epoch_ms) * rate // 1000
        base, entries = generator(rate, now_tick, first_change_s, horizon_s)
        path = os.path.join(workdir, f"{entry['name']}.toml")
        with open(path, "w", encoding="ascii") as f:
            f.write(config_toml(base, entries))
        args += ["--config", path]
    return args
