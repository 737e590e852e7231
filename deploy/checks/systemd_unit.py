"""deploy/ocean-server.service: the hardening keys, the credential for the admin token, and the
config path. systemd-analyze is not run here (it needs the binary and a systemd host).
"""

UNIT_REQUIRED = {
    "DynamicUser": "yes", "NoNewPrivileges": "yes", "ProtectSystem": "strict", "ProtectHome": "yes",
    "PrivateTmp": "yes", "PrivateDevices": "yes", "ProtectKernelTunables": "yes",
    "ProtectKernelModules": "yes", "ProtectKernelLogs": "yes", "ProtectControlGroups": "yes",
    "MemoryDenyWriteExecute": "yes", "LockPersonality": "yes", "RestrictNamespaces": "yes",
    "CapabilityBoundingSet": "", "ConfigurationDirectory": "ocean", "Restart": "on-failure",
    "KillSignal": "SIGTERM",
}
UNIT_ADDRESS_FAMILIES = {"AF_INET", "AF_INET6", "AF_UNIX"}


def parse_unit(text):
    sections, section = {}, None
    for line in text.splitlines():
        line = line.strip()
        if not line or line.startswith(("#", ";")):
            continue
        if line.startswith("[") and line.endswith("]"):
            section = sections.setdefault(line[1:-1], {})
        elif "=" in line and section is not None:
            key, value = line.split("=", 1)
            section.setdefault(key.strip(), []).append(value.strip())
    return sections


def check_unit(report, path):
    if not path.is_file():
        report.problem(path.name, "missing")
        return
    service = parse_unit(path.read_text()).get("Service", {})
    for key, wanted in UNIT_REQUIRED.items():
        values = service.get(key)
        if values is None:
            report.problem(path.name, f"[Service] lacks {key}={wanted}")
        elif values[-1] != wanted:
            report.problem(path.name, f"[Service] {key}={values[-1]}, expected {key}={wanted}")
    families = set(" ".join(service.get("RestrictAddressFamilies", [])).split())
    if families != UNIT_ADDRESS_FAMILIES:
        report.problem(path.name, f"RestrictAddressFamilies must be exactly {' '.join(sorted(UNIT_ADDRESS_FAMILIES))}")
    if "@system-service" not in " ".join(service.get("SystemCallFilter", [])).split():
        report.problem(path.name, "SystemCallFilter must allow only @system-service")
    credentials = [c.split(":", 1)[0] for c in service.get("LoadCredential", [])]
    exec_start = " ".join(service.get("ExecStart", []))
    if "admin-token" not in credentials or "--admin-token-file %d/admin-token" not in exec_start:
        report.problem(path.name, "the admin token must come from LoadCredential=admin-token:... and --admin-token-file %d/admin-token")
    if "--config %E/ocean/ocean-server.toml" not in exec_start:
        report.problem(path.name, "ExecStart must pass --config %E/ocean/ocean-server.toml (ConfigurationDirectory=ocean)")
