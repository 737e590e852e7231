"""The load-test Job (deploy/k8s/loadtest-job.yaml): K ocean-loadtest processes whose JSON
summaries are merged into one report. A merge only means something when the processes ran at the
same time against the server the manifests deploy, each printed its summary, and none shared a
machine with another; and its container is locked down like the server's.
"""
from .k8s_documents import by_kind
from .k8s_workloads import check_locked_down, mounted_sources


def flag_values(args, flag):
    """Values given to `flag` as `--flag value` or `--flag=value`."""
    values = []
    for i, arg in enumerate(args):
        if arg == flag and i + 1 < len(args):
            values.append(str(args[i + 1]))
        elif isinstance(arg, str) and arg.startswith(flag + "="):
            values.append(arg[len(flag) + 1:])
    return values


def service_ports(documents):
    """{(service name, port): {protocols}} over every Service."""
    ports = {}
    for _, service in by_kind(documents, "Service"):
        name = (service.get("metadata") or {}).get("name")
        for port in (service.get("spec") or {}).get("ports") or []:
            ports.setdefault((name, port.get("port")), set()).add(port.get("protocol", "TCP"))
    return ports


def check_servers(report, where, args, documents):
    """Every --server HOST:PORT is a Service of these manifests offering PORT over TCP (and UDP
    unless the clients ask for TCP): a load test aimed elsewhere tests something else."""
    ports = service_ports(documents)
    needed = {"TCP"} if "tcp" in flag_values(args, "--transport") else {"TCP", "UDP"}
    servers = [s for value in flag_values(args, "--server") for s in value.split(",") if s]
    if not servers:
        report.problem(where, "ocean-loadtest has no --server (it would aim at 127.0.0.1:7700 inside its own pod)")
    for server in servers:
        host, _, port = server.rpartition(":")
        offered = ports.get((host.split(".")[0], int(port) if port.isdigit() else port), set())
        if not needed <= offered:
            report.problem(where, f"--server {server}: no Service {host.split('.')[0]!r} offers port {port} over "
                                  f"{' and '.join(sorted(needed - offered))}")


def check_loadtest_job(report, where, job, container, documents):
    spec = job.get("spec") or {}
    pod = (spec.get("template") or {}).get("spec") or {}
    if spec.get("completionMode") != "Indexed":
        report.problem(where, "completionMode must be Indexed: each process needs its index (JOB_INDEX, its --seed)")
    if spec.get("parallelism") != spec.get("completions"):
        report.problem(where, f"parallelism {spec.get('parallelism')} != completions {spec.get('completions')}: "
                              "processes that do not run together measure different loads, and their merge means nothing")
    args = [str(a) for a in (container.get("command") or []) + (container.get("args") or [])]
    if "--json" not in args:
        report.problem(where, "ocean-loadtest needs --json: its summary is what --merge reads")
    check_servers(report, where, args, documents)
    spread = [c for c in pod.get("topologySpreadConstraints") or []
              if c.get("topologyKey") == "kubernetes.io/hostname" and c.get("whenUnsatisfiable") == "DoNotSchedule"]
    if not spread:
        report.problem(where, "no topologySpreadConstraint on kubernetes.io/hostname with DoNotSchedule: "
                              "two load-test processes on one node would share its cores")


def check_jobs(report, documents):
    configmaps, secrets = mounted_sources(documents)
    for where, job in by_kind(documents, "Job"):
        pod = (((job.get("spec") or {}).get("template") or {}).get("spec")) or {}
        for container in pod.get("containers") or []:
            check_locked_down(report, where, pod, container, configmaps, secrets)
            runs = " ".join(str(x) for x in [container.get("image", "")] + (container.get("command") or []))
            if "ocean-loadtest" in runs:
                check_loadtest_job(report, where, job, container, documents)
