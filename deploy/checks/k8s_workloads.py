"""How the Kubernetes objects fit together: Services reach declared container ports (TCP and UDP),
probes hit declared ports and the server's endpoints, mounted keys exist, the container is locked
down, the config's ports are the declared ones, and the Kustomization ships no placeholder Secret.
"""
from .k8s_documents import by_kind
from .server_config import port_of

CONFIG_PATH_IN_IMAGE = "/etc/ocean/ocean-server.toml"


def container_port(container, target, protocol):
    for port in container.get("ports") or []:
        if (port.get("name") == target or port.get("containerPort") == target) and \
                port.get("protocol", "TCP") == protocol:
            return port
    return None


def check_container(report, where, pod, container, configmaps, secrets):
    """A server container: probes on declared ports and the server's endpoints, and locked down."""
    name = container.get("name")
    for probe_kind in ("livenessProbe", "readinessProbe", "startupProbe"):
        probe = container.get(probe_kind) or {}
        handler = probe.get("httpGet") or probe.get("tcpSocket")
        if handler and container_port(container, handler.get("port"), "TCP") is None:
            report.problem(where, f"container {name}: {probe_kind} port {handler.get('port')!r} is not a declared TCP port")
    for probe_kind, path in (("livenessProbe", "/healthz"), ("readinessProbe", "/readyz")):
        got = ((container.get(probe_kind) or {}).get("httpGet") or {}).get("path")
        if got != path:
            report.problem(where, f"container {name}: {probe_kind} must GET {path} (ocean-server's endpoint), not {got!r}")
    check_locked_down(report, where, pod, container, configmaps, secrets)


def check_locked_down(report, where, pod, container, configmaps, secrets):
    """Any container of ours: no privilege, read-only root, no capabilities, non-root, sized, and
    its mounts resolve."""
    name = container.get("name")
    security = container.get("securityContext") or {}
    pod_security = pod.get("securityContext") or {}
    if security.get("allowPrivilegeEscalation") is not False:
        report.problem(where, f"container {name}: securityContext.allowPrivilegeEscalation must be false")
    if security.get("readOnlyRootFilesystem") is not True:
        report.problem(where, f"container {name}: securityContext.readOnlyRootFilesystem must be true")
    if "ALL" not in ((security.get("capabilities") or {}).get("drop") or []):
        report.problem(where, f"container {name}: securityContext.capabilities.drop must include ALL")
    if not (security.get("runAsNonRoot") or pod_security.get("runAsNonRoot")):
        report.problem(where, f"container {name}: runAsNonRoot must be true")
    resources = container.get("resources") or {}
    for part in ("requests", "limits"):
        for resource in ("cpu", "memory"):
            if resource not in (resources.get(part) or {}):
                report.problem(where, f"container {name}: resources.{part}.{resource} is missing")
    volumes = {v.get("name"): v for v in pod.get("volumes") or []}
    for mount in container.get("volumeMounts") or []:
        volume = volumes.get(mount.get("name"))
        if volume is None:
            report.problem(where, f"container {name}: volumeMount {mount.get('name')!r} has no volume")
            continue
        for source_kind, source_key, known in (("configMap", "name", configmaps), ("secret", "secretName", secrets)):
            source = volume.get(source_kind)
            if not source:
                continue
            keys = known.get(source.get(source_key))
            if keys is None:
                if source_kind == "configMap":
                    report.problem(where, f"volume {volume['name']}: ConfigMap {source.get(source_key)!r} is not defined")
                continue
            for item in source.get("items") or []:
                if item.get("key") not in keys:
                    report.problem(where, f"volume {volume['name']}: key {item.get('key')!r} is not in {source_kind} {source.get(source_key)!r}")


def mounted_sources(documents):
    """The keys of every ConfigMap and Secret, by name, for checking what pods mount."""
    configmaps = {d["metadata"]["name"]: set((d.get("data") or {}).keys())
                  for _, d in by_kind(documents, "ConfigMap") if isinstance(d.get("metadata"), dict)}
    secrets = {d["metadata"]["name"]: set((d.get("stringData") or {}).keys()) | set((d.get("data") or {}).keys())
               for _, d in by_kind(documents, "Secret") if isinstance(d.get("metadata"), dict)}
    return configmaps, secrets


def check_workloads(report, documents, configs):
    configmaps, secrets = mounted_sources(documents)
    deployments = by_kind(documents, "Deployment")
    if not deployments:
        report.problem("k8s", "no Deployment")
    pods = []
    for where, deployment in deployments:
        template = (deployment.get("spec") or {}).get("template") or {}
        pod = template.get("spec") or {}
        labels = (template.get("metadata") or {}).get("labels") or {}
        selector = ((deployment.get("spec") or {}).get("selector") or {}).get("matchLabels") or {}
        if any(labels.get(k) != v for k, v in selector.items()):
            report.problem(where, "spec.selector.matchLabels does not match the pod template's labels")
        for container in pod.get("containers") or []:
            check_container(report, where, pod, container, configmaps, secrets)
            check_ports_against_config(report, where, pod, container, configs)
        pods.append((where, labels, pod))
    for where, statefulset in by_kind(documents, "StatefulSet"):
        pods.append(check_statefulset(report, where, statefulset, configmaps, secrets))
    for where, service in by_kind(documents, "Service"):
        check_service(report, where, service, pods)


def check_statefulset(report, where, statefulset, configmaps, secrets):
    """Another workload of ours (the timeline's store): its labels, probes on declared ports, locked
    down, its mounts resolved (a claim template counts as a volume). Returns (where, labels, pod)."""
    spec = statefulset.get("spec") or {}
    template = spec.get("template") or {}
    pod = dict(template.get("spec") or {})
    labels = (template.get("metadata") or {}).get("labels") or {}
    selector = (spec.get("selector") or {}).get("matchLabels") or {}
    if any(labels.get(k) != v for k, v in selector.items()):
        report.problem(where, "spec.selector.matchLabels does not match the pod template's labels")
    claims = [{"name": (c.get("metadata") or {}).get("name")} for c in spec.get("volumeClaimTemplates") or []]
    pod["volumes"] = list(pod.get("volumes") or []) + claims
    for container in pod.get("containers") or []:
        for probe_kind in ("livenessProbe", "readinessProbe", "startupProbe"):
            handler = ((container.get(probe_kind) or {}).get("httpGet") or (container.get(probe_kind) or {}).get("tcpSocket"))
            if handler and container_port(container, handler.get("port"), "TCP") is None:
                report.problem(where, f"container {container.get('name')}: {probe_kind} port {handler.get('port')!r} is not a declared TCP port")
        check_locked_down(report, where, pod, container, configmaps, secrets)
    return where, labels, pod


def check_ports_against_config(report, where, pod, container, configs):
    """The server's listen/metrics ports (from the mounted ConfigMap) must be the declared ones."""
    volumes = {v.get("name"): v for v in pod.get("volumes") or []}
    for mount in container.get("volumeMounts") or []:
        source = (volumes.get(mount.get("name")) or {}).get("configMap") or {}
        for key, config in configs.get(source.get("name"), {}).items():
            if mount.get("mountPath", "").rstrip("/") + "/" + key != CONFIG_PATH_IN_IMAGE or config is None:
                continue
            _, listen = port_of(config.get("listen"))
            _, metrics = port_of(config.get("metrics-listen"))
            for protocol in ("TCP", "UDP"):
                if container_port(container, listen, protocol) is None:
                    report.problem(where, f"config listens on port {listen}, but the container declares no {protocol} port {listen}")
            if container_port(container, metrics, "TCP") is None:
                report.problem(where, f"config serves metrics on port {metrics}, but the container declares no TCP port {metrics}")


def check_service(report, where, service, pods):
    spec = service.get("spec") or {}
    selector = spec.get("selector") or {}
    matched = [(w, pod) for w, labels, pod in pods if selector and all(labels.get(k) == v for k, v in selector.items())]
    if not matched:
        report.problem(where, f"selector {selector} matches no Deployment's or StatefulSet's pods")
    ports = spec.get("ports") or []
    for port in ports:
        protocol = port.get("protocol", "TCP")
        target = port.get("targetPort", port.get("port"))
        for _, pod in matched:
            if not any(container_port(c, target, protocol) for c in pod.get("containers") or []):
                report.problem(where, f"port {port.get('name', port.get('port'))}: targetPort {target!r}/{protocol} is not a container port")
    udp = {p.get("port") for p in ports if p.get("protocol") == "UDP"}
    tcp = {p.get("port") for p in ports if p.get("protocol", "TCP") == "TCP"}
    if udp and udp != tcp & udp:
        report.problem(where, "every UDP port must also be offered over TCP on the same number (the client protocol uses both)")
    if udp and spec.get("sessionAffinity") != "ClientIP":
        report.problem(where, "a TCP+UDP Service needs sessionAffinity: ClientIP")


def check_kustomization(report, documents, k8s_dir):
    for where, kustomization in by_kind(documents, "Kustomization"):
        for resource in kustomization.get("resources") or []:
            path = k8s_dir / resource
            if not path.exists():
                report.problem(where, f"resource {resource} does not exist")
            elif any(p == path and d.get("kind") == "Secret" for _, p, d in documents):
                report.problem(where, f"resource {resource} is a Secret with placeholder values; create secrets outside the repo")
