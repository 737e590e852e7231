"""Loading deploy/k8s: every YAML document, its apiVersion/kind/metadata.name, and the subset
schemas (schemas.py) when python3-jsonschema is installed.
"""
import yaml  # python3-yaml

try:
    import jsonschema  # python3-jsonschema (optional)
except ImportError:
    jsonschema = None

from . import schemas

def load_documents(report, k8s_dir):
    documents = []
    files = sorted(p for p in k8s_dir.rglob("*") if p.suffix in (".yaml", ".yml"))
    if not files:
        report.problem(str(k8s_dir), "no YAML files")
    for path in files:
        try:
            loaded = list(yaml.safe_load_all(path.read_text()))
        except yaml.YAMLError as error:
            report.problem(path.name, f"not valid YAML: {error}")
            continue
        for index, document in enumerate(d for d in loaded if d is not None):
            where = f"{path.name}[{index}]"
            if not isinstance(document, dict):
                report.problem(where, "a document must be a mapping")
                continue
            for key in ("apiVersion", "kind"):
                if not isinstance(document.get(key), str):
                    report.problem(where, f"missing {key}")
            name = (document.get("metadata") or {}).get("name")
            if document.get("kind") != "Kustomization" and not isinstance(name, str):
                report.problem(where, "missing metadata.name")
            documents.append((where, path, document))
    return documents


def check_schemas(report, documents):
    if jsonschema is None:
        report.notes.append("schema: skipped (python3-jsonschema not installed)")
        return
    for where, _, document in documents:
        schema = schemas.SCHEMAS.get(document.get("kind"))
        if schema is None:
            report.problem(where, f"no schema for kind {document.get('kind')!r}; add one to schemas.py")
            continue
        validator = jsonschema.Draft7Validator(schema)
        for error in sorted(validator.iter_errors(document), key=lambda e: list(e.absolute_path)):
            path = ".".join(str(p) for p in error.absolute_path) or "(document)"
            report.problem(where, f"schema: {path}: {error.message}")
    report.notes.append(f"schema: {len(schemas.SCHEMAS)} subset schemas checked with python3-jsonschema")


def by_kind(documents, kind):
    return [(where, d) for where, _, d in documents if d.get("kind") == kind]
