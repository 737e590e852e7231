"""deploy/Dockerfile: exposes the config's ports (TCP and UDP), runs as the Deployment's non-root
uid, has a HEALTHCHECK and starts the server with the image's config file.
"""
import re

from .k8s_workloads import CONFIG_PATH_IN_IMAGE
from .server_config import port_of


def check_dockerfile(report, path, config, run_as_users):
    if not path.is_file():
        report.problem(path.name, "missing")
        return
    text = path.read_text()
    exposed = set(re.findall(r"\b(\d+/(?:tcp|udp))\b", " ".join(re.findall(r"(?m)^EXPOSE\s+(.*)$", text))))
    if config:
        _, listen = port_of(config.get("listen"))
        _, metrics = port_of(config.get("metrics-listen"))
        for wanted in (f"{listen}/tcp", f"{listen}/udp", f"{metrics}/tcp"):
            if wanted not in exposed:
                report.problem(path.name, f"EXPOSE lacks {wanted} (from ocean-server.toml)")
    user = re.findall(r"(?m)^USER\s+(\d+)", text)
    if not user or user[-1] == "0":
        report.problem(path.name, "USER must be a numeric non-root uid")
    elif run_as_users and {str(u) for u in run_as_users} != {user[-1]}:
        report.problem(path.name, f"USER {user[-1]} differs from the Deployment's runAsUser {sorted(run_as_users)}")
    if not re.search(r"(?m)^HEALTHCHECK\s", text):
        report.problem(path.name, "no HEALTHCHECK")
    if f'"--config", "{CONFIG_PATH_IN_IMAGE}"' not in text:
        report.problem(path.name, f"ENTRYPOINT must pass --config {CONFIG_PATH_IN_IMAGE}")
