"""Hand-written JSON schemas for the Kubernetes kinds deploy/k8s uses.

A SUBSET of the real OpenAPI schemas: only the fields our manifests use, their types, and the
required ones. Unknown fields are allowed except in containers, probes and container security
contexts, whose complete field lists are given. It catches typos in structure and type (a port given
as text, a probe without a handler), not everything the API server would reject.
"""

_name = {"type": "string", "pattern": "^[a-z0-9]([-a-z0-9]*[a-z0-9])?$", "maxLength": 63}
_metadata = {
    "type": "object",
    "required": ["name"],
    "properties": {
        "name": _name,
        "labels": {"type": "object", "additionalProperties": {"type": "string"}},
        "annotations": {"type": "object", "additionalProperties": {"type": "string"}},
    },
}
_port_name = {"type": "string", "pattern": "^[a-z0-9]([-a-z0-9]*[a-z0-9])?$", "maxLength": 15}
_port_number = {"type": "integer", "minimum": 1, "maximum": 65535}
_int_or_name = {"oneOf": [_port_number, _port_name]}
_protocol = {"enum": ["TCP", "UDP", "SCTP"]}
_quantity = {"type": ["string", "integer", "number"]}
_resource_list = {"type": "object", "properties": {"cpu": _quantity, "memory": _quantity}}

# Field names of the real API objects (Kubernetes 1.30), so a misspelt key is caught rather than
# silently ignored.
_probe_fields = ["exec", "failureThreshold", "grpc", "httpGet", "initialDelaySeconds", "periodSeconds",
                 "successThreshold", "tcpSocket", "terminationGracePeriodSeconds", "timeoutSeconds"]
_container_fields = ["args", "command", "env", "envFrom", "image", "imagePullPolicy", "lifecycle",
                     "livenessProbe", "name", "ports", "readinessProbe", "resizePolicy", "resources",
                     "restartPolicy", "securityContext", "startupProbe", "stdin", "stdinOnce",
                     "terminationMessagePath", "terminationMessagePolicy", "tty", "volumeDevices",
                     "volumeMounts", "workingDir"]
_security_context_fields = ["allowPrivilegeEscalation", "appArmorProfile", "capabilities", "privileged",
                            "procMount", "readOnlyRootFilesystem", "runAsGroup", "runAsNonRoot", "runAsUser",
                            "seLinuxOptions", "seccompProfile", "windowsOptions"]

_probe = {
    "type": "object",
    "propertyNames": {"enum": _probe_fields},
    "properties": {
        "httpGet": {
            "type": "object",
            "required": ["port"],
            "properties": {"path": {"type": "string"}, "port": _int_or_name},
        },
        "tcpSocket": {"type": "object", "required": ["port"], "properties": {"port": _int_or_name}},
        "periodSeconds": {"type": "integer", "minimum": 1},
        "timeoutSeconds": {"type": "integer", "minimum": 1},
        "failureThreshold": {"type": "integer", "minimum": 1},
        "initialDelaySeconds": {"type": "integer", "minimum": 0},
    },
    "oneOf": [{"required": ["httpGet"]}, {"required": ["tcpSocket"]}, {"required": ["exec"]}],
}

_container = {
    "type": "object",
    "required": ["name", "image"],
    "propertyNames": {"enum": _container_fields},
    "properties": {
        "name": _name,
        "image": {"type": "string", "minLength": 1},
        "args": {"type": "array", "items": {"type": "string"}},
        "command": {"type": "array", "items": {"type": "string"}},
        "ports": {
            "type": "array",
            "items": {
                "type": "object",
                "required": ["containerPort"],
                "properties": {"name": _port_name, "containerPort": _port_number, "protocol": _protocol},
            },
        },
        "livenessProbe": _probe,
        "readinessProbe": _probe,
        "startupProbe": _probe,
        "resources": {"type": "object", "properties": {"requests": _resource_list, "limits": _resource_list}},
        "securityContext": {
            "type": "object",
            "propertyNames": {"enum": _security_context_fields},
            "properties": {
                "runAsNonRoot": {"type": "boolean"},
                "allowPrivilegeEscalation": {"type": "boolean"},
                "readOnlyRootFilesystem": {"type": "boolean"},
                "capabilities": {
                    "type": "object",
                    "properties": {"drop": {"type": "array", "items": {"type": "string"}}},
                },
            },
        },
        "volumeMounts": {
            "type": "array",
            "items": {
                "type": "object",
                "required": ["name", "mountPath"],
                "properties": {"name": _name, "mountPath": {"type": "string"}, "readOnly": {"type": "boolean"}},
            },
        },
    },
}

_key_to_path = {
    "type": "array",
    "items": {"type": "object", "required": ["key", "path"],
              "properties": {"key": {"type": "string"}, "path": {"type": "string"}}},
}

_pod_spec = {
    "type": "object",
    "required": ["containers"],
    "properties": {
        "containers": {"type": "array", "minItems": 1, "items": _container},
        "restartPolicy": {"enum": ["Always", "OnFailure", "Never"]},
        "securityContext": {
            "type": "object",
            "properties": {
                "runAsNonRoot": {"type": "boolean"},
                "runAsUser": {"type": "integer", "minimum": 0},
                "runAsGroup": {"type": "integer", "minimum": 0},
                "fsGroup": {"type": "integer", "minimum": 0},
            },
        },
        "volumes": {
            "type": "array",
            "items": {
                "type": "object",
                "required": ["name"],
                "properties": {
                    "name": _name,
                    "configMap": {"type": "object", "required": ["name"],
                                  "properties": {"items": _key_to_path}},
                    "secret": {"type": "object", "required": ["secretName"],
                               "properties": {"items": _key_to_path}},
                },
            },
        },
    },
}

def _workload(required=(), **properties):
    """An apps/v1 workload of pods from a template (Deployment, StatefulSet) and its own fields."""
    return {
        "type": "object",
        "required": ["apiVersion", "kind", "metadata", "spec"],
        "properties": {
            "apiVersion": {"const": "apps/v1"},
            "metadata": _metadata,
            "spec": {
                "type": "object",
                "required": ["selector", "template", *required],
                "properties": {
                    "replicas": {"type": "integer", "minimum": 0},
                    "selector": {"type": "object", "required": ["matchLabels"]},
                    "template": {
                        "type": "object",
                        "required": ["metadata", "spec"],
                        "properties": {
                            "metadata": {"type": "object", "required": ["labels"]},
                            "spec": _pod_spec,
                        },
                    },
                    **properties,
                },
            },
        },
    }


_deployment = _workload()
# The timeline's store: a Service name for its members, and a claim template for their data.
_statefulset = _workload(
    required=("serviceName",),
    serviceName=_name,
    volumeClaimTemplates={
        "type": "array",
        "items": {"type": "object", "required": ["metadata", "spec"], "properties": {"metadata": _metadata}},
    },
)

# A Job's pods end: they may not restart Always.
_job = {
    "type": "object",
    "required": ["apiVersion", "kind", "metadata", "spec"],
    "properties": {
        "apiVersion": {"const": "batch/v1"},
        "metadata": _metadata,
        "spec": {
            "type": "object",
            "required": ["template"],
            "properties": {
                "completionMode": {"enum": ["NonIndexed", "Indexed"]},
                "completions": {"type": "integer", "minimum": 1},
                "parallelism": {"type": "integer", "minimum": 0},
                "backoffLimit": {"type": "integer", "minimum": 0},
                "ttlSecondsAfterFinished": {"type": "integer", "minimum": 0},
                "activeDeadlineSeconds": {"type": "integer", "minimum": 1},
                "template": {
                    "type": "object",
                    "required": ["spec"],
                    "properties": {
                        "spec": {"allOf": [_pod_spec, {"type": "object", "required": ["restartPolicy"],
                                                       "properties": {"restartPolicy": {"enum": ["OnFailure", "Never"]}}}]},
                    },
                },
            },
        },
    },
}

_service = {
    "type": "object",
    "required": ["apiVersion", "kind", "metadata", "spec"],
    "properties": {
        "apiVersion": {"const": "v1"},
        "metadata": _metadata,
        "spec": {
            "type": "object",
            "required": ["ports", "selector"],
            "properties": {
                "type": {"enum": ["ClusterIP", "NodePort", "LoadBalancer", "ExternalName"]},
                "externalTrafficPolicy": {"enum": ["Cluster", "Local"]},
                "sessionAffinity": {"enum": ["None", "ClientIP"]},
                "selector": {"type": "object", "additionalProperties": {"type": "string"}},
                "ports": {
                    "type": "array",
                    "minItems": 1,
                    "items": {
                        "type": "object",
                        "required": ["port"],
                        "properties": {"name": _port_name, "port": _port_number,
                                       "targetPort": _int_or_name, "protocol": _protocol,
                                       "nodePort": {"type": "integer", "minimum": 1, "maximum": 65535}},
                    },
                },
            },
        },
    },
}

_string_map = {"type": "object", "additionalProperties": {"type": "string"}}

_configmap = {
    "type": "object",
    "required": ["apiVersion", "kind", "metadata", "data"],
    "properties": {"apiVersion": {"const": "v1"}, "metadata": _metadata, "data": _string_map},
}

_secret = {
    "type": "object",
    "required": ["apiVersion", "kind", "metadata"],
    "properties": {"apiVersion": {"const": "v1"}, "metadata": _metadata, "type": {"type": "string"},
                   "data": _string_map, "stringData": _string_map},
}

_hpa = {
    "type": "object",
    "required": ["apiVersion", "kind", "metadata", "spec"],
    "properties": {
        "apiVersion": {"const": "autoscaling/v2"},
        "metadata": _metadata,
        "spec": {
            "type": "object",
            "required": ["scaleTargetRef", "maxReplicas"],
            "properties": {
                "scaleTargetRef": {"type": "object", "required": ["kind", "name"]},
                "minReplicas": {"type": "integer", "minimum": 1},
                "maxReplicas": {"type": "integer", "minimum": 1},
                "metrics": {
                    "type": "array",
                    "items": {"type": "object", "required": ["type"],
                              "properties": {"type": {"enum": ["Resource", "Pods", "Object", "External",
                                                               "ContainerResource"]}}},
                },
            },
        },
    },
}

_kustomization = {
    "type": "object",
    "required": ["resources"],
    "properties": {
        "apiVersion": {"const": "kustomize.config.k8s.io/v1beta1"},
        "kind": {"const": "Kustomization"},
        "namespace": {"type": "string"},
        "resources": {"type": "array", "items": {"type": "string"}},
        "images": {"type": "array", "items": {"type": "object", "required": ["name"]}},
    },
}

SCHEMAS = {
    "Deployment": _deployment,
    "StatefulSet": _statefulset,
    "Job": _job,
    "Service": _service,
    "ConfigMap": _configmap,
    "Secret": _secret,
    "HorizontalPodAutoscaler": _hpa,
    "Kustomization": _kustomization,
}
