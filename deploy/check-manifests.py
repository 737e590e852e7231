#!/usr/bin/python3
"""Checks the deployment files in deploy/ against each other and against what ocean-server accepts.

  check-manifests.py [--server BIN] DEPLOY_DIR              every problem on stderr, one line
                                                           each; exit 1 if any
  check-manifests.py --self-test [--server BIN] DEPLOY_DIR  breaks copies of DEPLOY_DIR on purpose
                                                           and exits 1 unless the checker catches
                                                           every breakage
  BIN is an ocean-server; its --help-json gives the options a config may use (without it, config
  keys are not checked, and the self-test needs it).

What it checks: every YAML document under k8s/ has apiVersion, kind and metadata.name; the
Services' targetPorts resolve to container ports of the same protocol (TCP and UDP alike); probes
point at declared TCP ports; mounted ConfigMap/Secret keys exist; the container runs locked down;
the server config (ConfigMap and ocean-server.toml) parses as TOML, uses only options the server
knows (ocean-server --help-json) and listens on the ports the
Deployment and Dockerfile declare; the systemd unit carries the hardening keys; the load-test Job
runs its processes together, one per node, against a Service of these manifests, printing --json. With
python3-jsonschema installed it also validates each document against a SUBSET schema
(checks/schemas.py).
"""
import argparse
import functools
import pathlib
import sys

sys.dont_write_bytecode = True  # importing checks/ must not litter the source tree
sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from checks.dockerfile import check_dockerfile  # noqa: E402  (beside this script)
from checks.k8s_documents import by_kind, check_schemas, load_documents  # noqa: E402
from checks.k8s_jobs import check_jobs  # noqa: E402
from checks.k8s_workloads import check_kustomization, check_workloads  # noqa: E402
from checks.report import Report  # noqa: E402
from checks.self_test import self_test  # noqa: E402
from checks.server_config import check_server_config, server_options  # noqa: E402
from checks.systemd_unit import check_unit  # noqa: E402


def check(deploy_dir, options):
    """options: {name: schedulable} of the server, or None (config keys then not checked)."""
    deploy_dir = pathlib.Path(deploy_dir)
    report = Report()
    if options is None:
        report.notes.append("no --server: config keys not checked")
    else:
        report.notes.append(f"{len(options)} server options")
    k8s_dir = deploy_dir / "k8s"
    documents = load_documents(report, k8s_dir)
    check_schemas(report, documents)
    configs = {}
    for where, configmap in by_kind(documents, "ConfigMap"):
        name = (configmap.get("metadata") or {}).get("name")
        for key, text in (configmap.get("data") or {}).items():
            if key.endswith(".toml"):
                configs.setdefault(name, {})[key] = check_server_config(report, f"{where} data.{key}", str(text), options)
    if not any(configs.values()):
        report.problem("k8s", "no ConfigMap holds an ocean-server .toml config")
    check_workloads(report, documents, configs)
    check_jobs(report, documents)
    check_kustomization(report, documents, k8s_dir)
    example = deploy_dir / "ocean-server.toml"
    example_config = None
    if example.is_file():
        example_config = check_server_config(report, example.name, example.read_text(), options)
    else:
        report.problem(example.name, "missing")
    check_unit(report, deploy_dir / "ocean-server.service")
    run_as_users = {((d.get("spec") or {}).get("template") or {}).get("spec", {}).get("securityContext", {}).get("runAsUser")
                    for _, d in by_kind(documents, "Deployment")} - {None}
    check_dockerfile(report, deploy_dir / "Dockerfile", example_config, run_as_users)
    report.notes.append(f"{len(documents)} YAML documents")
    return report


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--self-test", action="store_true")
    parser.add_argument("--server", help="an ocean-server binary, whose --help-json names its options")
    parser.add_argument("deploy_dir")
    args = parser.parse_args(argv[1:])
    options = None
    if args.server:
        try:
            options = server_options(args.server)
        except RuntimeError as error:
            print(f"check-manifests: {error}", file=sys.stderr)
            return 2
    elif args.self_test:
        print("check-manifests: the self-test needs --server (its breakages include unknown options)", file=sys.stderr)
        return 2
    if args.self_test:
        return self_test(args.deploy_dir, functools.partial(check, options=options))
    report = check(args.deploy_dir, options)
    for problem in report.problems:
        print(f"check-manifests: {problem}", file=sys.stderr)
    status = "FAILED" if report.problems else "OK"
    print(f"check-manifests: {status}; " + "; ".join(report.notes))
    return 1 if report.problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
