"""insmc from Python: run the command line and get its JSON as Python data.

A thin, dependency-free wrapper for notebooks and scripts. Every function
runs the `insmc` program with `--format json` and returns the parsed JSON,
so the results are exactly the command line's (the files and keys are
documented in the repository's README and docs/outputs.md). `rows()` turns
a result into flat records with SI keys (`rms_m`, `cep50_m`, ...);
`dataframe()` gives them as a pandas DataFrame when pandas is installed.

    import sys; sys.path.insert(0, "apps/python")   # from the clone's root
    import insmc
    study = insmc.run(samples=20000, scheme="none,5.4", test_duration="10min,20min")
    table = insmc.dataframe(study)          # one row per point, scheme, system, axis, time

Options are the command line's with underscores for dashes
(`test_duration="15min"` is `--test-duration=15min`); a list is joined
with commas (a sweep); `True` is a switch. `bound` and `dist` take a list
of NAME=VALUE strings. The program is $INSMC, else `insmc` on the PATH, else
the README's build (build/release/apps/insmc) or the test build.
"""

import json
import os
import shutil
import subprocess

__all__ = ["InsmcError", "run", "covariance", "gap", "rows", "dataframe", "program"]

_HERE = os.path.dirname(os.path.abspath(__file__))
_ROOT = os.path.dirname(os.path.dirname(_HERE))


class InsmcError(RuntimeError):
    """insmc refused the input (exit 2) or failed; the message is its own line."""

    def __init__(self, message, exit_code):
        super().__init__(message)
        self.exit_code = exit_code


def program():
    """The insmc executable this module runs."""
    if os.environ.get("INSMC"):
        return os.environ["INSMC"]
    on_path = shutil.which("insmc")
    if on_path:
        return on_path
    for build in ("release", "test"):
        candidate = os.path.join(_ROOT, "build", build, "apps", "insmc")
        if os.access(candidate, os.X_OK):
            return candidate
    raise InsmcError("insmc not found: set INSMC, put insmc on the PATH, or run the README's first command", 127)


def _arguments(options):
    args = []
    for name, value in options.items():
        flag = "--" + name.replace("_", "-")
        if value is None or value is False:
            continue
        if value is True:
            args.append(flag)
        elif name in ("bound", "dist", "input", "records", "effect"):
            values = [value] if isinstance(value, str) else list(value)
            args.extend(f"{flag}={v}" for v in values)
        elif isinstance(value, (list, tuple)):
            args.append(f"{flag}={','.join(str(v) for v in value)}")
        else:
            args.append(f"{flag}={value}")
    return args


def _json_of(subcommand, options):
    command = [program(), subcommand, *_arguments(options), "--format", "json"]
    done = subprocess.run(command, capture_output=True, text=True, check=False)
    if done.returncode != 0:
        raise InsmcError(done.stderr.strip() or f"insmc {subcommand} exited {done.returncode}", done.returncode)
    return json.loads(done.stdout)


def run(**options):
    """`insmc run` (a study, or a sweep when an option is a list): run.json or sweep.json."""
    return _json_of("run", options)


def covariance(**options):
    """`insmc covariance`: the exact linear-covariance RMS (its JSON)."""
    return _json_of("covariance", options)


def gap(records, **options):
    """`insmc gap --records FILE...`: gap.json of the diagnosis."""
    return _json_of("gap", {"records": records, **options})


def rows(result):
    """Flat records of a run.json (its envelope rows), a sweep.json (every
    point's rows with the swept values as columns) or a covariance JSON."""
    if "points" in result:
        out = []
        for point in result["points"]:
            for row in point["rows"]:
                out.append({**point["values_si"], **row})
        return out
    if "envelope" in result:
        return [dict(r) for r in result["envelope"]]
    if "covariance" in result:
        return [dict(r) for r in result["covariance"]]
    raise ValueError("not a run, sweep or covariance result of insmc")


def dataframe(result):
    """rows(result) as a pandas DataFrame (needs pandas)."""
    try:
        import pandas
    except ImportError as e:
        raise ImportError("insmc.dataframe needs pandas (Debian: python3-pandas); insmc.rows gives the same "
                          "records without it") from e
    return pandas.DataFrame(rows(result))
