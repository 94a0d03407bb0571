#!/usr/bin/env bash
# Builds the documentation site into docs/_build/html, with warnings as errors: theory pages, API
# reference (numpydoc docstrings), tutorials executed now, the gallery of paper figures rendered
# now by their scenes, and the benchmark tables generated from bench/results.
#   bash tools/docs.sh            # needs network access the first time (pip)
# Uses ./.venv (made by tools/setup.sh, or here if missing). gecko itself: the package installed in
# .venv (tools/setup.sh does `pip install .`); if it is missing there it is installed now. A
# development tree can set PYTHONPATH=python instead (with the _core module linked in).
set -euo pipefail
cd "$(dirname "$0")/.."
t0=$(date +%s)

if [ ! -x .venv/bin/python ]; then
  "${PYTHON:-python3}" -m venv .venv
fi
py=.venv/bin/python
# The documentation's own needs (the [docs] extra of pyproject.toml), installed only when missing.
if ! $py -c "import sphinx, myst_nb, numpydoc, ipykernel, matplotlib, pandas, pyarrow, scipy, distributed" 2>/dev/null; then
  echo "docs: installing the documentation requirements into .venv"
  $py -m pip install -q "sphinx>=7" "myst-nb>=1.0" "numpydoc>=1.6" ipykernel "matplotlib>=3.5" \
      "pandas>=1.5" "pyarrow>=10" "scipy>=1.9" "dask[distributed]>=2023.1"
fi
if ! $py -c "import gecko" 2>/dev/null; then
  echo "docs: installing gecko into .venv (pip install .)"
  $py -m pip install -q .
fi
$py -c "import gecko; print('docs: gecko', gecko.__version__, 'from', gecko.__file__)"

# The tutorials run in a Jupyter kernel of this interpreter; plots never open a window.
export MPLBACKEND=Agg
export PATH="$PWD/.venv/bin:$PATH"
rm -rf docs/_build docs/_generated docs/jupyter_execute
# -W: warnings are errors; --keep-going: report all of them; -j: the tutorials run in parallel.
$py -m sphinx -W --keep-going -j "${DOCS_JOBS:-2}" -b html docs docs/_build/html
echo "docs: built docs/_build/html/index.html in $(( $(date +%s) - t0 )) s"
