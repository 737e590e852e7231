"""The admin tests' check of one ocean-admin run: its exit status and, optionally, words its
stderr must hold; a miss is appended to `failures`, and the run's stdout returned."""


def expect(failures, name, got, code, stderr_has=None):
    rc, out, err = got
    if rc != code or (stderr_has and stderr_has not in err):
        failures.append(f"{name}: exit {rc} (want {code}), stderr {err.strip()!r}"
                        + (f" (want it to contain {stderr_has!r})" if stderr_has else ""))
    return out
