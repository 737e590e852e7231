"""The checker's own test: each breakage is applied to a fresh copy of deploy/ and must be reported
with the expected message; the unmodified files must pass. Keeps the checker from going blind.
"""
import pathlib
import shutil
import sys
import tempfile

from .k8s_documents import jsonschema

# Each breakage: (file, text to find, replacement, a fragment the checker's message must contain).
BREAKAGES = [
    ("k8s/service.yaml", "targetPort: ocean-udp", "targetPort: ocean-udpx", "targetPort 'ocean-udpx'/UDP"),
    ("k8s/deployment.yaml", "              containerPort: 7700\n              protocol: UDP",
     "              containerPort: 7701\n              protocol: UDP", "declares no UDP port 7700"),
    ("k8s/deployment.yaml", "              port: metrics\n            periodSeconds: 10",
     "              port: metricz\n            periodSeconds: 10", "livenessProbe port 'metricz'"),
    ("k8s/deployment.yaml", "allowPrivilegeEscalation: false", "allowPrivilegeEscalation: true", "allowPrivilegeEscalation"),
    ("k8s/deployment.yaml", "- key: cookie-key", "- key: cookie-keys", "'cookie-keys' is not in secret"),
    ("k8s/hpa.yaml", "  name: ocean-server\n  labels", "  labels", "missing metadata.name"),
    ("k8s/configmap.yaml", "    size = 256", "    size = ", "not valid TOML"),
    ("k8s/configmap.yaml", 'listen = "0.0.0.0:7700"', 'listen = "0.0.0.0:7701"', "config listens on port 7701"),
    ("k8s/configmap.yaml", "    # wind-speed = 18.0", "    # seed = 18", "'seed' cannot be scheduled"),
    ("k8s/kustomization.yaml", "  - hpa.yaml", "  - hpa.yaml\n  - secret.example.yaml", "placeholder values"),
    ("ocean-server.toml", "tick-rate = 30", "tick-rate = ", "not valid TOML"),
    ("ocean-server.toml", "max-clients = 64", "max-client = 64", "'max-client' is not an ocean-server option"),
    ("ocean-server.service", "NoNewPrivileges=yes\n", "", "lacks NoNewPrivileges=yes"),
    ("ocean-server.service", "RestrictAddressFamilies=AF_INET AF_INET6 AF_UNIX",
     "RestrictAddressFamilies=AF_INET AF_INET6 AF_UNIX AF_NETLINK", "RestrictAddressFamilies"),
    ("Dockerfile", "EXPOSE 7700/tcp 7700/udp 9464/tcp", "EXPOSE 7700/tcp 9464/tcp", "EXPOSE lacks 7700/udp"),
    ("k8s/loadtest-job.yaml", "completionMode: Indexed", "completionMode: NonIndexed", "completionMode must be Indexed"),
    ("k8s/loadtest-job.yaml", "parallelism: 20", "parallelism: 5", "parallelism 5 != completions 20"),
    ("k8s/loadtest-job.yaml", "- ocean-server:7700", "- ocean-server:7701", "--server ocean-server:7701: no Service"),
    ("k8s/loadtest-job.yaml", "            - --json\n", "", "needs --json"),
    ("k8s/loadtest-job.yaml", "whenUnsatisfiable: DoNotSchedule", "whenUnsatisfiable: ScheduleAnyway", "share its cores"),
    ("k8s/loadtest-job.yaml", "readOnlyRootFilesystem: true", "readOnlyRootFilesystem: false", "readOnlyRootFilesystem"),
]
SCHEMA_BREAKAGES = [
    ("k8s/service.yaml", "      port: 9464", '      port: "9464"', "schema: spec.ports.0.port"),
    ("k8s/deployment.yaml", "          readinessProbe:", "          readynessProbe:", "'readynessProbe' is not one of"),
    ("k8s/loadtest-job.yaml", "restartPolicy: Never", "restartPolicy: Always", "'Always' is not one of"),
]


def self_test(deploy_dir, check):
    deploy_dir = pathlib.Path(deploy_dir)
    failures = []
    clean = check(deploy_dir)
    if clean.problems:
        failures.append("the unmodified deploy/ already fails:\n  " + "\n  ".join(clean.problems))
    breakages = BREAKAGES + (SCHEMA_BREAKAGES if jsonschema is not None else [])
    with tempfile.TemporaryDirectory(prefix="ocean-deploy-selftest-") as scratch:
        for relative, find, replace, expected in breakages:
            copy_dir = pathlib.Path(scratch) / "deploy"
            shutil.rmtree(copy_dir, ignore_errors=True)
            shutil.copytree(deploy_dir, copy_dir, ignore=shutil.ignore_patterns("__pycache__"))
            target = copy_dir / relative
            text = target.read_text()
            if find not in text:
                failures.append(f"breakage of {relative} no longer applies: {find!r} not found; update BREAKAGES")
                continue
            target.write_text(text.replace(find, replace, 1))
            problems = check(copy_dir).problems
            if not any(expected in p for p in problems):
                failures.append(f"{relative}: replacing {find!r} with {replace!r} was not reported as {expected!r}; "
                                f"got {problems or 'no problems'}")
    for failure in failures:
        print(f"check-manifests self-test: {failure}", file=sys.stderr)
    if not failures:
        print(f"check-manifests self-test: all {len(breakages)} breakages caught; the unmodified files pass")
    return 1 if failures else 0
