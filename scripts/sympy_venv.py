"""The Python with sympy that scripts/bench_symbolic.py and scripts/check_formulas.py run:
the notebooks' virtual environment ($SPLINELAB_STATE/venv, default ~/.cache/splinelab/venv),
created and given sympy if it has none."""
import os
import pathlib
import subprocess
import sys

SYMPY_VERSION = "1.14.0"


def venv_python():
    state = pathlib.Path(os.environ.get("SPLINELAB_STATE", pathlib.Path.home() / ".cache/splinelab"))
    venv = state / "venv"
    python = venv / "bin" / "python"
    if not python.exists():
        subprocess.run([sys.executable, "-m", "venv", str(venv)], check=True)
    probe = subprocess.run([str(python), "-c", "import sympy"], capture_output=True)
    if probe.returncode != 0:
        subprocess.run(
            [str(python), "-m", "pip", "install", "--quiet", "--disable-pip-version-check",
             f"sympy=={SYMPY_VERSION}"],
            check=True,
        )
    return python
