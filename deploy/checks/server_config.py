"""An ocean-server TOML config: it parses, names only options the server has, schedules only
weather, and pins what replicas must agree on. The option table is the server's own
(ocean-server --help-json), so the check follows the server, not a copy of its option list.
"""
import json
import re
import subprocess
import tomllib


def server_tables(server):
    """ocean-server --help-json as a dict ({"options": [...], "profiles": [...]}); raises
    RuntimeError naming the problem when the binary cannot give it."""
    try:
        done = subprocess.run([str(server), "--help-json"], capture_output=True, text=True, timeout=30)
    except OSError as error:
        raise RuntimeError(f"{server}: cannot run it: {error}") from error
    if done.returncode != 0:
        raise RuntimeError(f"{server} --help-json exited {done.returncode}: {done.stderr.strip()}")
    try:
        return json.loads(done.stdout)
    except json.JSONDecodeError as error:
        raise RuntimeError(f"{server} --help-json printed no JSON: {error}") from error


def server_options(server):
    """{option name: schedulable} from the server's option table."""
    return {option["name"]: option["schedulable"] for option in server_tables(server)["options"]}


def port_of(address):
    match = re.fullmatch(r"(.*):(\d+)", address or "")
    return (match.group(1), int(match.group(2))) if match else (None, None)


def commented_schedule_example(text):
    """The commented-out [[schedule]] example, uncommented, or "" when the file has none."""
    lines, inside = [], False
    for line in text.splitlines():
        body = re.sub(r"^\s*#\s?", "", line) if line.lstrip().startswith("#") else None
        if body is not None and body.strip() == "[[schedule]]":
            inside = True
        elif not (inside and body is not None and re.fullmatch(r"[a-z-]+\s*=\s*\S.*", body.strip())):
            inside = False
            continue
        lines.append(body.strip())
    return "\n".join(lines)


def check_server_config(report, where, text, options):
    """Parses one server TOML config; returns its table (or None)."""
    try:
        config = tomllib.loads(text)
    except tomllib.TOMLDecodeError as error:
        report.problem(where, f"not valid TOML: {error}")
        return None
    for label, table in (("", config), (" (commented [[schedule]] example)", None)):
        if table is None:
            example = commented_schedule_example(text)
            if not example:
                report.problem(where, "has no commented [[schedule]] example to show a scheduled change")
                continue
            try:
                table = tomllib.loads(example)
            except tomllib.TOMLDecodeError as error:
                report.problem(where + label, f"not valid TOML once uncommented: {error}")
                continue
        for key in table:
            if key != "schedule" and options is not None and key not in options:
                report.problem(where + label, f"'{key}' is not an ocean-server option (see ocean-server --help)")
        for index, entry in enumerate(table.get("schedule", []), 1):
            if not isinstance(entry.get("tick"), int):
                report.problem(where + label, f"schedule entry {index} needs an integer tick")
            for key in entry:
                if key != "tick" and options is not None and not options.get(key, False):
                    report.problem(where + label, f"schedule entry {index}: '{key}' cannot be scheduled")
    for key in ("listen", "metrics-listen", "tick-rate", "epoch", "seed"):
        if key not in config:
            report.problem(where, f"must set '{key}' explicitly (replicas must agree on it; probes need it)")
    host, _ = port_of(config.get("metrics-listen"))
    if host in ("127.0.0.1", "localhost", "[::1]"):
        report.problem(where, "metrics-listen is loopback: probes and scrapers from outside cannot reach it")
    return config
