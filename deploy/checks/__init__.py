"""The checks behind deploy/check-manifests.py, one file per thing checked."""
