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
import socket
import subprocess
import time

DEFAULT_TICK_RATE_HZ = 30  # ocean-server's default --tick-rate
DAY_MS = 86_400_000


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
    """Every schedulable scene key (server/net/config_options.cpp: spectrum, spreading,
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
