"""Sphinx configuration of gecko's documentation (built by tools/docs.sh, warnings are errors)."""
import os
import sys
from pathlib import Path

DOCS = Path(__file__).resolve().parent
ROOT = DOCS.parent
sys.path.insert(0, str(DOCS / "_ext"))

import gecko  # noqa: E402  (the installed package, or python/ on PYTHONPATH)

# Pages generated from the package and the repository at build time (docs/_generated, ignored by git):
# the API list from gecko.__all__, the figure gallery from the figure scenes, the benchmark tables
# from bench/results.
import generate  # noqa: E402

generate.all_pages(ROOT, DOCS / "_generated")

project = "gecko"
author = "The gecko developers"
copyright = "2026, The gecko developers"
release = gecko.__version__
version = ".".join(release.split(".")[:2])

extensions = [
    "myst_nb",
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.mathjax",
    "sphinx.ext.viewcode",
    "numpydoc",
]

myst_enable_extensions = ["dollarmath", "amsmath", "colon_fence", "deflist"]
myst_heading_anchors = 3
myst_dmath_double_inline = True

# Tutorials are executed at every build; a failing cell fails the build.
nb_execution_mode = "force"
nb_execution_timeout = 300
nb_execution_raise_on_error = True
nb_execution_show_tb = True
nb_merge_streams = True

autosummary_generate = True
autosummary_imported_members = True
autodoc_default_options = {"members": False}
autodoc_typehints = "none"
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False
numpydoc_attributes_as_param_list = True

exclude_patterns = ["_build", "jupyter_execute", "Thumbs.db", ".DS_Store", "**.ipynb_checkpoints",
                    "_ext"]
source_suffix = {".rst": "restructuredtext", ".md": "myst-nb"}
templates_path = ["_templates"]

html_theme = "alabaster"
html_title = f"gecko {release}"
html_static_path = []
html_theme_options = {
    "description": "Mechanics of gecko-like adhesion",
    "fixed_sidebar": True,
    "page_width": "1100px",
}
suppress_warnings = []


# Prose docstrings write absolute values and norms as |x|, which reStructuredText would read as a
# substitution reference; escape them (gecko's docstrings use no substitutions).
import re  # noqa: E402

_BARS = re.compile(r"(?<![\\|\w])\|(?=[^\s|])([^|\n]*?[^\s|\\])\|(?![|\w])")


def _escape_bars(app, what, name, obj, options, lines):
    for i, line in enumerate(lines):
        if line.lstrip().startswith(("|", "+-", ">>>", "...")):
            continue  # tables and doctest lines stay as they are
        lines[i] = _BARS.sub(r"\\|\1\\|", line)


def setup(app):
    app.connect("autodoc-process-docstring", _escape_bars)
