"""Pages made at build time from the package and the repository, into docs/_generated/:

* ``api_*.md``: autosummary lists of every name in ``gecko.__all__``, grouped by module;
* ``cli.md``: the ``gecko`` command's help, as the installed command prints it;
* ``gallery.md``: every paper figure, rendered now by its scene (python/gecko/scene/figures),
  next to the scene that makes it;
* ``benchmarks.md``: the accuracy and performance tables, from bench/results/*.csv.

Nothing here is committed: a build always shows what the code and the results files say now.
"""
from __future__ import annotations

import contextlib
import csv
import io
import math
import shutil
import time
from pathlib import Path

MODULES = [
    ("gecko.elliptic", "Elliptic integrals",
     "Carlson's symmetric forms and Legendre's integrals; numpy ufuncs."),
    ("gecko.seta", "Two-level seta and peel lines",
     "The critical line of adhesion and its characteristics ({doc}`/theory/two_level_seta`)."),
    ("gecko.friction", "Frictional adhesion",
     "Curved-beam rigidity, force traces, detachment, steady sliding, fitting "
     "({doc}`/theory/frictional_adhesion`)."),
    ("gecko.design_sweep", "Design sweeps", "Many designs' characteristics as one table."),
    ("gecko.optimize", "Design optimisation", "Gradient-based seta design from exact sensitivities."),
]


def _api(out: Path) -> None:
    import importlib

    import gecko
    seen = set()
    lines = ["# API reference", "",
             "Every public name of the package, as `import gecko` exposes it (`gecko.__all__`), "
             "grouped by the module that defines it. Plotting is in {mod}`gecko.plot` (needs "
             "matplotlib) and the scene engine in {mod}`gecko.scene`.", ""]
    for modname, title, blurb in MODULES:
        mod = importlib.import_module(modname)
        names = [n for n in mod.__all__ if n in gecko.__all__]
        seen.update(names)
        lines += [f"## {title}", "", blurb, "", "```{eval-rst}", ".. autosummary::",
                  "   :toctree: api", ""]
        lines += [f"   gecko.{n}" for n in names]
        lines += ["```", ""]
    rest = [n for n in gecko.__all__ if n not in seen and n != "__version__"]
    lines += ["## Scenes", "", "Declarative studies; see {doc}`/_generated/gallery` for every paper figure as a scene.", "",
              "```{eval-rst}", ".. autosummary::", "   :toctree: api", ""]
    lines += [f"   gecko.{n}" for n in rest]
    lines += ["```", "", "## Plotting", "", "```{eval-rst}", ".. autosummary::", "   :toctree: api", ""]
    import gecko.plot as gp
    lines += [f"   gecko.plot.{n}" for n in gp.__all__ if callable(getattr(gp, n))]
    lines += ["```", "", "## Modules", "", "```{eval-rst}", ".. autosummary::", "   :toctree: api", "",
              "   gecko.plot", "   gecko.scene", "   gecko.friction_hierarchy", "   gecko.designs", "   gecko.cli",
              "```", ""]
    (out / "api.md").write_text("\n".join(lines))


def _cli(out: Path) -> None:
    from gecko import cli
    parts = ["# Command line", "",
             "The package installs one command, `gecko`. Its help, as this version prints it:", ""]
    for argv in ([], ["run"], ["figures"], ["plan"], ["validate"], ["models"]):
        buf = io.StringIO()
        with contextlib.redirect_stdout(buf), contextlib.redirect_stderr(buf):
            try:
                cli.main([*argv, "--help"])
            except SystemExit:
                pass
        parts += [f"## `gecko {' '.join(argv)} --help`".replace("  ", " "), "", "```text",
                  buf.getvalue().rstrip(), "```", ""]
    (out / "cli.md").write_text("\n".join(parts))


def _gallery(root: Path, out: Path) -> None:
    import gecko
    from gecko.scene import figure_scenes, load_scene
    from gecko.scene.runner import Cache
    gdir = out / "gallery"
    if gdir.exists():
        shutil.rmtree(gdir)
    gdir.mkdir(parents=True)
    cache = Cache()
    t0 = time.perf_counter()
    lines = ["# Gallery of the paper figures", "",
             "Every figure of the two papers, and a few studies beyond them, is a *scene*: a TOML "
             "file that names the model, the parameters and the outputs. The images below were "
             "rendered when this page was built, each by the scene printed under it. Run one "
             "yourself with `gecko run SCENE.toml --out DIR`, or all of them with "
             "`gecko figures --out DIR`; the scenes are installed with the package "
             "(`gecko.scene.figure_scenes()`) and are also in `examples/`.", ""]
    for path in figure_scenes():
        sc = load_scene(path)
        res = gecko.run_scene(path, gdir / path.stem, progress=False, cache=cache)
        title = sc.title or path.stem
        lines += [f"## {title}", "", f"Scene `{path.name}`, computed in {res.seconds:.2f} s.", ""]
        if sc.description.strip():
            lines += [" ".join(sc.description.split()), ""]
        for f in sorted(res.files):
            if Path(f).suffix == ".png":
                rel = Path(f).relative_to(out).as_posix()
                lines += [f"```{{image}} {rel}", f":alt: {title}", ":width: 600px", "```", ""]
        lines += [f"**`{path.name}`**", "", "```toml", path.read_text().rstrip(), "```", ""]
    lines += [f"*All {len(figure_scenes())} scenes rendered in {time.perf_counter() - t0:.1f} s "
              "(one shared cache).*", ""]
    (out / "gallery.md").write_text("\n".join(lines))


def _fmt(x: str, digits: int = 3) -> str:
    try:
        v = float(x)
    except ValueError:
        return x
    if math.isnan(v):
        return "—"
    if v == 0:
        return "0"
    if abs(v) >= 1e4 or abs(v) < 1e-2:
        return f"{v:.{digits - 1}e}"
    return f"{v:.{digits}g}"


def _table(header, rows):
    out = ["| " + " | ".join(header) + " |", "|" + "|".join("---" for _ in header) + "|"]
    out += ["| " + " | ".join(str(c).replace("|", "\\|") for c in r) + " |" for r in rows]
    return out


def _benchmarks(root: Path, out: Path) -> None:
    res = root / "bench" / "results"
    lines = ["# Accuracy and performance", "",
             "Generated at build time from the committed results files in `bench/results/` "
             "(the numbers are those of the last benchmark run, not of this build's machine). "
             "Every row gives run time *and* error, with the peers measured in the same run. "
             "Re-run them with the commands in the contributing guide; compare ratios within one "
             "run, as the machines are shared.", ""]
    trade = res / "tradeoff.csv"
    if trade.exists():
        rows = list(csv.DictReader(trade.open()))
        lines += ["## Run time against error, every kernel family", "",
                  "From `bench/results/tradeoff.csv` (`python3 bench/tradeoff/run.py`). Time per call; "
                  "error as the maximum over the input set, in the unit given (eps: multiples of "
                  "double-precision machine epsilon; rel: relative).", ""]
        families = []
        for r in rows:
            if r["family"] not in families:
                families.append(r["family"])
        for fam in families:
            sub = [r for r in rows if r["family"] == fam]
            lines += [f"### {fam}", "", f"Inputs: {sub[0]['input_set']} ({sub[0]['n']} per set).", ""]
            lines += _table(["method", "setting", "time per call (ns)", "max error", "unit", "failed"],
                            [[r["method"], r["setting"], _fmt(r["time_per_call_ns"]), _fmt(r["max_err"]),
                              r["unit"], r["failed"]] for r in sub])
            lines += [""]
    ell = res / "elliptic.csv"
    if ell.exists():
        rows = list(csv.DictReader(ell.open()))
        lines += ["## Elliptic integrals in detail", "",
                  "From `bench/results/elliptic.csv` (`bench/run_elliptic.sh`): median time per "
                  "evaluation, maximum and RMS error in units of machine epsilon against 40-digit "
                  "references, speed-up against Boost.Math.", ""]
        lines += _table(["function", "method", "setting", "inputs", "ns/eval", "max err (eps)",
                         "rms err (eps)", "non-finite", "vs Boost"],
                        [[r["function"], r["method"], r["setting"], r["input_set"],
                          _fmt(r["ns_per_eval_median"]), _fmt(r["max_err_eps"]), _fmt(r["rms_err_eps"]),
                          r["nonfinite"], _fmt(r["speedup_vs_boost"])] for r in rows])
        lines += [""]
    seta = res / "seta.csv"
    if seta.exists():
        rows = [r for r in csv.reader(seta.open()) if r]
        head, body = rows[0], [r for r in rows[1:] if r != rows[0]]
        lines += ["## The critical line", "",
                  "From `bench/results/seta.csv` (`bench/seta/run.sh`): the reference scene's "
                  "1000-point line, time per point and maximum relative error of Fn.", ""]
        lines += _table(["method", "setting", "µs per point", "max rel. error of Fn", "failed points"],
                        [[r[0], r[1], _fmt(r[2]), _fmt(r[3]), r[4]] for r in body if len(r) >= 5])
        lines += [""]
    others = sorted(p.name for p in res.glob("*.md"))
    lines += ["## Further results", "",
              "The full reports, with the machine, the commands and the discussion, are the "
              "Markdown files of `bench/results/` in the repository: " + ", ".join(f"`{o}`" for o in others) + ". "
              "The solver's validation campaign (10,000 random designs checked by independent ODE "
              "shooting and 60-digit arithmetic) is reported in `validation/results/stress.md`.", ""]
    (out / "benchmarks.md").write_text("\n".join(lines))


def all_pages(root: Path, out: Path) -> None:
    out.mkdir(parents=True, exist_ok=True)
    t0 = time.perf_counter()
    _api(out)
    _cli(out)
    _benchmarks(root, out)
    _gallery(root, out)
    print(f"docs: generated pages in {time.perf_counter() - t0:.1f} s")
